// SPDX-License-Identifier: MIT
#include <tutti/music/midi/midi_writer.hpp>
#include <tutti/music/general_midi.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>

#include <tutti/core/file_io.hpp>
#include <tutti/music/midi/pedal_span_merge.hpp>
#include <tutti/music/midi/smf_track_encoder.hpp>

namespace tutti::music {
namespace {

using midi_detail::SmfTrackEncoder;

constexpr int kFallbackTicksPerQuarter = 480;
constexpr int kMaxTicksPerQuarter = 0x7FFF;  // the division field has 15 bits
constexpr std::size_t kMaxTracks = 0xFFFF;

// The rank orders events at one tick. Lifts before presses and note-offs before note-ons, so a
// note or pedal that ends where the next one starts is read back as two, and zero-length notes
// end only after they start.
namespace rank {
enum : int {
  track_name,
  program,
  pedal_up,
  note_off,
  pedal_down,
  note_on,
  zero_length_note_off,
};
}  // namespace rank
namespace conductor_rank {
enum : int { track_name, tempo, time_signature, key_signature, text };
}  // namespace conductor_rank

// Score ticks -> file ticks. PPQ scores keep their ticks; SMPTE scores (and PPQ beyond 15 bits)
// are written at 480 PPQ through beats, which with the same tempo values keeps every time in
// seconds.
class TickConverter {
 public:
  explicit TickConverter(const TempoMap& map) : map_(map) {
    const int ppq = map.ticks_per_quarter();
    keep_ticks_ = !map.is_smpte() && ppq >= 1 && ppq <= kMaxTicksPerQuarter;
    ticks_per_quarter_ = keep_ticks_ ? ppq : kFallbackTicksPerQuarter;
  }
  int ticks_per_quarter() const { return ticks_per_quarter_; }
  std::int64_t operator()(std::int64_t tick) const {
    if (keep_ticks_) return tick;
    return std::llround(map_.beats_at(static_cast<double>(tick)) * ticks_per_quarter_);
  }

 private:
  const TempoMap& map_;
  bool keep_ticks_ = true;
  int ticks_per_quarter_ = kFallbackTicksPerQuarter;
};

std::string be_bytes(std::uint32_t value, int count) {
  std::string bytes;
  for (int shift = 8 * (count - 1); shift >= 0; shift -= 8) {
    bytes += static_cast<char>((value >> shift) & 0xFF);
  }
  return bytes;
}

int log2_floor(int value) {
  int power = 0;
  while (value > 1) value >>= 1, ++power;
  return power;
}

std::uint8_t text_meta_type(TextKind kind) {
  switch (kind) {
    case TextKind::copyright:
      return 0x02;
    case TextKind::track_name:
      return 0x03;
    case TextKind::instrument_name:
      return 0x04;
    case TextKind::lyric:
      return 0x05;
    case TextKind::marker:
      return 0x06;
    case TextKind::cue_point:
      return 0x07;
    default:
      return 0x01;  // text, and "other" whose original meta type the model did not keep
  }
}

std::vector<std::uint8_t> conductor_track(const Score& score, const TickConverter& to_file) {
  SmfTrackEncoder track;
  for (const TextEvent& text : score.texts) {
    if (text.kind == TextKind::track_name && text.track == 0) {
      track.add_meta(0, conductor_rank::track_name, 0x03,
                     text.text);  // the song title, by convention
      break;
    }
  }
  for (const TempoChange& change : score.tempo_map.changes()) {
    const auto microseconds = static_cast<std::uint32_t>(
        std::clamp(std::llround(change.microseconds_per_quarter), 1LL, 0xFFFFFFLL));
    track.add_meta(to_file(change.tick), conductor_rank::tempo, 0x51, be_bytes(microseconds, 3));
  }
  for (const TimeSignature& ts : score.time_signatures) {
    // MIDI stores the denominator as a power of two; other denominators cannot be written and
    // are rounded down to one. 24 MIDI clocks per metronome click, 8 32nds per quarter.
    std::string data;
    data += static_cast<char>(std::clamp(ts.numerator, 1, 255));
    data += static_cast<char>(log2_floor(std::max(ts.denominator, 1)));
    data += static_cast<char>(24);
    data += static_cast<char>(8);
    track.add_meta(to_file(ts.tick), conductor_rank::time_signature, 0x58, std::move(data));
  }
  for (const KeySignature& ks : score.key_signatures) {
    std::string data;
    data += static_cast<char>(static_cast<std::int8_t>(std::clamp(ks.fifths, -7, 7)));
    data += static_cast<char>(ks.minor ? 1 : 0);
    track.add_meta(to_file(ks.tick), conductor_rank::key_signature, 0x59, std::move(data));
  }
  for (const TextEvent& text : score.texts) {
    // Track and instrument names travel with the parts' own tracks.
    if (text.kind == TextKind::track_name || text.kind == TextKind::instrument_name) continue;
    track.add_meta(to_file(text.tick), conductor_rank::text, text_meta_type(text.kind), text.text);
  }
  return track.encode(to_file(score.end_ticks));
}

// MIDI channel per part: the part's own when it has one; otherwise 9 for percussion and the
// other fifteen in turn for the rest (several parts may then share a channel).
std::vector<int> part_channels(const std::vector<Part>& parts) {
  std::vector<int> channels;
  int next = 0;
  for (const Part& part : parts) {
    if (part.channel >= 0 && part.channel <= 15) {
      channels.push_back(part.channel);
    } else if (part.percussion) {
      channels.push_back(kPercussionChannel);
    } else {
      if (next == kPercussionChannel) ++next;
      channels.push_back(next);
      next = (next + 1) % 16;
    }
  }
  return channels;
}

// What goes into one part's track.
struct PartContent {
  std::vector<const Note*> notes;
  std::vector<const PedalSpan*> pedals;
};

std::vector<std::uint8_t> part_track(const Part& part, int channel, PartContent content,
                                     const TickConverter& to_file) {
  const auto ch = static_cast<std::uint8_t>(channel);
  const auto control = static_cast<std::uint8_t>(0xB0 | ch);
  SmfTrackEncoder track;
  if (!part.name.empty()) track.add_meta(0, rank::track_name, 0x03, part.name);
  track.add_channel(0, rank::program, static_cast<std::uint8_t>(0xC0 | ch), part.program);

  for (const PedalSpan* pedal : content.pedals) {
    track.add_channel(to_file(pedal->onset_ticks), rank::pedal_down, control, 64, 127);
    track.add_channel(to_file(pedal->offset_ticks), rank::pedal_up, control, 64, 0);
  }

  // Readers pair repeated keys first in, first out, so among notes of one key starting together
  // the one that ends first must be switched on first.
  auto& notes = content.notes;
  std::stable_sort(notes.begin(), notes.end(), [](const Note* a, const Note* b) {
    return std::tie(a->onset_ticks, a->pitch, a->offset_ticks) <
           std::tie(b->onset_ticks, b->pitch, b->offset_ticks);
  });
  for (const Note* note : notes) {
    const std::int64_t on = to_file(note->onset_ticks);
    const std::int64_t off = std::max(on, to_file(note->offset_ticks));
    const int key = std::clamp(note->pitch, 0, 127);
    track.add_channel(on, rank::note_on, static_cast<std::uint8_t>(0x90 | ch), key,
                      std::clamp(note->velocity, 1, 127));  // velocity 0 would mean note-off
    track.add_channel(off, off == on ? rank::zero_length_note_off : rank::note_off,
                      static_cast<std::uint8_t>(0x80 | ch), key, note->release_velocity);
  }
  return track.encode(0);
}

}  // namespace

std::vector<std::uint8_t> write_midi(const Score& score) {
  const TickConverter to_file(score.tempo_map);
  // A file holds at most 65535 tracks: the conductor and 65534 parts. Further parts are left
  // out; no score the project handles comes near that.
  const std::size_t part_count = std::min(score.parts.size(), kMaxTracks - 1);
  const std::vector<int> channels = part_channels(score.parts);
  const std::vector<PedalSpan> pedals =
      midi_detail::merge_overlapping_pedal_spans(score.pedal_spans);
  std::vector<PartContent> contents(part_count);
  auto content_of = [&](int part) -> PartContent* {
    return part >= 0 && static_cast<std::size_t>(part) < part_count
               ? &contents[static_cast<std::size_t>(part)]
               : nullptr;
  };
  for (const Note& note : score.notes) {
    if (PartContent* content = content_of(note.part)) content->notes.push_back(&note);
  }
  for (const PedalSpan& pedal : pedals) {
    if (PartContent* content = content_of(pedal.part)) content->pedals.push_back(&pedal);
  }

  std::vector<std::uint8_t> out;
  std::vector<std::uint8_t> header;
  midi_detail::append_be(header, 1, 2);  // format 1: simultaneous tracks
  midi_detail::append_be(header, static_cast<std::uint32_t>(part_count + 1), 2);
  midi_detail::append_be(header, static_cast<std::uint32_t>(to_file.ticks_per_quarter()), 2);
  midi_detail::append_chunk(out, "MThd", header);
  midi_detail::append_chunk(out, "MTrk", conductor_track(score, to_file));
  for (std::size_t p = 0; p < part_count; ++p) {
    midi_detail::append_chunk(
        out, "MTrk", part_track(score.parts[p], channels[p], std::move(contents[p]), to_file));
  }
  return out;
}

Status write_midi_file(const Score& score, const std::filesystem::path& path) {
  const std::vector<std::uint8_t> bytes = write_midi(score);
  return write_file_atomically(path, std::string(bytes.begin(), bytes.end()));
}

}  // namespace tutti::music
