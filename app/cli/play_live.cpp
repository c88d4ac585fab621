// SPDX-License-Identifier: MIT
#include <tutti/cli/play_live.hpp>

#include <tutti/audio/sound_font.hpp>
#include <tutti/finger_motion/finger_motion_params.hpp>
#include <tutti/fingering_planner/fingering_model.hpp>
#include <tutti/live/alsa_midi_source.hpp>
#include <tutti/piano/keyboard_players.hpp>

namespace tutti::cli {

Result<std::unique_ptr<LivePlay>> LivePlay::open(const LivePlayOptions& options,
                                                 const scene::Scene& scene) {
  auto play = std::make_unique<LivePlay>();
  play->options_ = options;
  if (options.midi_in.empty() && !options.keyboard_piano) return play;
  const char* flag = options.midi_in.empty() ? "--keyboard-piano" : "--midi-in";
  if (piano::keyboard_players(scene).empty()) {
    return Error{std::string(flag) + ": " + scene.source + " has no pianist to play the notes"};
  }
  if (!options.midi_in.empty()) {
    auto alsa = live::AlsaMidiSource::open(options.midi_in == "none" ? "" : options.midi_in);
    if (!alsa) return Error{"--midi-in " + options.midi_in + ": " + alsa.error().message};
    play->alsa_connections_ = (*alsa)->connections();
    play->sources_.push_back(std::move(*alsa));
  }
  if (options.keyboard_piano) {
    auto keyboard = std::make_unique<live::KeyboardPiano>();
    play->keyboard_ = keyboard.get();
    play->sources_.push_back(std::move(keyboard));
  }
  return play;
}

Status LivePlay::attach(const stage::Stage& stage, ecs::World& posed, const scene::Scene& scene,
                        std::string& notice) {
  if (!enabled()) return {};
  if (stage.find_performer("piano", 0).is_null()) {
    return Error{scene.source + ": the stage has no pianist"};
  }
  auto model = fingering_planner::load_fingering_model(
      "default", piano::keyboard_players(scene).front().hand_size);
  if (!model) return model.error();
  auto params = finger_motion::load_finger_motion_params(
      finger_motion::finger_motion_params_path(piano_model::default_content_dir()));
  if (!params) return params.error();
  auto pianist = live::LivePianist::create(std::move(*model), *params);
  if (!pianist) return pianist.error();
  pianist_ = std::move(*pianist);
  hand_to(stage, posed);
  if (options_.audio_driver != "simulated") {
    auto font = audio::find_sound_font(options_.sound_font);
    if (!font) {
      notice = "play: live notes are silent (" + font.error().message + ")";
    } else if (auto synth = live::LiveSynth::open(*font, options_.audio_driver); !synth) {
      notice = "play: live notes are silent (" + synth.error().message + ")";
    } else {
      synth_ = std::move(*synth);
    }
  }
  return {};
}

void LivePlay::frame(const stage::Stage& stage, ecs::World& posed, double host_s) {
  if (!pianist_) return;
  polled_.clear();
  for (auto& source : sources_) source->poll(host_s, polled_);
  if (synth_) synth_->play(polled_);
  for (const live::LiveNoteEvent& e : polled_) notes_ += e.on ? 1 : 0;
  if (pianist_->update(polled_, host_s)) hand_to(stage, posed);
}

void LivePlay::hand_to(const stage::Stage& stage, ecs::World& posed) const {
  // The live motion drives the pianist's hands from now on (the finger-motion system reads it).
  auto* handle = posed.try_get<finger_motion::PianistMotionHandle>(
      stage.find_performer("piano", 0));
  if (handle != nullptr) handle->motion = pianist_->motion();
}

std::string LivePlay::describe() const {
  std::string text;
  for (const auto& source : sources_) {
    text += (text.empty() ? "" : ", ") + source->name();
    if (source.get() != keyboard_ && alsa_connections_ >= 0) {
      text += " (" + std::to_string(alsa_connections_) + " connection" +
              (alsa_connections_ == 1 ? "" : "s") + ")";
    }
  }
  return "play: live input: " + text + (synth_ ? ", sound on " + synth_->device() : "");
}

}  // namespace tutti::cli
