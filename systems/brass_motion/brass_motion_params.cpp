// SPDX-License-Identifier: MIT
#include <nlohmann/json.hpp>

#include <tutti/brass_motion/brass_motion_params.hpp>

#include <tutti/content/content_dir.hpp>
#include <tutti/content/json_reader.hpp>

namespace tutti::brass_motion {

Result<BrassMotionParams> load_brass_motion_params() {
  return load_brass_motion_params(
      (content::default_content_dir() / "brass" / "motion.json").string());
}

Result<BrassMotionParams> load_brass_motion_params(const std::string& file) {
  auto document = content::read_json_file(file);
  if (!document) return document.error();
  const content::JsonReader reader(file);
  BrassMotionParams p;
  const content::NumberField fields[] = {
      {"valve_lead_s", &p.valve_lead_s, 0.0, 1.0},
      {"valve_release_s", &p.valve_release_s, 0.0, 1.0},
      {"valve_hold_rest_s", &p.valve_hold_rest_s, 0.0, 10.0},
      {"slide_comfortable_s", &p.slide_comfortable_s, 0.0, 2.0},
      {"slide_min_move_s", &p.slide_min_move_s, 0.001, 1.0},
      {"slide_reach_ramp_s", &p.slide_reach_ramp_s, 0.01, 2.0},
      {"slide_reach_bridge_s", &p.slide_reach_bridge_s, 0.0, 5.0},
      {"mouth_rest_tension", &p.mouth_rest_tension, 0.0, 1.0},
      {"mouth_low_tension", &p.mouth_low_tension, 0.0, 1.0},
      {"mouth_tension_exponent", &p.mouth_tension_exponent, 0.1, 10.0},
      {"mouth_ramp_s", &p.mouth_ramp_s, 0.0, 1.0},
      {"mouth_relax_after_s", &p.mouth_relax_after_s, 0.0, 10.0},
      {"corner_pull_from", &p.corner_pull_from, 0.0, 0.999},
  };
  if (auto ok = reader.read_number_fields(*document, "", fields, /*required=*/false); !ok) {
    return ok.error();
  }
  return p;
}

}  // namespace tutti::brass_motion
