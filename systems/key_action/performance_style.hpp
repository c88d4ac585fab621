// SPDX-License-Identifier: MIT
#pragma once
// How a pianist's fingers strike, as data (content/piano/styles.json). The player means every
// note to sound at its written time and loudness; a style says how fast and how faithfully the
// fingers carry that out. Nothing here is a timing or velocity offset: note_strokes.hpp turns a
// style into strokes (when each finger starts down, how fast it moves), and the key action turns
// the resulting motion into sound, so unevenness comes out of the motion.

#include <array>
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/finger_motion/finger_motion_params.hpp>

namespace tutti::key_action {

struct PerformanceStyle {
  std::string name;
  std::string description;
  double strength = 1.0;       // intended key speed x this (1 = the score's velocities)
  double min_stroke_s = 0.02;  // the fastest stroke the fingers make
  double max_stroke_s = 0.2;   // the slowest
  double hover_lift_mm = 9.0;  // fingertip height above the keys between notes
  double bend_scale = 1.0;     // finger curvature on the keys (1 = trained; < 1 flatter)
  // Each finger's actual stroke speed / the one meant (thumb .. little; 1 = does as meant).
  std::array<double, 5> finger_speed{1.0, 1.0, 1.0, 1.0, 1.0};
  double timing_spread_ms = 0.0;        // motor timing noise (standard deviation, seeded)
  double strength_spread = 0.0;         // stroke-speed noise (standard deviation of its log)
  double release_anticipation = 1.0;    // share of release_s a repeated key is let go early
  double release_s = 0.04;              // the finger lifts off a key in this long
  double relax_time_constant_s = 0.15;  // hand relaxation after a release
};

struct StyleBook {
  std::vector<PerformanceStyle> styles;  // sorted by name
  // Error naming the style and the ones that exist.
  Result<PerformanceStyle> find(std::string_view name) const;
};

Result<StyleBook> load_styles(const std::filesystem::path& path);
Result<StyleBook> styles_from_json(const nlohmann::json& document, const std::string& file_name);

// <content_dir>/piano/styles.json.
std::filesystem::path styles_path(const std::filesystem::path& content_dir);

// The finger-motion parameters this style plays with: hover height, the bends on white and black
// keys scaled by bend_scale, release and relaxation times.
finger_motion::FingerMotionParams apply_style(finger_motion::FingerMotionParams params,
                                              const PerformanceStyle& style);

}  // namespace tutti::key_action
