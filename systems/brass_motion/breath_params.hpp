// SPDX-License-Identifier: MIT
#pragma once
// How a brass player breathes: inhale timing, the air model and catch-breaths
// (content/brass/breath.json; README.md in this folder). Loading is strict: every key is
// required, unknown keys and out-of-range values are errors naming the file and the JSON path
// ("breath.json: /capacity_s: must be in [0.5, 120]").

#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include <tutti/core/result.hpp>

namespace tutti::brass_motion {

struct BreathParams {
  // Inhaling. A breath fills the end of the rule's window (rest, last beat, last two beats) for
  // at most inhale_max_s; a window shorter than inhale_min_s gives no breath.
  double inhale_min_s = 0.15;
  double inhale_max_s = 1.0;
  double refill_per_s = 1.25;  // fraction of full lungs gained per second of inhale
  double prepare_s = 0.6;      // preparatory motion before a breath after a long rest
  double resting_air = 0.45;   // air before the first breath

  // Draining. Full lungs last capacity_s of playing at mf_velocity in the middle of the range;
  // the rate is multiplied by a loudness factor (drain_soft at velocity 1, 1 at mf_velocity,
  // drain_loud at 127, linear between) and a register factor (drain_low at the bottom of the
  // range, 1 in the middle, drain_high at the top, linear between).
  double capacity_s = 8.0;
  double mf_velocity = 80.0;
  double drain_soft = 0.6;
  double drain_loud = 1.8;
  double drain_low = 0.85;
  double drain_high = 1.4;

  // Strain: 0 while air >= strain_from_air, rising smoothly to 1 as the air reaches 0.
  double strain_from_air = 0.25;

  // Catch-breaths, when the air would fall below catch_reserve_air inside a phrase: an inhale
  // of catch_inhale_s (at least catch_min_s) taken from the rest after a note and, where that is
  // too short, from the end of the note (at most catch_max_cut of it). Placed where the air is
  // below catch_below_air when possible, after the longest note; a note starting on a downbeat
  // counts (1 + catch_strong_beat_bonus) times its length, on another beat (1 + bonus / 2)
  // times, and the strain the player would feel there lowers the score (README.md).
  double catch_reserve_air = 0.1;
  double catch_inhale_s = 0.25;
  double catch_min_s = 0.12;
  double catch_max_cut = 0.4;
  double catch_below_air = 0.5;
  double catch_strong_beat_bonus = 0.5;
};

// content/brass/breath.json under content::default_content_dir().
std::filesystem::path breath_params_path();
Result<BreathParams> load_breath_params();
Result<BreathParams> load_breath_params(const std::filesystem::path& file);
// `file_name` is used in messages only.
Result<BreathParams> breath_params_from_json(const nlohmann::json& document,
                                             const std::string& file_name);

}  // namespace tutti::brass_motion
