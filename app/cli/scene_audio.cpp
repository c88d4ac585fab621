// SPDX-License-Identifier: MIT
#include <tutti/cli/scene_audio.hpp>

#include <cmath>
#include <vector>

#include <tutti/audio/sound_font.hpp>
#include <tutti/audio/synth_events.hpp>
#include <tutti/runtime/scene_sound.hpp>

namespace tutti::cli {
namespace {

std::int64_t audio_frame_of_video_frame(std::int64_t k, int fps, int sample_rate) {
  return static_cast<std::int64_t>(
      std::llround(static_cast<double>(k) * sample_rate / static_cast<double>(fps)));
}

}  // namespace

Result<audio::AudioBuffer> render_scene_audio(const stage::Stage& stage, int fps,
                                              std::int64_t first_frame, std::int64_t end_frame,
                                              const SceneAudioOptions& options) {
  auto font = audio::find_sound_font(options.sound_font);
  if (!font) return font.error();
  // The same timeline `tutti play` hears (runtime/scene_sound.hpp): the Note entities as heard.
  runtime::SceneSoundOptions sound;
  sound.sample_rate = options.sample_rate;
  sound.compensate_attacks = options.compensate_attacks;
  auto timeline = runtime::scene_timeline(stage, options.tempo_factor, *font, sound);
  if (!timeline) return timeline.error();

  const std::int64_t from = audio_frame_of_video_frame(first_frame, fps, options.sample_rate);
  const std::int64_t to = audio_frame_of_video_frame(end_frame, fps, options.sample_rate);
  audio::OfflineSynthOptions synth_options;
  synth_options.sound_font = *font;
  synth_options.frames = to;
  auto full = audio::render_timeline(*timeline, synth_options);
  if (!full) return full.error();
  audio::AudioBuffer slice;
  slice.sample_rate = full->sample_rate;
  slice.channels = full->channels;
  const auto channels = static_cast<std::size_t>(full->channels);
  slice.samples.assign(full->samples.begin() +
                           static_cast<std::ptrdiff_t>(static_cast<std::size_t>(from) * channels),
                       full->samples.end());
  return slice;
}

}  // namespace tutti::cli
