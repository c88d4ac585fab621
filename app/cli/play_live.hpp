// SPDX-License-Identifier: MIT
#pragma once
// `tutti play --midi-in PORT` / `--keyboard-piano`: the scene's pianist plays what comes in
// instead of the score. Every frame the sources are polled at the host time, the live pianist
// (app/live) fingers and strikes the new notes, its motion replaces the pianist's planned
// one on the stage, and the stage is shown at the host time; the notes sound through a live
// FluidSynth (silent, with a notice, without a sound card). The scene's own music is not played.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/live/keyboard_piano.hpp>
#include <tutti/live/live_note_event.hpp>
#include <tutti/live/live_pianist.hpp>
#include <tutti/live/live_synth.hpp>
#include <tutti/scene/scene.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::cli {

struct LivePlayOptions {
  std::string midi_in;  // "" = none; "auto", "none" (open, connect nothing), "client:port", name
  bool keyboard_piano = false;
  std::filesystem::path sound_font;  // empty: audio::find_sound_font()
  std::string audio_driver;          // "simulated": no sound
};

class LivePlay {
 public:
  bool enabled() const { return !sources_.empty(); }

  // Checked before any window opens: the scene has a pianist, the MIDI port opens.
  static Result<std::unique_ptr<LivePlay>> open(const LivePlayOptions& options,
                                                const scene::Scene& scene);
  // Once the stage is built: the live pianist replaces the planned motion in `posed`, the
  // world the stage is posed and drawn in (the player's sampling context). `notice` gets a line
  // about the sound when there is none.
  Status attach(const stage::Stage& stage, ecs::World& posed, const scene::Scene& scene,
                std::string& notice);
  // Polls, plays and hands the new motion to `posed` (call before showing host_s).
  void frame(const stage::Stage& stage, ecs::World& posed, double host_s);

  live::KeyboardPiano* keyboard() { return keyboard_; }
  std::string describe()
      const;  // "live input: ALSA 128:0 (tutti) (2 connections), computer keyboard"
  int notes_played() const { return notes_; }

 private:
  void hand_to(const stage::Stage& stage, ecs::World& posed) const;

  std::vector<std::unique_ptr<live::LiveNoteSource>> sources_;
  live::KeyboardPiano* keyboard_ = nullptr;
  int alsa_connections_ = -1;
  LivePlayOptions options_;
  std::unique_ptr<live::LivePianist> pianist_;
  std::unique_ptr<live::LiveSynth> synth_;
  std::vector<live::LiveNoteEvent> polled_;
  int notes_ = 0;
};

}  // namespace tutti::cli
