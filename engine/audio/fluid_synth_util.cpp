// SPDX-License-Identifier: MIT
#include <tutti/audio/fluid_synth_util.hpp>

#include <mutex>

namespace tutti::audio {
namespace {

std::mutex& error_mutex() {
  static std::mutex m;
  return m;
}

std::string& error_text() {
  static std::string message;
  return message;
}

void keep_error(int, const char* message, void*) {
  const std::lock_guard lock(error_mutex());
  error_text() = message != nullptr ? message : "";
}

}  // namespace

void quiet_fluid_log() {
  static std::once_flag once;
  std::call_once(once, [] {
    fluid_set_log_function(FLUID_PANIC, keep_error, nullptr);
    fluid_set_log_function(FLUID_ERR, keep_error, nullptr);
    fluid_set_log_function(FLUID_WARN, nullptr, nullptr);
    fluid_set_log_function(FLUID_INFO, nullptr, nullptr);
    fluid_set_log_function(FLUID_DBG, nullptr, nullptr);
  });
}

std::string last_fluid_error() {
  const std::lock_guard lock(error_mutex());
  return error_text();
}

void send_event(fluid_synth_t* synth, const SynthEvent& event) {
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

}  // namespace tutti::audio
