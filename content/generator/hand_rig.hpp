// SPDX-License-Identifier: MIT
#pragma once
// Everything the skinned hands are built from (README.md, "Hands"): per finger its root, segment
// lengths and rest angles from the piano motion model's data (content/piano/finger_motion.json
// and hands.json, the default preset), and joint limits and flesh sizes from
// content/generator/hand_rig.json (strict: every key required, unknown keys and out-of-range
// values are one-line errors with the JSON path).
//
// Keyboard frame (x along the keys, y into the keys, z up), millimetres, relative to the hand's
// reference point: the middle finger's MCP (components/hand.hpp).

#include <array>
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include <tutti/components/hand_side.hpp>
#include <tutti/core/result.hpp>

namespace tutti::content_generator {

struct JointLimits {
  double flexion_min_deg = 0.0;
  double flexion_max_deg = 0.0;
  bool has_spread = false;  // the first segment of each finger
  double spread_min_deg = 0.0;
  double spread_max_deg = 0.0;
};

struct HandShape {
  double palm_length_mm = 95.0;  // knuckle line back to the wrist
  double palm_thickness_mm = 28.0;
  double palm_margin_mm = 9.0;    // palm beyond the index and little finger roots
  double finger_radius_mm = 9.0;  // fingers 2..4, at the knuckle
  double little_finger_radius_mm = 7.5;
  double thumb_radius_mm = 10.5;
  double tip_radius_ratio = 0.78;  // radius at the fingertip / at the knuckle
};

// hand_rig.json. limits[3 * (finger - 1) + (segment - 1)], finger 1 = thumb.
struct HandRigData {
  std::array<JointLimits, 15> limits{};
  HandShape shape;

  static Result<HandRigData> load(const std::filesystem::path& path);
  static Result<HandRigData> from_json(const nlohmann::json& document,
                                       const std::string& file_name);
};

// Bone names without the side suffix: "thumb_1" .. "little_3"; `finger` 1..5, `segment` 1..3.
std::string finger_bone_name(int finger, int segment);
// The fingers' names in bone names, thumb first.
inline constexpr const char* kFingerNames[5] = {"thumb", "index", "middle", "ring", "little"};

struct FingerRig {
  std::array<double, 3> root_mm{};          // x, y, z from the middle finger's MCP
  std::array<double, 3> phalanges_mm{};     // segment lengths, root first
  std::array<double, 3> rest_angles_rad{};  // joint 1 (stroke), 2 (bend), 3 (coupling x bend)
};

struct HandRig {
  components::HandSide side = components::HandSide::right;
  std::array<FingerRig, 5> fingers{};  // [0] = thumb
  HandRigData data;
};

// Reads content_dir/piano/{keyboard,hands,finger_motion}.json and content_dir/generator/
// hand_rig.json. Rest pose = the motion model's rest: neutral bend, the stroke angle that holds
// the tip at the neutral height (white-key top + hover lift), spread 0.
Result<HandRig> load_hand_rig(const std::filesystem::path& content_dir, components::HandSide side);

}  // namespace tutti::content_generator
