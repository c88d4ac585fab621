// SPDX-License-Identifier: MIT
#pragma once
// What the offline renderer and the live output share about driving FluidSynth: owners for its
// objects, its log kept quiet (tutti reports its own errors; the last FluidSynth error is kept
// for the message) and one SynthEvent sent to the synth.

#include <fluidsynth.h>

#include <string>

#include <tutti/audio/synth_events.hpp>

namespace tutti::audio {

struct SettingsDeleter {
  void operator()(fluid_settings_t* s) const { delete_fluid_settings(s); }
};
struct SynthDeleter {
  void operator()(fluid_synth_t* s) const { delete_fluid_synth(s); }
};
struct AudioDriverDeleter {
  void operator()(fluid_audio_driver_t* d) const { delete_fluid_audio_driver(d); }
};

// Panics and errors are kept (last_fluid_error), warnings and the rest dropped. Idempotent.
void quiet_fluid_log();
std::string last_fluid_error();

void send_event(fluid_synth_t* synth, const SynthEvent& event);

}  // namespace tutti::audio
