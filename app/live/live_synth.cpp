// SPDX-License-Identifier: MIT
#include <tutti/live/live_synth.hpp>

#include <algorithm>

#include <tutti/audio/fluid_synth_util.hpp>

namespace tutti::live {

struct LiveSynth::Impl {
  // Destroyed in reverse: the driver stops pulling before the synth goes.
  std::unique_ptr<fluid_settings_t, audio::SettingsDeleter> settings;
  std::unique_ptr<fluid_synth_t, audio::SynthDeleter> synth;
  std::unique_ptr<fluid_audio_driver_t, audio::AudioDriverDeleter> driver;
};

LiveSynth::~LiveSynth() = default;

Result<std::unique_ptr<LiveSynth>> LiveSynth::open(const std::filesystem::path& sound_font,
                                                   const std::string& driver) {
  audio::quiet_fluid_log();
  std::unique_ptr<LiveSynth> out(new LiveSynth());
  out->impl_ = std::make_unique<Impl>();
  Impl& impl = *out->impl_;
  impl.settings.reset(new_fluid_settings());
  if (!impl.settings) return Error{"live sound: FluidSynth could not start"};
  fluid_settings_t* s = impl.settings.get();
  fluid_settings_setnum(s, "synth.sample-rate", 48000);
  fluid_settings_setint(s, "audio.period-size", 512);
  fluid_settings_setint(s, "audio.periods", 2);
  fluid_settings_setnum(s, "synth.gain", 0.5);
  if (!driver.empty()) fluid_settings_setstr(s, "audio.driver", driver.c_str());
  impl.synth.reset(new_fluid_synth(s));
  if (!impl.synth)
    return Error{"live sound: FluidSynth could not start: " + audio::last_fluid_error()};
  if (fluid_synth_sfload(impl.synth.get(), sound_font.c_str(), 1) == FLUID_FAILED) {
    return Error{"live sound: " + sound_font.string() + ": not a sound font FluidSynth loads"};
  }
  fluid_synth_program_change(impl.synth.get(), 0, 0);  // acoustic grand piano
  impl.driver.reset(new_fluid_audio_driver(s, impl.synth.get()));
  if (!impl.driver) return Error{"live sound: no audio device (" + audio::last_fluid_error() + ")"};
  char* name = nullptr;
  if (fluid_settings_dupstr(s, "audio.driver", &name) == FLUID_OK && name != nullptr) {
    out->device_ = name;
    fluid_free(name);
  }
  return out;
}

void LiveSynth::play(std::span<const LiveNoteEvent> events) {
  for (const LiveNoteEvent& e : events) {
    if (e.key < 0 || e.key > 127) continue;
    if (e.on) {
      fluid_synth_noteon(impl_->synth.get(), 0, e.key, std::clamp(e.velocity, 1, 127));
    } else {
      fluid_synth_noteoff(impl_->synth.get(), 0, e.key);
    }
  }
}

}  // namespace tutti::live
