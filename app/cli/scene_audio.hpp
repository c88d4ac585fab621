// SPDX-License-Identifier: MIT
#pragma once
// The sound of a rendered range of frames: the scene's scores, as played (Stage::sounding),
// through FluidSynth from the
// scene's start, cut to frames [first, end) at `fps`. A slice's audio is exactly the full
// render's samples for those frames (the cut points are round(k * rate / fps)).

#include <cstdint>
#include <filesystem>

#include <tutti/audio/offline_synth.hpp>
#include <tutti/core/result.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::cli {

struct SceneAudioOptions {
  std::filesystem::path sound_font;  // empty: find_sound_font()'s search
  int sample_rate = 48000;
  double tempo_factor = 1.0;  // practice tempo (the frames are at the same factor)
  // Wind notes sent early by their measured attack (audio/attack_time.hpp), so they are heard
  // when the tongue, valve or slide lands.
  bool compensate_attacks = true;
};

Result<audio::AudioBuffer> render_scene_audio(const stage::Stage& stage, int fps,
                                              std::int64_t first_frame, std::int64_t end_frame,
                                              const SceneAudioOptions& options = {});

}  // namespace tutti::cli
