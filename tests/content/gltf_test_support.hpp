// SPDX-License-Identifier: MIT
#pragma once
// Shared by the content generator tests: generate into a temporary folder, load a .glb back
// with tinygltf, find nodes and meshes by name, check a model's buffers and accessors.

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <set>
#include <string>

#include <tutti/generator/generate.hpp>
#include "testdata.hpp"

namespace tutti::test {

// Indices of a position's axes.
inline constexpr int kX = 0;
inline constexpr int kY = 1;
inline constexpr int kZ = 2;

inline std::filesystem::path content_dir() { return TUTTI_CONTENT_DIR; }

// Generates every asset into a fresh temporary folder (removed by the destructor).
class GeneratedAssets {
 public:
  explicit GeneratedAssets(const std::string& name) : dir_(unique_temp_path(name)) {
    std::filesystem::remove_all(dir_);
    const Status status = content_generator::generate_assets(content_dir(), dir_);
    EXPECT_TRUE(status.ok()) << (status.ok() ? "" : status.error().message);
  }
  ~GeneratedAssets() {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
  GeneratedAssets(const GeneratedAssets&) = delete;
  GeneratedAssets& operator=(const GeneratedAssets&) = delete;
  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path dir_;
};

inline tinygltf::Model load_glb(const std::filesystem::path& path) {
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string error;
  std::string warning;
  const bool ok = loader.LoadBinaryFromFile(&model, &error, &warning, path.string());
  EXPECT_TRUE(ok) << path << ": " << error;
  EXPECT_EQ(warning, "") << path;
  return model;
}

inline int find_node(const tinygltf::Model& model, const std::string& name) {
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    if (model.nodes[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

inline int parent_of(const tinygltf::Model& model, int node) {
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    for (const int child : model.nodes[i].children) {
      if (child == node) return static_cast<int>(i);
    }
  }
  return -1;
}

inline double translation(const tinygltf::Model& model, int node, int axis) {
  const auto& t = model.nodes[static_cast<std::size_t>(node)].translation;
  return t.empty() ? 0.0 : t[static_cast<std::size_t>(axis)];
}

// Translation relative to the scene root, for chains of nodes without rotation or scale.
inline double world_translation(const tinygltf::Model& model, int node, int axis) {
  double sum = 0.0;
  for (int n = node; n >= 0; n = parent_of(model, n)) {
    EXPECT_TRUE(model.nodes[static_cast<std::size_t>(n)].rotation.empty());
    EXPECT_TRUE(model.nodes[static_cast<std::size_t>(n)].scale.empty());
    sum += translation(model, n, axis);
  }
  return sum;
}

inline const tinygltf::Accessor& position_accessor(const tinygltf::Model& model, int mesh) {
  const auto& primitive = model.meshes.at(static_cast<std::size_t>(mesh)).primitives.at(0);
  return model.accessors.at(static_cast<std::size_t>(primitive.attributes.at("POSITION")));
}

// Size of a mesh along an axis, metres, from its POSITION min/max.
inline double mesh_extent(const tinygltf::Model& model, int mesh, int axis) {
  const auto& accessor = position_accessor(model, mesh);
  return accessor.maxValues.at(static_cast<std::size_t>(axis)) -
         accessor.minValues.at(static_cast<std::size_t>(axis));
}

// Every accessor lies inside its buffer view and every view inside the (single) buffer;
// views are 4-byte aligned and tightly packed; POSITION has min/max that bound the data;
// triangles wind counter-clockwise around their flat normals.
inline void expect_valid_buffers(const tinygltf::Model& model) {
  EXPECT_EQ(model.asset.version, "2.0");
  EXPECT_EQ(model.asset.generator, "tutti");
  // Nodes form a tree: unique names, at most one parent, the scene's roots have none, and
  // every mesh and material index is in range.
  std::set<std::string> names;
  std::vector<int> parents(model.nodes.size(), 0);
  for (const auto& node : model.nodes) {
    EXPECT_TRUE(names.insert(node.name).second) << "duplicate node name " << node.name;
    EXPECT_LT(node.mesh, static_cast<int>(model.meshes.size())) << node.name;
    for (const int child : node.children) {
      ASSERT_GE(child, 0);
      ASSERT_LT(child, static_cast<int>(model.nodes.size()));
      ++parents[static_cast<std::size_t>(child)];
    }
  }
  for (const int count : parents) EXPECT_LE(count, 1);
  ASSERT_EQ(model.scenes.size(), 1u);
  EXPECT_EQ(model.defaultScene, 0);
  for (const int root : model.scenes[0].nodes) {
    EXPECT_EQ(parents.at(static_cast<std::size_t>(root)), 0);
  }
  for (const auto& mesh : model.meshes) {
    for (const auto& primitive : mesh.primitives) {
      EXPECT_LT(primitive.material, static_cast<int>(model.materials.size())) << mesh.name;
    }
  }
  ASSERT_EQ(model.buffers.size(), 1u);
  const auto& buffer = model.buffers[0];
  EXPECT_TRUE(buffer.uri.empty());
  EXPECT_EQ(buffer.data.size() % 4, 0u);
  for (const auto& view : model.bufferViews) {
    EXPECT_EQ(view.buffer, 0);
    EXPECT_EQ(view.byteOffset % 4, 0u);
    EXPECT_EQ(view.byteStride, 0u);  // tightly packed
    EXPECT_LE(view.byteOffset + view.byteLength, buffer.data.size());
  }
  for (const auto& accessor : model.accessors) {
    ASSERT_GE(accessor.bufferView, 0);
    const auto& view = model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
    const int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(accessor.type));
    const int size =
        tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(accessor.componentType));
    EXPECT_LE(accessor.byteOffset + accessor.count * static_cast<std::size_t>(components * size),
              view.byteLength);
  }
  for (const auto& mesh : model.meshes) {
    ASSERT_EQ(mesh.primitives.size(), 1u) << mesh.name;
    const auto& primitive = mesh.primitives[0];
    EXPECT_EQ(primitive.mode, TINYGLTF_MODE_TRIANGLES);
    EXPECT_GE(primitive.material, 0) << mesh.name;
    const auto& positions =
        model.accessors.at(static_cast<std::size_t>(primitive.attributes.at("POSITION")));
    const auto& normals =
        model.accessors.at(static_cast<std::size_t>(primitive.attributes.at("NORMAL")));
    const auto& indices = model.accessors.at(static_cast<std::size_t>(primitive.indices));
    ASSERT_EQ(positions.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
    ASSERT_EQ(positions.type, TINYGLTF_TYPE_VEC3);
    ASSERT_EQ(normals.count, positions.count);
    ASSERT_EQ(indices.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    ASSERT_EQ(indices.count % 3, 0u);
    ASSERT_EQ(positions.minValues.size(), 3u) << mesh.name;
    ASSERT_EQ(positions.maxValues.size(), 3u) << mesh.name;
    auto data = [&](const tinygltf::Accessor& accessor) {
      const auto& view = model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
      return buffer.data.data() + view.byteOffset + accessor.byteOffset;
    };
    auto vec3 = [&](const tinygltf::Accessor& accessor, std::size_t i) {
      std::array<float, 3> v{};
      std::memcpy(v.data(), data(accessor) + i * 12, 12);
      return v;
    };
    std::array<double, 3> min{1e9, 1e9, 1e9};
    std::array<double, 3> max{-1e9, -1e9, -1e9};
    for (std::size_t i = 0; i < positions.count; ++i) {
      const auto p = vec3(positions, i);
      for (std::size_t a = 0; a < 3; ++a) {
        min[a] = std::min(min[a], static_cast<double>(p[a]));
        max[a] = std::max(max[a], static_cast<double>(p[a]));
      }
    }
    for (std::size_t a = 0; a < 3; ++a) {
      EXPECT_EQ(positions.minValues[a], min[a]) << mesh.name << " axis " << a;
      EXPECT_EQ(positions.maxValues[a], max[a]) << mesh.name << " axis " << a;
    }
    for (std::size_t t = 0; t < indices.count; t += 3) {
      std::array<std::uint16_t, 3> tri{};
      std::memcpy(tri.data(), data(indices) + t * 2, 6);
      for (const auto index : tri) ASSERT_LT(index, positions.count) << mesh.name;
      const auto a = vec3(positions, tri[0]);
      const auto b = vec3(positions, tri[1]);
      const auto c = vec3(positions, tri[2]);
      const std::array<double, 3> u{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
      const std::array<double, 3> v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
      const std::array<double, 3> cross{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                                        u[0] * v[1] - u[1] * v[0]};
      const auto n = vec3(normals, tri[0]);
      EXPECT_GT(cross[0] * n[0] + cross[1] * n[1] + cross[2] * n[2], 0.0)
          << mesh.name << " triangle " << t / 3 << " winds against its normal";
    }
  }
}

}  // namespace tutti::test
