// SPDX-License-Identifier: MIT
#include <tutti/audio/offline_synth.hpp>

#include <fluidsynth.h>

#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <string>

#include <tutti/audio/fluid_synth_util.hpp>

namespace tutti::audio {
namespace {

std::int16_t to_pcm(float v) {
  const float scaled = std::nearbyint(std::clamp(v, -1.0f, 1.0f) * 32767.0f);
  return static_cast<std::int16_t>(scaled);
}

}  // namespace

Result<AudioBuffer> render_timeline(const SynthTimeline& timeline,
                                    const OfflineSynthOptions& options) {
  quiet_fluid_log();
  std::int64_t frames = options.frames;
  if (frames < 0) {
    frames = timeline.end_frame +
             static_cast<std::int64_t>(std::ceil(options.tail_s * timeline.sample_rate));
  }
  if (frames > std::numeric_limits<std::int32_t>::max() / 2) {
    return Error{"audio: " + std::to_string(frames) + " frames is too long to render at once"};
  }
  std::unique_ptr<fluid_settings_t, SettingsDeleter> settings(new_fluid_settings());
  if (!settings) return Error{"audio: FluidSynth settings could not be created"};
  fluid_settings_setnum(settings.get(), "synth.sample-rate", timeline.sample_rate);
  fluid_settings_setint(settings.get(), "synth.midi-channels", timeline.channel_count);
  fluid_settings_setint(settings.get(), "synth.cpu-cores", 1);
  fluid_settings_setint(settings.get(), "synth.polyphony", 512);
  fluid_settings_setnum(settings.get(), "synth.gain", options.gain);
  std::unique_ptr<fluid_synth_t, SynthDeleter> synth(new_fluid_synth(settings.get()));
  if (!synth) return Error{"audio: FluidSynth could not start: " + last_fluid_error()};
  if (fluid_synth_sfload(synth.get(), options.sound_font.c_str(), 1) == FLUID_FAILED) {
    return Error{options.sound_font.string() + ": not a sound font FluidSynth can load (" +
                 last_fluid_error() + ")"};
  }

  AudioBuffer out;
  out.sample_rate = timeline.sample_rate;
  out.channels = 2;
  out.samples.resize(static_cast<std::size_t>(frames) * 2);
  std::vector<float> left(kSynthBlockFrames);
  std::vector<float> right(kSynthBlockFrames);
  std::size_t next = 0;
  // Whole blocks only: an event sent between two blocks takes effect at the first frame of the
  // next, which is its frame (synth_events.hpp).
  for (std::int64_t at = 0; at < frames; at += kSynthBlockFrames) {
    while (next < timeline.events.size() && timeline.events[next].frame <= at) {
      send_event(synth.get(), timeline.events[next++]);
    }
    const auto count = static_cast<int>(std::min<std::int64_t>(kSynthBlockFrames, frames - at));
    fluid_synth_write_float(synth.get(), count, left.data(), 0, 1, right.data(), 0, 1);
    for (int i = 0; i < count; ++i) {
      const auto o = static_cast<std::size_t>(at + i) * 2;
      out.samples[o] = to_pcm(left[static_cast<std::size_t>(i)]);
      out.samples[o + 1] = to_pcm(right[static_cast<std::size_t>(i)]);
    }
  }
  return out;
}

}  // namespace tutti::audio
