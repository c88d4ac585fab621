// SPDX-License-Identifier: MIT
#pragma once
// The scores of a scene as one time-ordered list of synthesizer events (program changes, sustain
// pedal, note on/off) at audio frames, each part on its own MIDI channel with its General MIDI
// program. Pure data: no FluidSynth here, so the timing rules are testable on their own.
//
// Timing: a score time s plays at audio time (s - start_s) / tempo_factor (0.5 = half speed).
// FluidSynth applies events at the start of its 64-frame blocks (1.33 ms at 48 kHz), so every
// event is placed on the nearest block boundary: at most 32 frames (0.67 ms) from its score time,
// and the frame where it is heard is exactly `frame`.

#include <cstdint>
#include <span>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/music/score.hpp>

namespace tutti::audio {

inline constexpr int kSynthBlockFrames = 64;

enum class SynthEventKind : std::uint8_t { note_off = 0, control = 1, program = 2, note_on = 3 };

struct SynthEvent {
  std::int64_t frame = 0;  // audio frame from the start of the rendering, a multiple of 64
  SynthEventKind kind = SynthEventKind::note_on;
  int channel = 0;  // 0..(channel_count - 1); 9 (+16k) are percussion channels
  int data1 = 0;    // key, controller or program
  int data2 = 0;    // velocity or controller value
  // Which score and note it came from (-1 for programs and controllers).
  int score = -1;
  int note = -1;
};

struct SynthTimeline {
  int sample_rate = 48000;
  double start_s = 0.0;            // score time at frame 0
  double tempo_factor = 1.0;       // > 0
  int channel_count = 16;          // a multiple of 16
  std::vector<SynthEvent> events;  // by frame; at one frame: offs, controls, programs, ons
  std::int64_t end_frame = 0;      // the last note's release, rounded up to a block
};

struct TimelineOptions {
  int sample_rate = 48000;    // 8000..192000
  double start_s = 0.0;       // score time of frame 0; notes before it are left out
  double tempo_factor = 1.0;  // 0.1..4
};

// Audio frame of score time t (its nearest 64-frame block boundary).
std::int64_t frame_of(double score_s, const TimelineOptions& options);

// An error for an out-of-range option or more than 240 parts.
Result<SynthTimeline> build_synth_timeline(std::span<const music::Score* const> scores,
                                           const TimelineOptions& options);

}  // namespace tutti::audio
