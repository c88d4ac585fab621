// SPDX-License-Identifier: MIT
#pragma once
// hand_right.glb and hand_left.glb: a palm and three segments per finger, one skinned mesh, the
// bones posed by the piano finger-motion system's angles (README.md, "Hands"). The performer rig
// (performer_asset.hpp) builds its hands from the same HandRig data, hanging from the wrist with
// identity rest rotations.

#include <tiny_gltf.h>

#include <array>
#include <string>
#include <vector>

#include <tutti/generator/gltf_builder.hpp>
#include <tutti/generator/hand_rig.hpp>

namespace tutti::content_generator {

struct HandBones {
  int root = -1;                                 // the hand bone (origin: middle finger MCP)
  std::array<std::array<int, 3>, 5> segments{};  // [finger - 1][segment - 1]
  std::array<int, 5> tips{};                     // non-joint nodes at the fingertips
};

// The posing contract: a finger bone's local rotation for the motion model's angles. Flexion
// (Finger::mcp/pip/dip_flexion_rad, thumb: abduction/mcp/pip) turns about the bone's local -X
// axis (> 0: the tip goes toward the palm, local -Y); spread (first segments only) about the
// parent's +Y axis, toward the little finger (local +X for the right hand, -X for the left).
// Result = spread * flexion (flexion first).
Quat finger_bone_rotation(components::HandSide side, double spread_rad, double flexion_rad);

// Keyboard-frame millimetres (x along the keys, y into the keys, z up) to glTF metres in the
// hand bone's frame: (x, z, -y) / 1000.
DVec3 keyboard_to_gltf(const std::array<double, 3>& mm);

// Adds the hand bone "hand" + suffix (under `parent`, or a scene root when parent < 0, with the
// given local transform), its finger bones "thumb_1" + suffix .. "little_3" + suffix at the rest
// pose, tip nodes "thumb_tip" + suffix .., and appends the skinned flesh to `mesh` (vertices
// placed at the bones' current world transforms). Each new joint is appended to `joints`;
// JOINTS_0 indexes that list.
HandBones add_hand(ModelBuilder& builder, MeshData& mesh, std::vector<int>& joints,
                   const HandRig& rig, const std::string& suffix, int parent, DVec3 translation,
                   Quat rotation);

// A hand on its own: scene roots "hand_r" (or "hand_l"; the hand bone at the origin) and the
// skinned mesh node "hand_r_mesh" ("hand_l_mesh").
tinygltf::Model build_hand(const HandRig& rig);

}  // namespace tutti::content_generator
