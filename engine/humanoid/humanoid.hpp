// SPDX-License-Identifier: MIT
#pragma once
// A humanoid recognised in a glTF model by itself: which node plays each of tutti's character
// roles, and the facts a retarget needs (units, height, up and facing, rest pose, finger
// segments, face morphs). No mapping file: a VRM file's humanoid table is taken as it is (0.x
// and 1.0); any other rig by its bone names (Mixamo with or without a namespace, Unreal,
// Rigify / Blender .L .R, Unity-like, 3ds Max biped) checked against its hierarchy: the hands
// and feet by name, the arms and legs up their parents, the spine between the hips and the
// head. A mapping file then only overrides.
//
//   auto model = tutti::model::load_model("avatar.glb");
//   tutti::humanoid::Humanoid h = tutti::humanoid::recognise(*model);
//   if (!h.missing_required.empty()) { ... h.missing_required lists them ... }
//   int wrist = h.node("hand_r");

#include <array>
#include <glm/glm.hpp>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <tutti/model/model_asset.hpp>

namespace tutti::humanoid {

// The roles, in order: hips spine chest neck head, shoulder / upper_arm / forearm / hand,
// thigh / shin / foot (left then right), then the 30 finger joints thumb_1_l .. little_3_r
// (joint 1 at the knuckle; the thumb's joint 1 is its metacarpal).
std::span<const std::string_view> roles();
// What a character must have to play: hips, spine, head, both arms down to the hands.
std::span<const std::string_view> required_roles();

enum class RestPose { t_pose, a_pose, other };
std::string_view rest_pose_name(RestPose pose);

struct Humanoid {
  std::string method;  // "VRM 1.0 humanoid table", "bone names and hierarchy"
  // role -> node, in roles() order; -1 where not found.
  std::vector<std::pair<std::string_view, int>> nodes;
  std::vector<std::string_view> missing_required;
  std::vector<std::string_view> missing_optional;

  // Units: metres per unit of the file's world space (its node scales applied): 1 for a file in
  // metres; 0.01 when a file is evidently in centimetres (a standing height of 50..300 units).
  double metres_per_unit = 1.0;
  bool units_guessed = false;
  double height_m = 0.0;  // soles to the top of the head, in metres
  // The file's world frame; on an axis when within 25 (up) or 10 (facing) degrees of it.
  glm::vec3 up{0, 1, 0};
  glm::vec3 facing{0, 0, 1};  // where the character looks
  RestPose rest = RestPose::other;
  double arm_below_horizontal_deg = 0.0;
  // Bones found along each finger (side, thumb .. little): 3, or 4 with a metacarpal (dropped).
  std::array<std::array<int, 5>, 2> finger_bones{};
  // Face morphs: tutti's morph role -> the target's name ("open" -> "jawOpen").
  std::vector<std::pair<std::string, std::string>> morphs;
  std::vector<std::string> notes;  // guesses and cuts, one line each
  // What keeps it from playing besides missing roles ("no skin: no vertex follows its bones").
  std::vector<std::string> problems;

  int node(std::string_view role) const;
  bool playable() const { return missing_required.empty() && problems.empty(); }
  // "no hips, spine; no skin: ..." — what playable() found missing, for a one-line error.
  std::string what_is_missing() const;
};

Humanoid recognise(const model::ModelAsset& asset);

// Degrees about X, then Y, then Z (a mapping file's rotation_deg) that stand the figure on +Y
// facing +Z.
glm::dvec3 rotation_to_tutti_deg(const Humanoid& humanoid);

}  // namespace tutti::humanoid
