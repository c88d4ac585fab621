// SPDX-License-Identifier: MIT
// Detail levels and bounds (render/mesh_lod.hpp) on the generated performer and trumpet, checked
// against the files' own triangles and the CPU skinning reference (model::deform_vertex).
#include <tutti/render/mesh_lod.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <string>
#include <vector>

#include <tutti/model/model_asset.hpp>

namespace tutti::render {
namespace {

model::ModelAsset load(const std::string& name) {
  auto asset = model::load_model(std::string(TUTTI_ASSET_DIR) + "/" + name);
  EXPECT_TRUE(asset) << asset.error().message;
  return asset ? std::move(*asset) : model::ModelAsset{};
}

// Triangles as sorted index triples (a reordered, rotated triangle is the same triangle).
std::vector<std::array<std::uint32_t, 3>> triangles(const std::uint32_t* indices,
                                                    std::uint32_t count) {
  std::vector<std::array<std::uint32_t, 3>> out;
  for (std::uint32_t t = 0; t + 2 < count; t += 3) {
    std::array<std::uint32_t, 3> tri{indices[t], indices[t + 1], indices[t + 2]};
    std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
    out.push_back(tri);
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(MeshLod, LevelZeroHoldsEveryTriangleOfTheFileWithItsWinding) {
  const model::ModelAsset asset = load("performer.glb");
  const MeshLods lods = build_mesh_lods(asset);
  ASSERT_EQ(lods.first_primitive.size(), asset.meshes.size());
  for (std::size_t m = 0; m < asset.meshes.size(); ++m) {
    for (std::size_t p = 0; p < asset.meshes[m].primitives.size(); ++p) {
      const model::Primitive& primitive = asset.meshes[m].primitives[p];
      const PrimitiveLods& level = lods.primitives[lods.first_primitive[m] + p];
      ASSERT_GE(level.level_count, 1u);
      EXPECT_EQ(level.levels[0].error, 0.0f);
      EXPECT_EQ(
          triangles(lods.indices.data() + level.levels[0].first_index, level.levels[0].index_count),
          triangles(asset.indices.data() + primitive.first_index, primitive.index_count))
          << asset.meshes[m].name;
    }
  }
}

TEST(MeshLod, CoarserLevelsDropTrianglesWithinTheErrorBound) {
  const model::ModelAsset asset = load("performer.glb");
  const MeshLods lods = build_mesh_lods(asset);
  std::size_t full = 0;
  std::size_t coarsest = 0;
  for (std::size_t m = 0; m < asset.meshes.size(); ++m) {
    for (std::size_t p = 0; p < asset.meshes[m].primitives.size(); ++p) {
      const model::Primitive& primitive = asset.meshes[m].primitives[p];
      const PrimitiveLods& level = lods.primitives[lods.first_primitive[m] + p];
      full += level.levels[0].index_count / 3;
      coarsest += level.levels[level.level_count - 1].index_count / 3;
      for (std::uint32_t l = 1; l < level.level_count; ++l) {
        const LodLevel& finer = level.levels[l - 1];
        const LodLevel& coarser = level.levels[l];
        EXPECT_LE(coarser.index_count * 10, finer.index_count * 7) << asset.meshes[m].name;
        EXPECT_GE(coarser.error, finer.error);
        EXPECT_GT(coarser.error, 0.0f);
        // 2 % of the primitive's extent at most; its bounding sphere's diameter bounds that.
        EXPECT_LE(coarser.error, 0.02f * 2.0f * level.radius + 1e-6f);
        for (std::uint32_t i = 0; i < coarser.index_count; ++i) {
          ASSERT_LT(lods.indices[coarser.first_index + i], primitive.vertex_count);
        }
      }
    }
  }
  // The performer is mostly smooth tubes: far away it needs well under half its triangles.
  EXPECT_LT(coarsest * 3, full) << coarsest << " of " << full;
}

TEST(MeshLod, SameAssetGivesTheSameLevels) {
  const model::ModelAsset asset = load("trumpet.glb");
  const MeshLods a = build_mesh_lods(asset);
  const MeshLods b = build_mesh_lods(asset);
  EXPECT_EQ(a.indices, b.indices);
  ASSERT_EQ(a.primitives.size(), b.primitives.size());
  for (std::size_t i = 0; i < a.primitives.size(); ++i) {
    EXPECT_EQ(a.primitives[i].level_count, b.primitives[i].level_count);
    EXPECT_EQ(a.primitives[i].radius, b.primitives[i].radius);
  }
}

// Poses every node of the performer (arms raised, head turned, knees bent: a rotation on each
// joint) with the mouth morphs at full weight, and checks every deformed vertex lies in the
// bound the renderer culls and picks levels by.
TEST(MeshLod, SkinnedBoundHoldsEveryPosedVertex) {
  const model::ModelAsset asset = load("performer.glb");
  ASSERT_FALSE(asset.skins.empty());
  const MeshLods lods = build_mesh_lods(asset);
  model::ModelPose pose = model::rest_pose(asset);
  for (std::size_t n = 0; n < pose.local.size(); ++n) {
    const float angle = 0.35f * static_cast<float>((n % 5) + 1) * ((n % 2) ? 1.0f : -1.0f);
    pose.local[n].rotation =
        pose.local[n].rotation *
        glm::angleAxis(angle, glm::normalize(glm::vec3(0.3f, 1.0f, 0.5f * static_cast<float>(n % 3))));
  }
  std::fill(pose.morph_weights.begin(), pose.morph_weights.end(), 1.0f);
  const glm::mat4 root = glm::translate(glm::mat4(1.0f), glm::vec3(2.0f, 0.0f, -3.0f));
  std::vector<glm::mat4> world(asset.nodes.size());
  model::compute_world_matrices(asset, pose, root, world);
  std::size_t checked = 0;
  for (std::size_t n = 0; n < asset.nodes.size(); ++n) {
    const model::Node& node = asset.nodes[n];
    if (node.mesh < 0) continue;
    const model::Mesh& mesh = asset.meshes[static_cast<std::size_t>(node.mesh)];
    std::vector<glm::mat4> joints;
    if (node.skin >= 0) {
      joints.resize(asset.skins[static_cast<std::size_t>(node.skin)].joints.size());
      model::compute_joint_matrices(asset, node.skin, world, joints);
    }
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
      const PrimitiveLods& level =
          lods.primitives[lods.first_primitive[static_cast<std::size_t>(node.mesh)] + p];
      const BoundingSphere bound =
          node.skin >= 0
              ? skinned_world_bound(level, asset.skins[static_cast<std::size_t>(node.skin)], world,
                                    joints)
              : rigid_world_bound(level, world[n]);
      for (std::uint32_t v = 0; v < mesh.primitives[p].vertex_count; ++v) {
        const model::SkinnedVertex posed =
            model::deform_vertex(asset, pose, world, static_cast<int>(n), static_cast<int>(p), v);
        ASSERT_LE(glm::length(posed.position - bound.center), bound.radius * 1.0001f + 1e-5f)
            << mesh.name << " vertex " << v;
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 10000u);
}

}  // namespace
}  // namespace tutti::render
