#include "audio/offline_synth.hpp"

#include <fluidsynth.h>

#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <string>

namespace tutti::audio {
namespace {

struct SettingsDeleter {
  void operator()(fluid_settings_t* s) const { delete_fluid_settings(s); }
};
struct SynthDeleter {
  void operator()(fluid_synth_t* s) const { delete_fluid_synth(s); }
};

// FluidSynth prints warnings (a missing preset, say) to stderr by default; tutti reports its own
// errors, so its log goes nowhere except panics and errors, which are kept for the message.
std::string& last_fluid_error() {
  static std::string message;
  return message;
}

void keep_error(int, const char* message, void*) {
  last_fluid_error() = message != nullptr ? message : "";
}

void quiet_log() {
  static std::once_flag once;
  std::call_once(once, [] {
    fluid_set_log_function(FLUID_PANIC, keep_error, nullptr);
    fluid_set_log_function(FLUID_ERR, keep_error, nullptr);
    fluid_set_log_function(FLUID_WARN, nullptr, nullptr);
    fluid_set_log_function(FLUID_INFO, nullptr, nullptr);
    fluid_set_log_function(FLUID_DBG, nullptr, nullptr);
  });
}

void send(fluid_synth_t* synth, const SynthEvent& event) {
  switch (event.kind) {
    case SynthEventKind::note_on:
      fluid_synth_noteon(synth, event.channel, event.data1, event.data2);
      break;
    case SynthEventKind::note_off:
      fluid_synth_noteoff(synth, event.channel, event.data1);
      break;
    case SynthEventKind::control:
      fluid_synth_cc(synth, event.channel, event.data1, event.data2);
      break;
    case SynthEventKind::program:
      fluid_synth_program_change(synth, event.channel, event.data1);
      break;
  }
}

std::int16_t to_pcm(float v) {
  const float scaled = std::nearbyint(std::clamp(v, -1.0f, 1.0f) * 32767.0f);
  return static_cast<std::int16_t>(scaled);
}

}  // namespace

Result<AudioBuffer> render_timeline(const SynthTimeline& timeline,
                                    const OfflineSynthOptions& options) {
  quiet_log();
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
      send(synth.get(), timeline.events[next++]);
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
