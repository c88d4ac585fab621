// SPDX-License-Identifier: MIT
#include <tutti/runtime/scene_sound.hpp>

#include <vector>

#include <tutti/audio/attack_time.hpp>
#include <tutti/audio/sound_font.hpp>

namespace tutti::runtime {

Result<audio::SynthTimeline> scene_timeline(const stage::Stage& stage, double tempo_factor,
                                            const std::filesystem::path& sound_font,
                                            const SceneSoundOptions& options) {
  // The notes as played (catch breaths leave gaps, the keys' own timing), from the Note entities.
  const std::vector<music::Score> heard = stage.heard_scores();
  std::vector<const music::Score*> scores;
  for (const music::Score& score : heard) scores.push_back(&score);
  audio::TimelineOptions timeline_options;
  timeline_options.sample_rate = options.sample_rate;
  timeline_options.start_s = stage.start_s();
  timeline_options.tempo_factor = tempo_factor;
  auto timeline = audio::build_synth_timeline(scores, timeline_options);
  if (!timeline) return timeline.error();
  if (options.compensate_attacks) {
    auto compensated = audio::compensate_attacks(*timeline, sound_font);
    if (!compensated) return compensated.error();
  }
  return timeline;
}

Result<std::unique_ptr<audio::LiveOutput>> open_scene_sound(const stage::Stage& stage,
                                                            double tempo_factor,
                                                            const SceneSoundOptions& options) {
  auto font = audio::find_sound_font(options.sound_font);
  if (!font) return font.error();
  auto timeline = scene_timeline(stage, tempo_factor, *font, options);
  if (!timeline) return timeline.error();
  audio::LiveOutputOptions live;
  live.sound_font = *font;
  live.driver = options.driver;
  return audio::LiveOutput::open(*timeline, live);
}

}  // namespace tutti::runtime
