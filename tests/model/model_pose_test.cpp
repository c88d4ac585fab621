// SPDX-License-Identifier: MIT
// Posing: rest pose, world matrices, joint matrices, and deform_vertex against hand-computed
// skinning and morph maths.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>

#include "gltf_test_builder.hpp"
#include "glm_expect.hpp"
#include <tutti/model/model_asset.hpp>

namespace tutti::model {
namespace {

using test::expect_near;
using test::GltfBuilder;

ModelAsset load_or_fail(const GltfBuilder& b, const std::string& name) {
  auto asset = test::load_bytes(b.glb(), name);
  EXPECT_TRUE(asset.ok()) << (asset.ok() ? "" : asset.error().message);
  return asset.ok() ? std::move(*asset) : ModelAsset{};
}

TEST(ModelPose, ToMatrixIsTranslationRotationScale) {
  NodeTransform t;
  t.translation = {1, 2, 3};
  t.rotation = glm::angleAxis(0.7f, glm::normalize(glm::vec3(1, 2, -1)));
  t.scale = {2, 3, 0.5f};
  const glm::mat4 expected = glm::translate(glm::mat4(1.0f), t.translation) *
                             glm::mat4_cast(t.rotation) * glm::scale(glm::mat4(1.0f), t.scale);
  expect_near(to_matrix(t), expected);
}

TEST(ModelPose, RestPoseCopiesNodesAndDefaultWeights) {
  GltfBuilder b = test::two_bone_strip();
  const ModelAsset asset = load_or_fail(b, "strip.glb");
  const ModelPose pose = rest_pose(asset);
  ASSERT_EQ(pose.local.size(), 3u);
  expect_near(pose.local[1].translation, {0, 1, 0});
  EXPECT_TRUE(pose.morph_weights.empty());
  ASSERT_EQ(pose.first_morph_weight.size(), 1u);
}

// Rotating tip_joint 90 degrees about +Z: a vertex v skinned fully to it goes to
// T(0,1,0) * Rz(90) * T(0,-1,0) * v, so the tip (0.5, 2, 0) -> (-1, 1.5, 0); the middle row,
// half on each joint, averages its two images: (0.5, 1, 0) -> ((0.5, 1) + (0, 1.5)) / 2.
TEST(ModelPose, TwoBoneStripDeformsAsHandComputed) {
  const ModelAsset asset = load_or_fail(test::two_bone_strip(), "strip.glb");
  const int tip = asset.find_node("tip_joint");
  const int strip = asset.find_node("strip");
  ASSERT_GE(tip, 0);
  ASSERT_GE(strip, 0);
  ModelPose pose = rest_pose(asset);
  pose.local[static_cast<std::size_t>(tip)].rotation =
      glm::angleAxis(std::numbers::pi_v<float> / 2, glm::vec3(0, 0, 1));
  std::vector<glm::mat4> world(asset.nodes.size());
  compute_world_matrices(asset, pose, glm::mat4(1.0f), world);

  // At rest the strip is where the file puts it (the mesh node's own (5,0,0) is ignored).
  const ModelPose rest = rest_pose(asset);
  std::vector<glm::mat4> rest_world(asset.nodes.size());
  compute_world_matrices(asset, rest, glm::mat4(1.0f), rest_world);
  expect_near(deform_vertex(asset, rest, rest_world, strip, 0, 5).position, {0.5f, 2, 0});

  expect_near(deform_vertex(asset, pose, world, strip, 0, 5).position, {-1, 1.5f, 0});
  expect_near(deform_vertex(asset, pose, world, strip, 0, 4).position, {-1, 0.5f, 0});
  expect_near(deform_vertex(asset, pose, world, strip, 0, 3).position, {0.25f, 1.25f, 0});
  expect_near(deform_vertex(asset, pose, world, strip, 0, 1).position, {0.5f, 0, 0});
  // Normals (0,0,1) stay: the rotation is about Z.
  expect_near(deform_vertex(asset, pose, world, strip, 0, 5).normal, {0, 0, 1});

  // A model placed in the world moves every skinned vertex with it.
  const glm::mat4 placed = glm::translate(glm::mat4(1.0f), glm::vec3(10, 0, 0));
  compute_world_matrices(asset, pose, placed, world);
  expect_near(deform_vertex(asset, pose, world, strip, 0, 5).position, {9, 1.5f, 0});
}

TEST(ModelPose, DeformVertexAgreesWithJointMatrices) {
  const ModelAsset asset = load_or_fail(test::two_bone_strip(), "strip.glb");
  ModelPose pose = rest_pose(asset);
  pose.local[0].rotation = glm::angleAxis(0.3f, glm::vec3(1, 0, 0));
  pose.local[0].translation = {0.1f, 0.2f, 0.3f};
  pose.local[1].rotation = glm::angleAxis(-1.1f, glm::normalize(glm::vec3(0, 1, 1)));
  pose.local[1].scale = {1.5f, 1.5f, 1.5f};
  std::vector<glm::mat4> world(asset.nodes.size());
  compute_world_matrices(asset, pose, glm::mat4(1.0f), world);

  // world = parent chain * local
  expect_near(world[1], to_matrix(pose.local[0]) * to_matrix(pose.local[1]));

  const Skin& skin = asset.skins.at(0);
  std::vector<glm::mat4> joints(skin.joints.size());
  compute_joint_matrices(asset, 0, world, joints);
  for (std::size_t j = 0; j < joints.size(); ++j) {
    expect_near(joints[j], world[static_cast<std::size_t>(skin.joints[j])] * skin.inverse_bind[j]);
  }
  const Primitive& p = asset.meshes[0].primitives[0];
  for (std::uint32_t v = 0; v < p.vertex_count; ++v) {
    const Vertex& vertex = asset.vertices[p.first_vertex + v];
    glm::mat4 m(0.0f);
    for (int i = 0; i < 4; ++i) m += vertex.weights[i] * joints[vertex.joints[i]];
    const glm::vec3 expected = glm::vec3(m * glm::vec4(vertex.position, 1.0f));
    const SkinnedVertex got = deform_vertex(asset, pose, world, asset.find_node("strip"), 0, v);
    expect_near(got.position, expected);
    EXPECT_NEAR(glm::length(got.normal), 1.0f, 1e-5f);
  }
}

// One triangle, two targets: target 0 lifts vertex 0 by (0,0,1), target 1 shifts every vertex by
// (1,0,0) and tilts its normal.
GltfBuilder morph_triangle(bool names) {
  GltfBuilder b;
  const int position = b.add_vec3s({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  const int normal = b.add_vec3s({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
  const int lift = b.add_vec3s({{0, 0, 1}, {0, 0, 0}, {0, 0, 0}});
  const int shift = b.add_vec3s({{1, 0, 0}, {1, 0, 0}, {1, 0, 0}});
  const int tilt = b.add_vec3s({{0, 1, 0}, {0, 1, 0}, {0, 1, 0}});
  nlohmann::json mesh = {
      {"name", "face"},
      {"weights", {0.25, 0.0}},
      {"primitives",
       {{{"attributes", {{"POSITION", position}, {"NORMAL", normal}}},
         {"targets", {{{"POSITION", lift}}, {{"POSITION", shift}, {"NORMAL", tilt}}}}}}}};
  if (names) mesh["extras"] = {{"targetNames", {"lift", "shift"}}};
  b.add_mesh(mesh);
  b.add_node({{"name", "face"}, {"mesh", 0}, {"translation", {0, 0, 2}}});
  return b;
}

TEST(ModelPose, MorphWeightsMoveVerticesByWeightTimesDelta) {
  const ModelAsset asset = load_or_fail(morph_triangle(true), "face.gltf");
  ASSERT_EQ(asset.meshes.size(), 1u);
  EXPECT_EQ(asset.meshes[0].target_names, (std::vector<std::string>{"lift", "shift"}));
  EXPECT_EQ(asset.meshes[0].default_weights, (std::vector<float>{0.25f, 0.0f}));
  EXPECT_EQ(asset.morph_weight_count(), 2u);
  ModelPose pose = rest_pose(asset);
  ASSERT_EQ(pose.morph_weights, (std::vector<float>{0.25f, 0.0f}));
  std::vector<glm::mat4> world(asset.nodes.size());
  compute_world_matrices(asset, pose, glm::mat4(1.0f), world);
  // Default weight 0.25 on "lift"; the node is 2 m up Z.
  expect_near(deform_vertex(asset, pose, world, 0, 0, 0).position, {0, 0, 2.25f});

  pose.morph_weights = {0.5f, 0.75f};
  expect_near(deform_vertex(asset, pose, world, 0, 0, 0).position, {0.75f, 0, 2.5f});
  expect_near(deform_vertex(asset, pose, world, 0, 0, 1).position, {1.75f, 0, 2});
  expect_near(deform_vertex(asset, pose, world, 0, 0, 2).position, {0.75f, 1, 2});
  expect_near(deform_vertex(asset, pose, world, 0, 0, 2).normal,
              glm::normalize(glm::vec3(0, 0.75f, 1)));
}

TEST(ModelPose, MorphTargetsWithoutNamesAreNumbered) {
  const ModelAsset asset = load_or_fail(morph_triangle(false), "face.glb");
  EXPECT_EQ(asset.meshes[0].target_names, (std::vector<std::string>{"target_0", "target_1"}));
}

}  // namespace
}  // namespace tutti::model
