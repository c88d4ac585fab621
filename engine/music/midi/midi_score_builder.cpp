// SPDX-License-Identifier: MIT
#include <tutti/music/midi/midi_score_builder.hpp>
#include <tutti/music/general_midi.hpp>

#include <algorithm>
#include <limits>
#include <tuple>
#include <utility>

#include <tutti/music/midi/midi_text.hpp>
#include <tutti/music/midi/pedal_span_merge.hpp>

namespace tutti::music::midi_detail {
namespace {

constexpr int kSustainController = 64;
constexpr int kMaxDenominatorPower = 10;     // 1/1024 notes; anything beyond is corrupt data
constexpr int kDefaultReleaseVelocity = 64;  // what a note-on with velocity 0 implies

TempoMap tempo_map_for(const SmfDivision& division) {
  return division.smpte ? TempoMap::with_smpte(division.frames_per_second, division.ticks_per_frame)
                        : TempoMap::with_ticks_per_quarter(division.ticks_per_quarter);
}

std::string too_short(const char* what, std::size_t needed, std::size_t has) {
  return std::string{what} + " meta event needs " + std::to_string(needed) + " data bytes, has " +
         std::to_string(has);
}

TextKind text_kind(std::uint8_t meta_type) {
  switch (meta_type) {
    case 0x01:
      return TextKind::text;
    case 0x02:
      return TextKind::copyright;
    case 0x03:
      return TextKind::track_name;
    case 0x04:
      return TextKind::instrument_name;
    case 0x05:
      return TextKind::lyric;
    case 0x06:
      return TextKind::marker;
    case 0x07:
      return TextKind::cue_point;
    default:
      return TextKind::other;  // 0x08 program name, 0x09 device name, 0x0A-0x0F unnamed
  }
}

}  // namespace

MidiScoreBuilder::MidiScoreBuilder(const SmfHeader& header, const std::string& source) {
  score_.source = source;
  score_.tempo_map = tempo_map_for(header.division);
}

void MidiScoreBuilder::begin_track(int track_index, std::int64_t start_tick) {
  track_ = track_index;
  start_tick_ = start_tick;
  sounding_.clear();
  std::fill(std::begin(pedal_down_), std::end(pedal_down_), false);
  const auto size = static_cast<std::size_t>(track_index) + 1;
  if (track_names_.size() < size) track_names_.resize(size);
  if (instrument_names_.size() < size) instrument_names_.resize(size);
}

std::string MidiScoreBuilder::on_event(const SmfEvent& event) {
  const std::int64_t tick = start_tick_ + event.tick;
  switch (event.kind) {
    case SmfEventKind::channel:
      on_channel_event(event, tick);
      return {};
    case SmfEventKind::meta:
      return on_meta_event(event, tick);
    case SmfEventKind::sysex:
      return {};  // device-specific; nothing in the score model depends on it
  }
  return {};
}

void MidiScoreBuilder::on_channel_event(const SmfEvent& event, std::int64_t tick) {
  const int channel = event.channel();
  switch (event.message()) {
    case 0x90:
      if (event.data2 > 0) {
        start_note(channel, event.data1, event.data2, tick);
      } else {
        end_note(channel, event.data1, kDefaultReleaseVelocity, tick);
      }
      break;
    case 0x80:
      end_note(channel, event.data1, event.data2, tick);
      break;
    case 0xB0:
      if (event.data1 == kSustainController) set_pedal(channel, event.data2 >= 64, tick);
      break;
    case 0xC0:
      program_changes_.push_back(
          ProgramChange{channel, tick, track_, program_changes_.size(), event.data1});
      break;
    default:
      break;  // pressure, pitch bend and other controllers do not enter the score model
  }
}

std::string MidiScoreBuilder::on_meta_event(const SmfEvent& event, std::int64_t tick) {
  const auto data = event.payload;
  switch (event.meta_type) {
    case 0x51: {
      if (data.size() < 3) return too_short("tempo", 3, data.size());
      const int microseconds = (data[0] << 16) | (data[1] << 8) | data[2];
      if (microseconds == 0) return "tempo meta event of 0 microseconds per quarter note";
      score_.tempo_map.set_tempo(tick, microseconds);
      return {};
    }
    case 0x58: {
      if (data.size() < 4) return too_short("time signature", 4, data.size());
      if (data[0] == 0) return "time signature meta event with numerator 0";
      if (data[1] > kMaxDenominatorPower) {
        return "time signature meta event with denominator 2^" + std::to_string(data[1]);
      }
      TimeSignature signature;
      signature.tick = tick;
      signature.numerator = data[0];
      signature.denominator = 1 << data[1];
      score_.time_signatures.push_back(signature);
      return {};
    }
    case 0x59: {
      if (data.size() < 2) return too_short("key signature", 2, data.size());
      const int fifths = static_cast<std::int8_t>(data[0]);
      if (fifths < -7 || fifths > 7) {
        return "key signature meta event with " + std::to_string(fifths) + " fifths (-7..7 exist)";
      }
      score_.key_signatures.push_back(KeySignature{tick, 0.0, fifths, data[1] != 0});
      return {};
    }
    case 0x54:
      // SMPTE offset: where the track starts on an external time code. Players ignore it and so
      // does the score (it would only shift everything); it is still checked for its size.
      if (data.size() < 5) return too_short("SMPTE offset", 5, data.size());
      return {};
    default:
      break;
  }
  if (event.meta_type >= 0x01 && event.meta_type <= 0x0F) {
    TextEvent text;
    text.tick = tick;
    text.kind = text_kind(event.meta_type);
    text.track = track_;
    text.text = text_from_midi_bytes(data);
    const auto index = static_cast<std::size_t>(track_);
    if (text.kind == TextKind::track_name && track_names_[index].empty()) {
      track_names_[index] = text.text;
    }
    if (text.kind == TextKind::instrument_name && instrument_names_[index].empty()) {
      instrument_names_[index] = text.text;
    }
    score_.texts.push_back(std::move(text));
  }
  // Sequence number, channel prefix, port, end of track, sequencer-specific and unknown meta
  // events carry nothing the score model holds.
  return {};
}

void MidiScoreBuilder::start_note(int channel, int key, int velocity, std::int64_t tick) {
  Note note;
  note.pitch = key;
  note.onset_ticks = tick;
  note.offset_ticks = tick;  // until its note-off, or the end of the track
  note.velocity = velocity;
  note.channel = channel;
  note.source_index = note_ons_++;
  sounding_[channel * 128 + key].push_back(score_.notes.size());
  score_.notes.push_back(note);
  note_tracks_.push_back(track_);
}

void MidiScoreBuilder::end_note(int channel, int key, int release_velocity, std::int64_t tick) {
  auto found = sounding_.find(channel * 128 + key);
  if (found == sounding_.end() || found->second.empty()) return;  // stray note-off: harmless
  Note& note = score_.notes[found->second.front()];
  found->second.pop_front();
  note.offset_ticks = tick;
  note.release_velocity = release_velocity;
}

void MidiScoreBuilder::set_pedal(int channel, bool down, std::int64_t tick) {
  const auto c = static_cast<std::size_t>(channel);
  if (down && !pedal_down_[c]) {
    pedal_down_[c] = true;
    pedal_down_since_[c] = tick;
  } else if (!down && pedal_down_[c]) {
    pedal_down_[c] = false;
    pedals_.push_back(HeldPedal{track_, channel, pedal_down_since_[c], tick});
  }
}

void MidiScoreBuilder::end_track(std::int64_t end_tick) {
  for (auto& [key, queue] : sounding_) {
    for (std::size_t index : queue) score_.notes[index].offset_ticks = end_tick;
  }
  sounding_.clear();
  for (int channel = 0; channel < 16; ++channel) set_pedal(channel, false, end_tick);
}

int MidiScoreBuilder::program_at(int track, int channel, std::int64_t tick) const {
  // program_changes_ is sorted by (channel, tick, track, order) here. The last change at or
  // before `tick` decides, but among changes at that same tick the part's own track wins.
  auto key = [](const ProgramChange& p) { return std::tie(p.channel, p.tick, p.track, p.order); };
  auto last_not_after = [&](std::int64_t t, int tr) -> const ProgramChange* {
    const ProgramChange probe{channel, t, tr, std::numeric_limits<std::size_t>::max(), 0};
    auto after = std::upper_bound(
        program_changes_.begin(), program_changes_.end(), probe,
        [&](const ProgramChange& a, const ProgramChange& b) { return key(a) < key(b); });
    if (after == program_changes_.begin()) return nullptr;
    const ProgramChange* found = &*std::prev(after);
    return found->channel == channel ? found : nullptr;
  };
  const ProgramChange* latest = last_not_after(tick, std::numeric_limits<int>::max());
  if (latest == nullptr) return 0;  // General MIDI: program 0 until a program change
  const ProgramChange* own = last_not_after(latest->tick, track);
  if (own != nullptr && own->tick == latest->tick && own->track == track) return own->program;
  return latest->program;
}

Score MidiScoreBuilder::finish(std::int64_t end_ticks) && {
  std::sort(program_changes_.begin(), program_changes_.end(),
            [](const ProgramChange& a, const ProgramChange& b) {
              return std::tie(a.channel, a.tick, a.track, a.order) <
                     std::tie(b.channel, b.tick, b.track, b.order);
            });

  // One part per (track, channel) with notes, in track then channel order.
  std::map<std::pair<int, int>, int> part_of;
  for (std::size_t i = 0; i < score_.notes.size(); ++i) {
    part_of.emplace(std::pair{note_tracks_[i], score_.notes[i].channel}, 0);
  }
  std::map<int, int> channels_in_track;
  for (auto& [track_channel, index] : part_of) {
    index = static_cast<int>(score_.parts.size());
    ++channels_in_track[track_channel.first];
    Part part;
    part.track = track_channel.first;
    part.channel = track_channel.second;
    part.id = "track" + std::to_string(part.track) + "-ch" + std::to_string(part.channel);
    part.percussion = part.channel == kPercussionChannel;
    score_.parts.push_back(part);
  }

  std::vector<std::int64_t> first_onset(score_.parts.size(),
                                        std::numeric_limits<std::int64_t>::max());
  for (std::size_t i = 0; i < score_.notes.size(); ++i) {
    Note& note = score_.notes[i];
    note.part = part_of.at({note_tracks_[i], note.channel});
    auto& first = first_onset[static_cast<std::size_t>(note.part)];
    first = std::min(first, note.onset_ticks);
  }

  for (std::size_t p = 0; p < score_.parts.size(); ++p) {
    Part& part = score_.parts[p];
    const auto t = static_cast<std::size_t>(part.track);
    std::string name = track_names_[t].empty() ? instrument_names_[t] : track_names_[t];
    if (channels_in_track[part.track] > 1) {
      const std::string channel = "ch " + std::to_string(part.channel + 1);
      name = name.empty() ? channel : name + " (" + channel + ")";
    }
    part.name = std::move(name);
    part.program = program_at(part.track, part.channel, first_onset[p]);
  }

  int first_part_on_channel[16];
  std::fill(std::begin(first_part_on_channel), std::end(first_part_on_channel), -1);
  for (const auto& [track_channel, index] : part_of) {
    int& first = first_part_on_channel[track_channel.second];
    if (first < 0) first = index;  // part_of is ordered by track: the lowest track comes first
  }
  std::vector<PedalSpan> spans;
  for (const HeldPedal& pedal : pedals_) {
    const auto same = part_of.find({pedal.track, pedal.channel});
    const int part = same != part_of.end() ? same->second : first_part_on_channel[pedal.channel];
    if (part < 0) continue;  // a pedal on a channel that plays no notes
    PedalSpan span;
    span.part = part;
    span.onset_ticks = pedal.onset;
    span.offset_ticks = pedal.offset;
    spans.push_back(span);
  }
  score_.pedal_spans = merge_overlapping_pedal_spans(std::move(spans));

  score_.end_ticks = end_ticks;
  finalize_score(score_);
  return std::move(score_);
}

}  // namespace tutti::music::midi_detail
