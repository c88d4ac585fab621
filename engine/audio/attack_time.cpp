// SPDX-License-Identifier: MIT
#include <tutti/audio/attack_time.hpp>

#include <tutti/audio/energy_rise.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <tuple>

#include <tutti/audio/offline_synth.hpp>
#include <tutti/audio/onset_detection.hpp>

namespace tutti::audio {
namespace {

constexpr double kSlotS = 0.6;  // one note per slot
// A struck note's slot is longer: the last one's release has died away when it enters, so its
// energy jump is its own.
constexpr double kStruckSlotS = 1.2;

constexpr double kOnS = 0.02;   // its note-on, into the slot
constexpr double kOffS = 0.45;  // and its note-off

std::int64_t on_block(double seconds, int rate) {
  const auto frame = static_cast<std::int64_t>(std::llround(seconds * rate));
  return frame / kSynthBlockFrames * kSynthBlockFrames;
}

}  // namespace

bool is_struck_program(int program) { return program >= 0 && program < 16; }

Result<std::vector<double>> measure_attack_times(const std::filesystem::path& sound_font,
                                                 std::span<const SampledNote> notes,
                                                 int sample_rate, const AttackOptions& o) {
  std::vector<double> attacks(notes.size(), 0.0);
  if (notes.empty()) return attacks;
  SynthTimeline timeline;
  timeline.sample_rate = sample_rate;
  std::vector<double> slot_start(notes.size() + 1, 0.0);
  for (std::size_t i = 0; i < notes.size(); ++i) {
    slot_start[i + 1] = slot_start[i] + (is_struck_program(notes[i].program) ? kStruckSlotS : kSlotS);
  }
  for (std::size_t i = 0; i < notes.size(); ++i) {
    const double slot = slot_start[i];
    const SampledNote& n = notes[i];
    timeline.events.push_back(
        {on_block(slot, sample_rate), SynthEventKind::program, 0, n.program, 0});
    timeline.events.push_back(
        {on_block(slot + kOnS, sample_rate), SynthEventKind::note_on, 0, n.key, n.velocity});
    timeline.events.push_back(
        {on_block(slot + kOffS, sample_rate), SynthEventKind::note_off, 0, n.key, 0});
  }
  timeline.end_frame = on_block(slot_start.back(), sample_rate);
  OfflineSynthOptions synth;
  synth.sound_font = sound_font;
  synth.frames = timeline.end_frame;
  auto audio = render_timeline(timeline, synth);
  if (!audio) return audio.error();

  // Each slot on its own, through the detector.
  for (std::size_t i = 0; i < notes.size(); ++i) {
    const std::int64_t from = on_block(slot_start[i], sample_rate);
    const std::int64_t to = on_block(slot_start[i + 1], sample_rate);
    AudioBuffer slot;
    slot.sample_rate = sample_rate;
    slot.channels = 2;
    slot.samples.assign(audio->samples.begin() + static_cast<std::ptrdiff_t>(from * 2),
                        audio->samples.begin() + static_cast<std::ptrdiff_t>(to * 2));
    const std::vector<Onset> onsets = detect_onsets(slot, o.onsets);
    if (onsets.empty()) continue;  // silent
    const double on_s =
        static_cast<double>(on_block(slot_start[i] + kOnS, sample_rate) - from) /
        sample_rate;
    // The detector finds the note. A struck sample (General MIDI's piano and chromatic
    // percussion families, programs 0-15) is heard where its energy jumps (energy_rise.hpp), a
    // few milliseconds after its note-on where the detector's -6 dB point hears it some 7 ms
    // later; a blown note swells and is heard at the detector's point.
    const bool struck = is_struck_program(notes[i].program);
    const double heard =
        struck ? steepest_energy_rise_s(slot, on_s - 0.001, onsets.front().time_s + 0.005,
                                        onsets.front().time_s)
               : onsets.front().time_s;
    attacks[i] = std::clamp(heard - on_s, 0.0, o.max_advance_s);
  }
  return attacks;
}

Result<AttackCompensation> compensate_attacks(SynthTimeline& timeline,
                                              const std::filesystem::path& sound_font,
                                              const AttackOptions& options) {
  AttackCompensation stats;
  const auto channels = static_cast<std::size_t>(std::max(timeline.channel_count, 16));
  struct ChannelState {
    int program = 0;
    int sounding = 0;
    int last_key = -1;
    std::int64_t last_on_frame = -1;
    std::int64_t last_off_frame = -1;         // of last_key
    std::size_t last_off = 0;                 // its event
    std::int64_t quiet_since = 0;             // the frame the channel last fell silent
    std::array<std::int64_t, 128> key_off{};  // each key's last note-off
  };
  // Attacks differ little between neighbouring velocities: measure one per 8.
  auto bucket = [](int velocity) { return std::clamp((velocity + 4) / 8 * 8, 1, 127); };

  // One pass finds the notes (and, on the second, moves them): every melodic note-on;
  // slurred when its channel's only note ended at this very frame.
  auto walk = [&](auto&& visit) {
    std::vector<ChannelState> state(channels);
    for (std::size_t i = 0; i < timeline.events.size(); ++i) {
      SynthEvent& e = timeline.events[i];
      if (e.channel < 0 || static_cast<std::size_t>(e.channel) >= channels) continue;
      ChannelState& c = state[static_cast<std::size_t>(e.channel)];
      const auto key = static_cast<std::size_t>(std::clamp(e.data1, 0, 127));
      switch (e.kind) {
        case SynthEventKind::program:
          c.program = e.data1;
          break;
        case SynthEventKind::control:
          break;
        case SynthEventKind::note_off:
          c.sounding = std::max(0, c.sounding - 1);
          c.key_off[key] = e.frame;
          if (c.sounding == 0) c.quiet_since = e.frame;
          if (e.data1 == c.last_key) {
            c.last_off_frame = e.frame;
            c.last_off = i;
          }
          break;
        case SynthEventKind::note_on:
          if (e.channel % 16 != 9) visit(i, c);  // not a percussion channel
          ++c.sounding;
          c.last_key = e.data1;
          c.last_on_frame = e.frame;
          c.last_off_frame = -1;
          break;
      }
    }
  };

  std::vector<SampledNote> unique;
  std::map<std::tuple<int, int, int>, std::size_t> index_of;
  walk([&](std::size_t i, const ChannelState& c) {
    const SynthEvent& e = timeline.events[i];
    const std::tuple<int, int, int> key{c.program, e.data1, bucket(e.data2)};
    auto [it, added] = index_of.try_emplace(key, unique.size());
    if (added) unique.push_back({c.program, e.data1, bucket(e.data2)});
    ++stats.notes;
  });
  if (unique.empty()) return stats;
  auto attacks = measure_attack_times(sound_font, unique, timeline.sample_rate, options);
  if (!attacks) return attacks.error();

  double sum = 0.0;
  walk([&](std::size_t i, const ChannelState& c) {
    SynthEvent& e = timeline.events[i];
    const double attack = (*attacks)[index_of.at({c.program, e.data1, bucket(e.data2)})];
    const auto blocks = static_cast<std::int64_t>(
        std::llround(attack * timeline.sample_rate / static_cast<double>(kSynthBlockFrames)));
    const bool slurred = c.sounding == 0 && c.last_off_frame == e.frame && c.last_on_frame >= 0;
    // Never before the same key was last released, nor (a line after a rest) into its
    // previous note; a slur keeps half the old note.
    std::int64_t earliest = c.key_off[static_cast<std::size_t>(std::clamp(e.data1, 0, 127))];
    if (c.sounding == 0) earliest = std::max(earliest, c.quiet_since);
    if (slurred) {
      const std::int64_t half = c.last_on_frame + (e.frame - c.last_on_frame + 1) / 2;
      earliest = (half + kSynthBlockFrames - 1) / kSynthBlockFrames * kSynthBlockFrames;
    }
    const std::int64_t moved = std::max(e.frame - blocks * kSynthBlockFrames, earliest);
    if (moved >= e.frame) return;
    const double advance = static_cast<double>(e.frame - moved) / timeline.sample_rate;
    if (slurred) timeline.events[c.last_off].frame = moved;
    e.frame = moved;
    ++stats.moved;
    sum += advance;
    stats.max_advance_s = std::max(stats.max_advance_s, advance);
  });
  if (stats.moved > 0) stats.mean_advance_s = sum / stats.moved;
  std::stable_sort(timeline.events.begin(), timeline.events.end(),
                   [](const SynthEvent& a, const SynthEvent& b) {
                     return a.frame != b.frame ? a.frame < b.frame : a.kind < b.kind;
                   });
  return stats;
}

}  // namespace tutti::audio
