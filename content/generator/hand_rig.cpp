// SPDX-License-Identifier: MIT
#include <tutti/generator/hand_rig.hpp>

#include <nlohmann/json.hpp>

#include <tutti/content/json_reader.hpp>
#include <tutti/finger_motion/finger_chain.hpp>
#include <tutti/finger_motion/finger_motion_params.hpp>
#include <tutti/piano_model/hand_model.hpp>
#include <tutti/piano_model/keyboard.hpp>

namespace tutti::content_generator {
namespace {

using content::NumberField;

constexpr double kAngleMin = -180.0;
constexpr double kAngleMax = 180.0;

}  // namespace

std::string finger_bone_name(int finger, int segment) {
  return std::string(kFingerNames[finger - 1]) + "_" + std::to_string(segment);
}

Result<HandRigData> HandRigData::load(const std::filesystem::path& path) {
  auto document = content::read_json_file(path);
  if (!document) return document.error();
  return from_json(*document, path.filename().string());
}

Result<HandRigData> HandRigData::from_json(const nlohmann::json& document,
                                           const std::string& file_name) {
  const content::JsonReader reader(file_name);
  if (auto ok = reader.check_keys(document, "", {"description", "joint_limits_deg", "shape_mm"});
      !ok) {
    return ok.error();
  }
  HandRigData d;
  if (!document.contains("joint_limits_deg")) return reader.error("/joint_limits_deg", "missing");
  const nlohmann::json& limits = document.at("joint_limits_deg");
  if (!limits.is_object()) return reader.error("/joint_limits_deg", "expected an object");
  for (const auto& [key, value] : limits.items()) {
    bool known = false;
    for (int f = 1; f <= 5 && !known; ++f) {
      for (int s = 1; s <= 3 && !known; ++s) known = key == finger_bone_name(f, s);
    }
    if (!known) return reader.error("/joint_limits_deg", "unknown key \"" + key + "\"");
  }
  for (int f = 1; f <= 5; ++f) {
    for (int s = 1; s <= 3; ++s) {
      const std::string name = finger_bone_name(f, s);
      const std::string path = "/joint_limits_deg/" + name;
      if (!limits.contains(name)) return reader.error(path, "missing");
      JointLimits& l = d.limits[static_cast<std::size_t>(3 * (f - 1) + (s - 1))];
      l.has_spread = s == 1;
      const std::array flexion{
          NumberField{"flexion_min_deg", &l.flexion_min_deg, kAngleMin, kAngleMax},
          NumberField{"flexion_max_deg", &l.flexion_max_deg, kAngleMin, kAngleMax}};
      const std::array both{
          NumberField{"flexion_min_deg", &l.flexion_min_deg, kAngleMin, kAngleMax},
          NumberField{"flexion_max_deg", &l.flexion_max_deg, kAngleMin, kAngleMax},
          NumberField{"spread_min_deg", &l.spread_min_deg, -90.0, 90.0},
          NumberField{"spread_max_deg", &l.spread_max_deg, -90.0, 90.0}};
      const Status ok = l.has_spread
                            ? reader.read_number_fields(limits.at(name), path, both, true)
                            : reader.read_number_fields(limits.at(name), path, flexion, true);
      if (!ok) return ok.error();
      if (l.flexion_min_deg >= l.flexion_max_deg) {
        return reader.error(path + "/flexion_min_deg", "must be less than flexion_max_deg");
      }
      if (l.has_spread && l.spread_min_deg >= l.spread_max_deg) {
        return reader.error(path + "/spread_min_deg", "must be less than spread_max_deg");
      }
    }
  }
  HandShape& h = d.shape;
  const std::array shape{
      NumberField{"palm_length_mm", &h.palm_length_mm, 40.0, 200.0},
      NumberField{"palm_thickness_mm", &h.palm_thickness_mm, 10.0, 60.0},
      NumberField{"palm_margin_mm", &h.palm_margin_mm, 0.0, 40.0},
      NumberField{"finger_radius_mm", &h.finger_radius_mm, 3.0, 20.0},
      NumberField{"little_finger_radius_mm", &h.little_finger_radius_mm, 3.0, 20.0},
      NumberField{"thumb_radius_mm", &h.thumb_radius_mm, 3.0, 20.0},
      NumberField{"tip_radius_ratio", &h.tip_radius_ratio, 0.3, 1.0},
  };
  if (!document.contains("shape_mm")) return reader.error("/shape_mm", "missing");
  if (auto ok = reader.read_number_fields(document.at("shape_mm"), "/shape_mm", shape, true); !ok) {
    return ok.error();
  }
  return d;
}

Result<HandRig> load_hand_rig(const std::filesystem::path& content_dir, components::HandSide side) {
  auto keyboard = piano_model::Keyboard::load(content_dir / "piano" / "keyboard.json");
  if (!keyboard.ok()) return keyboard.error();
  auto hands = piano_model::HandModel::load(content_dir / "piano" / "hands.json", "",
                                            keyboard->white_key_width_mm());
  if (!hands.ok()) return hands.error();
  auto params = finger_motion::load_finger_motion_params(
      finger_motion::finger_motion_params_path(content_dir));
  if (!params.ok()) return params.error();
  auto data = HandRigData::load(content_dir / "generator" / "hand_rig.json");
  if (!data.ok()) return data.error();

  HandRig rig;
  rig.side = side;
  rig.data = *data;
  const music::Hand hand =
      side == components::HandSide::left ? music::Hand::left : music::Hand::right;
  // The same derivation as plan_finger_motion: lengths and root heights scaled by the preset,
  // each finger's rest line in the middle of its reach range.
  const double scale = hands->scale();
  auto rest_x = [&](int finger) {
    const piano_model::FingerRange& range = hands->range(hand, finger);
    return 0.5 * (range.lo_mm + range.hi_mm);
  };
  const finger_motion::FingerGeometry& middle = params->fingers[2];
  const double neutral_z = params->keys.white_top_z_mm + params->keys.hover_lift_mm;
  for (std::size_t f = 0; f < 5; ++f) {
    finger_motion::FingerGeometry g = params->fingers[f];
    for (double& length : g.phalanges_mm) length *= scale;
    g.root_y_mm *= scale;
    g.root_z_mm *= scale;
    g.pad_drop_mm *= scale;
    FingerRig& out = rig.fingers[f];
    out.root_mm = {rest_x(static_cast<int>(f) + 1) - rest_x(3),
                   g.root_y_mm - middle.root_y_mm * scale, g.root_z_mm - middle.root_z_mm * scale};
    out.phalanges_mm = g.phalanges_mm;
    const finger_motion::ChainShape shape = finger_motion::chain_shape(g, g.neutral_bend_rad);
    const finger_motion::StrokeSolution stroke =
        finger_motion::solve_stroke(shape, g.root_z_mm - (neutral_z + g.pad_drop_mm));
    out.rest_angles_rad = {stroke.joint1_rad, shape.bend_rad, shape.joint3_rad};
  }
  return rig;
}

}  // namespace tutti::content_generator
