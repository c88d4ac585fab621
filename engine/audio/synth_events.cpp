// SPDX-License-Identifier: MIT
#include <tutti/audio/synth_events.hpp>
#include <tutti/music/general_midi.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

namespace tutti::audio {
namespace {

constexpr int kSustainPedal = 64;
constexpr int kMaxParts = 240;

}  // namespace

std::int64_t frame_of(double score_s, const TimelineOptions& options) {
  const double frames =
      (score_s - options.start_s) / options.tempo_factor * static_cast<double>(options.sample_rate);
  const double blocks = std::nearbyint(frames / kSynthBlockFrames);
  return static_cast<std::int64_t>(blocks) * kSynthBlockFrames;
}

Result<SynthTimeline> build_synth_timeline(std::span<const music::Score* const> scores,
                                           const TimelineOptions& options) {
  if (options.sample_rate < 8000 || options.sample_rate > 192000) {
    return Error{"audio: sample rate " + std::to_string(options.sample_rate) +
                 " Hz is outside 8000..192000"};
  }
  if (!(options.tempo_factor >= 0.1 && options.tempo_factor <= 4.0)) {
    return Error{"audio: tempo factor must be in [0.1, 4]"};
  }
  if (!std::isfinite(options.start_s)) return Error{"audio: start time is not a number"};
  SynthTimeline timeline;
  timeline.sample_rate = options.sample_rate;
  timeline.start_s = options.start_s;
  timeline.tempo_factor = options.tempo_factor;

  // Melodic parts take channels 0..15 skipping 9, then 16..31 skipping 25, ...; percussion parts
  // share the percussion channel of the first bank.
  int next_melodic = 0;
  int parts_total = 0;
  int highest_channel = 0;
  for (std::size_t s = 0; s < scores.size(); ++s) {
    const music::Score& score = *scores[s];
    parts_total += static_cast<int>(score.parts.size());
    if (parts_total > kMaxParts) {
      return Error{score.source + ": more than " + std::to_string(kMaxParts) +
                   " parts in the scene's scores"};
    }
    std::vector<int> channel_of_part(score.parts.size(), 0);
    for (std::size_t p = 0; p < score.parts.size(); ++p) {
      const music::Part& part = score.parts[p];
      int channel = music::kPercussionChannel;
      if (!part.percussion) {
        if (next_melodic % 16 == music::kPercussionChannel) ++next_melodic;
        channel = next_melodic++;
        timeline.events.push_back(
            {0, SynthEventKind::program, channel, std::clamp(part.program, 0, 127), 0, -1, -1});
      }
      channel_of_part[p] = channel;
      highest_channel = std::max(highest_channel, channel);
    }
    for (const music::PedalSpan& pedal : score.pedal_spans) {
      if (pedal.part < 0 || static_cast<std::size_t>(pedal.part) >= score.parts.size()) continue;
      if (pedal.offset_s <= options.start_s) continue;
      const int channel = channel_of_part[static_cast<std::size_t>(pedal.part)];
      timeline.events.push_back({std::max<std::int64_t>(0, frame_of(pedal.onset_s, options)),
                                 SynthEventKind::control, channel, kSustainPedal, 127, -1, -1});
      timeline.events.push_back({frame_of(pedal.offset_s, options), SynthEventKind::control,
                                 channel, kSustainPedal, 0, -1, -1});
    }
    for (std::size_t n = 0; n < score.notes.size(); ++n) {
      const music::Note& note = score.notes[n];
      if (note.onset_s < options.start_s) continue;
      if (note.part < 0 || static_cast<std::size_t>(note.part) >= score.parts.size()) continue;
      const int channel = channel_of_part[static_cast<std::size_t>(note.part)];
      const std::int64_t on = frame_of(note.onset_s, options);
      // A note always sounds for at least one block.
      const std::int64_t off = std::max(on + kSynthBlockFrames, frame_of(note.offset_s, options));
      const int key = std::clamp(note.pitch, 0, 127);
      timeline.events.push_back({on, SynthEventKind::note_on, channel, key,
                                 std::clamp(note.velocity, 1, 127), static_cast<int>(s),
                                 static_cast<int>(n)});
      timeline.events.push_back({off, SynthEventKind::note_off, channel, key, 0,
                                 static_cast<int>(s), static_cast<int>(n)});
      timeline.end_frame = std::max(timeline.end_frame, off);
    }
  }
  timeline.channel_count = (highest_channel / 16 + 1) * 16;
  // Offs before ons at one frame, so a repeated key sounds again; ties by channel and key.
  std::stable_sort(timeline.events.begin(), timeline.events.end(),
                   [](const SynthEvent& a, const SynthEvent& b) {
                     return std::tie(a.frame, a.kind, a.channel, a.data1) <
                            std::tie(b.frame, b.kind, b.channel, b.data1);
                   });
  return timeline;
}

}  // namespace tutti::audio
