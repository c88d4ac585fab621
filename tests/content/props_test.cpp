// SPDX-License-Identifier: MIT
#include <tutti/generator/props.hpp>

#include <gtest/gtest.h>

#include <cmath>

#include "gltf_test_support.hpp"

namespace tutti::test {
namespace {

class Props : public ::testing::Test {
 protected:
  void SetUp() override { assets_ = std::make_unique<GeneratedAssets>("props"); }
  std::unique_ptr<GeneratedAssets> assets_;
};

int mesh_of(const tinygltf::Model& model, const std::string& node) {
  const int index = find_node(model, node);
  EXPECT_GE(index, 0) << node;
  return index < 0 ? -1 : model.nodes[static_cast<std::size_t>(index)].mesh;
}

TEST_F(Props, ChairHasItsNamedPartsAtRealHeights) {
  const tinygltf::Model model = load_glb(assets_->dir() / "chair.glb");
  const int chair = find_node(model, "chair");
  ASSERT_GE(chair, 0);
  EXPECT_EQ(model.scenes.at(0).nodes, std::vector<int>{chair});
  for (const char* part : {"seat", "leg_front_left", "leg_front_right", "leg_back_left",
                           "leg_back_right", "backrest"}) {
    const int node = find_node(model, part);
    ASSERT_GE(node, 0) << part;
    EXPECT_EQ(parent_of(model, node), chair) << part;
    EXPECT_GE(model.nodes[static_cast<std::size_t>(node)].mesh, 0) << part;
  }
  const auto& seat = position_accessor(model, mesh_of(model, "seat"));
  EXPECT_NEAR(seat.maxValues[kY], 0.46, 1e-6);  // seat top above the floor
  EXPECT_NEAR(mesh_extent(model, mesh_of(model, "seat"), kX), 0.45, 1e-6);
  // The legs stand on the floor and reach the seat; front legs at +Z, left legs at -X.
  const int leg = mesh_of(model, "leg_front_left");
  EXPECT_EQ(mesh_of(model, "leg_back_right"), leg);
  EXPECT_NEAR(position_accessor(model, leg).minValues[kY], 0.0, 1e-9);
  EXPECT_NEAR(position_accessor(model, leg).maxValues[kY], seat.minValues[kY], 1e-6);
  EXPECT_GT(world_translation(model, find_node(model, "leg_front_left"), kZ), 0.0);
  EXPECT_LT(world_translation(model, find_node(model, "leg_front_left"), kX), 0.0);
  // The backrest is behind (-Z) and above the seat.
  const auto& backrest = position_accessor(model, mesh_of(model, "backrest"));
  EXPECT_LT(backrest.maxValues[kZ], 0.0);
  EXPECT_GT(backrest.maxValues[kY], 0.8);
  expect_valid_buffers(model);
}

TEST_F(Props, MusicStandHasBaseShaftAndALeaningDesk) {
  const tinygltf::Model model = load_glb(assets_->dir() / "music_stand.glb");
  const int stand = find_node(model, "music_stand");
  ASSERT_GE(stand, 0);
  EXPECT_EQ(model.scenes.at(0).nodes, std::vector<int>{stand});
  for (const char* part : {"base", "shaft", "desk"}) {
    const int node = find_node(model, part);
    ASSERT_GE(node, 0) << part;
    EXPECT_EQ(parent_of(model, node), stand) << part;
  }
  EXPECT_NEAR(position_accessor(model, mesh_of(model, "base")).minValues[kY], 0.0, 1e-9);
  EXPECT_NEAR(position_accessor(model, mesh_of(model, "shaft")).maxValues[kY], 1.0, 1e-6);
  const auto& desk = model.nodes[static_cast<std::size_t>(find_node(model, "desk"))];
  ASSERT_EQ(desk.translation.size(), 3u);
  EXPECT_NEAR(desk.translation[1], 1.0, 1e-9);  // hinged at the top of the shaft
  ASSERT_EQ(desk.rotation.size(), 4u);
  // A unit quaternion about X; the desk's top leans away from the reader (toward -Z).
  EXPECT_NEAR(desk.rotation[0] * desk.rotation[0] + desk.rotation[3] * desk.rotation[3], 1.0,
              1e-12);
  const double angle = 2.0 * std::atan2(desk.rotation[0], desk.rotation[3]);
  EXPECT_NEAR(angle * 180.0 / 3.14159265358979, -20.0, 1e-9);
  const double top_y = position_accessor(model, mesh_of(model, "desk")).maxValues[kY];
  EXPECT_NEAR(top_y, 0.33, 1e-6);
  EXPECT_LT(top_y * std::sin(angle), 0.0);  // z of the desk's top after the rotation
  EXPECT_NEAR(mesh_extent(model, mesh_of(model, "desk"), kX), 0.51, 1e-6);
  expect_valid_buffers(model);
}

}  // namespace
}  // namespace tutti::test
