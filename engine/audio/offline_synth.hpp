// SPDX-License-Identifier: MIT
#pragma once
// Renders a SynthTimeline to interleaved stereo 16-bit PCM with FluidSynth, offline: no audio
// device, one thread, no dither, so the same timeline and sound font give the same samples.
//
//   auto timeline = build_synth_timeline(scores, {.sample_rate = 48000});
//   auto audio = render_timeline(*timeline, {.sound_font = *find_sound_font()});
//   write_wav("out.wav", *audio);

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <vector>

#include <tutti/audio/synth_events.hpp>
#include <tutti/core/result.hpp>

namespace tutti::audio {

struct AudioBuffer {
  int sample_rate = 48000;
  int channels = 2;
  std::vector<std::int16_t> samples;  // interleaved, frames * channels
  std::int64_t frames() const {
    return static_cast<std::int64_t>(samples.size()) / std::max(channels, 1);
  }
};

struct OfflineSynthOptions {
  std::filesystem::path sound_font;
  // Frames to render; -1 = the timeline's end plus `tail_s` of release and reverb.
  std::int64_t frames = -1;
  double tail_s = 2.0;
  double gain = 0.5;  // FluidSynth's master gain
};

// Errors: the sound font does not load, FluidSynth cannot be created, more than 2^31 frames.
Result<AudioBuffer> render_timeline(const SynthTimeline& timeline,
                                    const OfflineSynthOptions& options);

}  // namespace tutti::audio
