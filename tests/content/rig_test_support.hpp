// SPDX-License-Identifier: MIT
#pragma once
// Shared by the skinned-asset tests: node matrices from a loaded glTF, typed accessor reads, and
// the checks every skin must pass (joint and matrix counts, IBM x bind pose = identity, weights).

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "gltf_test_support.hpp"

namespace tutti::test {

using Matrix = std::array<double, 16>;  // column-major

inline Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix m{};
  for (std::size_t c = 0; c < 4; ++c) {
    for (std::size_t r = 0; r < 4; ++r) {
      for (std::size_t k = 0; k < 4; ++k) m[4 * c + r] += a[4 * k + r] * b[4 * c + k];
    }
  }
  return m;
}

// T * R * S of one node, written out from the quaternion (independent of the generator's code).
inline Matrix local_matrix(const tinygltf::Node& node) {
  EXPECT_TRUE(node.matrix.empty()) << node.name;
  const auto& t = node.translation;
  const auto& q = node.rotation;
  const auto& s = node.scale;
  const double x = q.empty() ? 0 : q[0], y = q.empty() ? 0 : q[1], z = q.empty() ? 0 : q[2],
               w = q.empty() ? 1 : q[3];
  const double sx = s.empty() ? 1 : s[0], sy = s.empty() ? 1 : s[1], sz = s.empty() ? 1 : s[2];
  Matrix m{1 - 2 * (y * y + z * z), 2 * (x * y + z * w),     2 * (x * z - y * w),     0,
           2 * (x * y - z * w),     1 - 2 * (x * x + z * z), 2 * (y * z + x * w),     0,
           2 * (x * z + y * w),     2 * (y * z - x * w),     1 - 2 * (x * x + y * y), 0,
           t.empty() ? 0 : t[0],    t.empty() ? 0 : t[1],    t.empty() ? 0 : t[2],    1};
  for (std::size_t r = 0; r < 3; ++r) {
    m[r] *= sx;
    m[4 + r] *= sy;
    m[8 + r] *= sz;
  }
  return m;
}

inline Matrix world_matrix(const tinygltf::Model& model, int node) {
  Matrix world = local_matrix(model.nodes.at(static_cast<std::size_t>(node)));
  for (int p = parent_of(model, node); p >= 0; p = parent_of(model, p)) {
    world = multiply(local_matrix(model.nodes[static_cast<std::size_t>(p)]), world);
  }
  return world;
}

inline std::array<double, 3> apply(const Matrix& m, std::array<double, 3> p) {
  return {m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12],
          m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13],
          m[2] * p[0] + m[6] * p[1] + m[10] * p[2] + m[14]};
}

inline std::array<double, 3> world_origin(const tinygltf::Model& model, int node) {
  return apply(world_matrix(model, node), {0, 0, 0});
}

template <typename T>
std::vector<T> read_accessor(const tinygltf::Model& model, int index) {
  const auto& accessor = model.accessors.at(static_cast<std::size_t>(index));
  const auto& view = model.bufferViews.at(static_cast<std::size_t>(accessor.bufferView));
  const std::size_t components = static_cast<std::size_t>(
      tinygltf::GetNumComponentsInType(static_cast<uint32_t>(accessor.type)));
  std::vector<T> values(accessor.count * components);
  std::memcpy(values.data(), model.buffers[0].data.data() + view.byteOffset + accessor.byteOffset,
              values.size() * sizeof(T));
  return values;
}

// Every skin: joints = IBM count, MAT4 float IBMs with IBM[j] x world(joint j) = identity; every
// skinned primitive: JOINTS_0 unsigned short VEC4 (not normalised) in range, WEIGHTS_0 float
// VEC4 >= 0 summing to 1; a skinned mesh node is a scene root without transform.
inline void expect_valid_skins(const tinygltf::Model& model) {
  for (const auto& skin : model.skins) {
    ASSERT_GE(skin.inverseBindMatrices, 0) << skin.name;
    const auto& ibm = model.accessors[static_cast<std::size_t>(skin.inverseBindMatrices)];
    EXPECT_EQ(ibm.type, TINYGLTF_TYPE_MAT4);
    EXPECT_EQ(ibm.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
    ASSERT_EQ(ibm.count, skin.joints.size()) << skin.name;
    const auto matrices = read_accessor<float>(model, skin.inverseBindMatrices);
    for (std::size_t j = 0; j < skin.joints.size(); ++j) {
      Matrix inverse{};
      for (std::size_t k = 0; k < 16; ++k) inverse[k] = matrices[16 * j + k];
      const Matrix product = multiply(inverse, world_matrix(model, skin.joints[j]));
      for (std::size_t k = 0; k < 16; ++k) {
        EXPECT_NEAR(product[k], k % 5 == 0 ? 1.0 : 0.0, 1e-5)
            << skin.name << " joint " << model.nodes[static_cast<std::size_t>(skin.joints[j])].name;
      }
    }
  }
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    const auto& node = model.nodes[n];
    if (node.skin < 0) continue;
    ASSERT_LT(node.skin, static_cast<int>(model.skins.size()));
    EXPECT_EQ(parent_of(model, static_cast<int>(n)), -1) << node.name;
    EXPECT_TRUE(node.translation.empty() && node.rotation.empty() && node.scale.empty())
        << node.name;
    const auto& skin = model.skins[static_cast<std::size_t>(node.skin)];
    ASSERT_GE(node.mesh, 0);
    for (const auto& primitive : model.meshes[static_cast<std::size_t>(node.mesh)].primitives) {
      ASSERT_TRUE(primitive.attributes.count("JOINTS_0")) << node.name;
      ASSERT_TRUE(primitive.attributes.count("WEIGHTS_0")) << node.name;
      const auto& ja =
          model.accessors[static_cast<std::size_t>(primitive.attributes.at("JOINTS_0"))];
      const auto& wa =
          model.accessors[static_cast<std::size_t>(primitive.attributes.at("WEIGHTS_0"))];
      EXPECT_EQ(ja.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
      EXPECT_FALSE(ja.normalized);
      EXPECT_EQ(ja.type, TINYGLTF_TYPE_VEC4);
      EXPECT_EQ(wa.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
      EXPECT_EQ(wa.type, TINYGLTF_TYPE_VEC4);
      const auto& positions =
          model.accessors[static_cast<std::size_t>(primitive.attributes.at("POSITION"))];
      ASSERT_EQ(ja.count, positions.count);
      ASSERT_EQ(wa.count, positions.count);
      const auto joints = read_accessor<std::uint16_t>(model, primitive.attributes.at("JOINTS_0"));
      const auto weights = read_accessor<float>(model, primitive.attributes.at("WEIGHTS_0"));
      for (std::size_t v = 0; v < positions.count; ++v) {
        double sum = 0.0;
        for (std::size_t k = 0; k < 4; ++k) {
          ASSERT_LT(joints[4 * v + k], skin.joints.size()) << node.name << " vertex " << v;
          ASSERT_GE(weights[4 * v + k], 0.0f);
          sum += weights[4 * v + k];
        }
        ASSERT_NEAR(sum, 1.0, 1e-6) << node.name << " vertex " << v;
      }
    }
  }
}

}  // namespace tutti::test
