// SPDX-License-Identifier: MIT
#include <tutti/generator/hand_asset.hpp>

#include <algorithm>

namespace tutti::content_generator {
namespace {

Vec3 to_vec3(const DVec3& v) {
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

tinygltf::Value limit_extras(const JointLimits& limits) {
  tinygltf::Value::Object extras;
  extras["flexion_min_deg"] = tinygltf::Value(limits.flexion_min_deg);
  extras["flexion_max_deg"] = tinygltf::Value(limits.flexion_max_deg);
  if (limits.has_spread) {
    extras["spread_min_deg"] = tinygltf::Value(limits.spread_min_deg);
    extras["spread_max_deg"] = tinygltf::Value(limits.spread_max_deg);
  }
  return tinygltf::Value(std::move(extras));
}

// Adds `part` (built in the frame of `bone`) to `mesh`, placed at the bone's rest transform and
// weighted to joint `joint`.
void add_part(ModelBuilder& builder, MeshData& mesh, const MeshData& part, int bone,
              std::uint16_t joint) {
  const std::size_t first = mesh.vertex_count();
  const auto offset = static_cast<std::uint16_t>(first);
  mesh.positions.insert(mesh.positions.end(), part.positions.begin(), part.positions.end());
  mesh.normals.insert(mesh.normals.end(), part.normals.begin(), part.normals.end());
  for (const std::uint16_t i : part.indices) {
    mesh.indices.push_back(static_cast<std::uint16_t>(i + offset));
  }
  transform_vertices(mesh, first, builder.world_matrix(bone));
  weight_vertices(mesh, first, joint);
}

}  // namespace

Quat finger_bone_rotation(components::HandSide side, double spread_rad, double flexion_rad) {
  const double mirror = side == components::HandSide::left ? -1.0 : 1.0;
  // Spread > 0 turns the finger (local -Z) toward +X on the right hand: a negative turn about +Y.
  return quat_multiply(rotation_about({0, 1, 0}, -mirror * spread_rad),
                       rotation_about({1, 0, 0}, -flexion_rad));
}

DVec3 keyboard_to_gltf(const std::array<double, 3>& mm) {
  return {mm[0] / 1000.0, mm[2] / 1000.0, -mm[1] / 1000.0};
}

HandBones add_hand(ModelBuilder& builder, MeshData& mesh, std::vector<int>& joints,
                   const HandRig& rig, const std::string& suffix, int parent, DVec3 translation,
                   Quat rotation) {
  HandBones bones;
  bones.root = builder.add_node("hand" + suffix, -1, translation, rotation);
  if (parent >= 0) {
    builder.add_child(parent, bones.root);
  } else {
    builder.add_root(bones.root);
  }
  auto joint_of = [&](int node) {
    joints.push_back(node);
    return static_cast<std::uint16_t>(joints.size() - 1);
  };
  const std::uint16_t hand_joint = joint_of(bones.root);
  for (int f = 1; f <= 5; ++f) {
    const FingerRig& finger = rig.fingers[static_cast<std::size_t>(f - 1)];
    int at = bones.root;
    DVec3 offset = keyboard_to_gltf(finger.root_mm);
    for (int s = 1; s <= 3; ++s) {
      const auto i = static_cast<std::size_t>(s - 1);
      const int bone =
          builder.add_node(finger_bone_name(f, s) + suffix, -1, offset,
                           finger_bone_rotation(rig.side, 0.0, finger.rest_angles_rad[i]));
      builder.set_extras(
          bone, limit_extras(rig.data.limits[static_cast<std::size_t>(3 * (f - 1) + (s - 1))]));
      builder.add_child(at, bone);
      bones.segments[static_cast<std::size_t>(f - 1)][i] = bone;
      at = bone;
      offset = {0.0, 0.0, -finger.phalanges_mm[i] / 1000.0};
    }
    const std::string first = finger_bone_name(f, 1);
    const std::string name = first.substr(0, first.size() - 2);  // "index_1" -> "index"
    bones.tips[static_cast<std::size_t>(f - 1)] =
        builder.add_node(name + "_tip" + suffix, -1, offset);
    builder.add_child(at, bones.tips[static_cast<std::size_t>(f - 1)]);
  }

  // Flesh. Fingers: a capsule per segment tapering from the knuckle to the tip.
  const HandShape& shape = rig.data.shape;
  for (int f = 1; f <= 5; ++f) {
    const auto fi = static_cast<std::size_t>(f - 1);
    const FingerRig& finger = rig.fingers[fi];
    const double base = f == 1   ? shape.thumb_radius_mm
                        : f == 5 ? shape.little_finger_radius_mm
                                 : shape.finger_radius_mm;
    const double total = finger.phalanges_mm[0] + finger.phalanges_mm[1] + finger.phalanges_mm[2];
    double along = 0.0;
    for (std::size_t s = 0; s < 3; ++s) {
      const double length = finger.phalanges_mm[s];
      auto radius = [&](double at_mm) {
        return base * (1.0 - (1.0 - shape.tip_radius_ratio) * at_mm / total);
      };
      // The last segment's capsule ends its rounded cap at the tip: shorten it by its radius.
      const double end = s == 2 ? length - radius(along + length) : length;
      MeshData part;
      add_capsule(part, {0, 0, 0}, {0, 0, -m(end)}, m(radius(along)), m(radius(along + length)),
                  12);
      const int bone = bones.segments[fi][s];
      joints.push_back(bone);
      add_part(builder, mesh, part, bone, static_cast<std::uint16_t>(joints.size() - 1));
      along += length;
    }
  }
  // Palm: knuckle bar, the palm's body back to the wrist, the thumb's ball.
  MeshData palm;
  const auto& index = rig.fingers[1].root_mm;
  const auto& little = rig.fingers[4].root_mm;
  const auto& thumb = rig.fingers[0].root_mm;
  const DVec3 index_at = keyboard_to_gltf(index);
  const DVec3 little_at = keyboard_to_gltf(little);
  add_capsule(palm, to_vec3(index_at), to_vec3(little_at), m(shape.finger_radius_mm + 1.5),
              m(shape.little_finger_radius_mm + 1.5), 12);
  const double x_lo = std::min(index[0], little[0]) - shape.palm_margin_mm;
  const double x_hi = std::max(index[0], little[0]) + shape.palm_margin_mm;
  add_ellipsoid(
      palm, {m((x_lo + x_hi) / 2), m(-2.0), m(shape.palm_length_mm * 0.45)},
      {m((x_hi - x_lo) / 2), m(shape.palm_thickness_mm / 2), m(shape.palm_length_mm * 0.6)}, 20);
  const DVec3 thumb_at = keyboard_to_gltf(thumb);
  const double heel_x = index[0] + (thumb[0] - index[0]) * 0.4;
  add_capsule(palm, to_vec3(thumb_at), {m(heel_x), m(-4.0), m(shape.palm_length_mm * 0.7)},
              m(shape.thumb_radius_mm * 1.1), m(shape.thumb_radius_mm * 1.6), 12);
  add_part(builder, mesh, palm, bones.root, hand_joint);
  return bones;
}

tinygltf::Model build_hand(const HandRig& rig) {
  ModelBuilder builder;
  const int skin = builder.add_material({"skin", {0.72, 0.45, 0.33, 1.0}, 0.0, 0.55});
  const std::string suffix = rig.side == components::HandSide::left ? "_l" : "_r";
  MeshData mesh;
  std::vector<int> joints;
  const HandBones bones = add_hand(builder, mesh, joints, rig, suffix, -1, {0, 0, 0}, {0, 0, 0, 1});
  const int skin_index = builder.add_skin("hand" + suffix, joints, bones.root);
  const int node =
      builder.add_node("hand" + suffix + "_mesh", builder.add_mesh("hand" + suffix, mesh, skin));
  builder.set_skin(node, skin_index);
  builder.add_root(node);
  return builder.finish();
}

}  // namespace tutti::content_generator
