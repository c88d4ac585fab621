// SPDX-License-Identifier: MIT
#pragma once
// The scene's sound for live playback: the stage's scores as played (Stage::heard_scores) as one
// SynthTimeline at a practice tempo, wind attacks compensated (as `tutti render` does), opened
// on a LiveOutput. A tempo change opens a new one: the events are re-timed at the new factor.

#include <filesystem>
#include <memory>
#include <string>

#include <tutti/audio/live_output.hpp>
#include <tutti/audio/synth_events.hpp>
#include <tutti/core/result.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::runtime {

struct SceneSoundOptions {
  std::filesystem::path sound_font;  // empty: audio::find_sound_font()'s search
  std::string driver;                // FluidSynth audio driver; empty: its default; "simulated"
  int sample_rate = 48000;
  bool compensate_attacks = true;
};

// Frame 0 is score time stage.start_s(); tempo_factor in [0.1, 4].
Result<audio::SynthTimeline> scene_timeline(const stage::Stage& stage, double tempo_factor,
                                            const std::filesystem::path& sound_font,
                                            const SceneSoundOptions& options = {});

// The timeline on a live device (simulated when there is none).
Result<std::unique_ptr<audio::LiveOutput>> open_scene_sound(const stage::Stage& stage,
                                                            double tempo_factor,
                                                            const SceneSoundOptions& options = {});

}  // namespace tutti::runtime
