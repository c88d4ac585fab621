// SPDX-License-Identifier: MIT
// World matrices below one node (model/world_matrices_below.hpp) are exactly what a whole pass
// gives when only that node's subtree changed, and nothing outside it is touched.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <tutti/model/model_asset.hpp>
#include <tutti/model/world_matrices_below.hpp>

namespace tutti::model {
namespace {

bool same_bytes(const glm::mat4& a, const glm::mat4& b) {
  return std::memcmp(&a, &b, sizeof(glm::mat4)) == 0;
}

TEST(WorldMatricesBelow, AnArmTurnedGivesWhatAWholePassGives) {
  const std::filesystem::path file =
      std::filesystem::path(TUTTI_MODEL_TEST_ASSET_DIR) / "performer.glb";
  auto loaded = load_model(file);
  ASSERT_TRUE(loaded.ok()) << loaded.error().message;
  const ModelAsset& asset = *loaded;
  const int arm = asset.find_node("upper_arm_r");
  ASSERT_GE(arm, 0);
  ModelPose pose = rest_pose(asset);
  const glm::mat4 root = glm::translate(glm::mat4(1.0f), glm::vec3(0.3f, 0.0f, -1.2f));
  std::vector<glm::mat4> world(asset.nodes.size());
  compute_world_matrices(asset, pose, root, world);
  const std::vector<glm::mat4> before = world;

  pose.local[static_cast<std::size_t>(arm)].rotation =
      glm::angleAxis(0.7f, glm::normalize(glm::vec3(0.3f, 1.0f, -0.2f)));
  update_world_matrices_below(asset, pose, root, arm, world);
  std::vector<glm::mat4> whole(asset.nodes.size());
  compute_world_matrices(asset, pose, root, whole);

  int below = 0;
  for (std::size_t i = 0; i < world.size(); ++i) {
    EXPECT_TRUE(same_bytes(world[i], whole[i])) << asset.nodes[i].name;
    if (!same_bytes(world[i], before[i])) ++below;
  }
  // The arm, forearm, hand, grip and fingers moved; the rest of the body did not.
  EXPECT_GT(below, 15);
  EXPECT_LT(below, static_cast<int>(asset.nodes.size()) / 2);
  const int head = asset.find_node("head");
  ASSERT_GE(head, 0);
  EXPECT_TRUE(same_bytes(world[static_cast<std::size_t>(head)], before[static_cast<std::size_t>(head)]));
}

TEST(WorldMatricesBelow, ANodeOutsideTheModelDoesNothing) {
  const std::filesystem::path file =
      std::filesystem::path(TUTTI_MODEL_TEST_ASSET_DIR) / "performer.glb";
  auto loaded = load_model(file);
  ASSERT_TRUE(loaded.ok()) << loaded.error().message;
  const ModelPose pose = rest_pose(*loaded);
  std::vector<glm::mat4> world(loaded->nodes.size(), glm::mat4(2.0f));
  for (const int node : {-1, static_cast<int>(loaded->nodes.size()), 1 << 30}) {
    update_world_matrices_below(*loaded, pose, glm::mat4(1.0f), node, world);
  }
  for (const glm::mat4& m : world) EXPECT_EQ(m, glm::mat4(2.0f));
}

}  // namespace
}  // namespace tutti::model
