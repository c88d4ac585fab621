// SPDX-License-Identifier: MIT
#include <tutti/generator/brass_assets.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <tutti/brass_model/instrument.hpp>
#include <tutti/content/json_reader.hpp>
#include "gltf_test_support.hpp"
#include "rig_test_support.hpp"

namespace tutti::test {
namespace {

class BrassAndStage : public ::testing::Test {
 protected:
  void SetUp() override {
    assets_ = std::make_unique<GeneratedAssets>("brass");
    auto document = content::read_json_file(content_dir() / "generator" / "dimensions.json");
    ASSERT_TRUE(document.ok()) << document.error().message;
    dimensions_ = *document;
  }
  std::unique_ptr<GeneratedAssets> assets_;
  nlohmann::json dimensions_;
};

double extra(const tinygltf::Model& model, const std::string& node, const std::string& key) {
  const int index = find_node(model, node);
  EXPECT_GE(index, 0) << node;
  if (index < 0) return -1.0;
  const auto& extras = model.nodes[static_cast<std::size_t>(index)].extras;
  EXPECT_TRUE(extras.Has(key)) << node << " extras lack " << key;
  return extras.Get(key).GetNumberAsDouble();
}

// Bounds of a node's mesh in the root's frame (translation-only chains).
std::array<double, 2> world_extent(const tinygltf::Model& model, const std::string& node,
                                   int axis) {
  const int index = find_node(model, node);
  const auto& accessor =
      position_accessor(model, model.nodes[static_cast<std::size_t>(index)].mesh);
  const double origin = world_origin(model, index)[static_cast<std::size_t>(axis)];
  return {origin + accessor.minValues[static_cast<std::size_t>(axis)],
          origin + accessor.maxValues[static_cast<std::size_t>(axis)]};
}

TEST_F(BrassAndStage, EveryAssetLoadsAndIsWellFormed) {
  for (const char* name :
       {"stage.glb", "trumpet.glb", "trombone.glb", "euphonium.glb", "tuba.glb", "horn.glb"}) {
    SCOPED_TRACE(name);
    const tinygltf::Model model = load_glb(assets_->dir() / name);
    expect_valid_buffers(model);
    ASSERT_EQ(model.scenes[0].nodes.size(), 1u);
  }
}

TEST_F(BrassAndStage, TrumpetHasItsNodesAndRealDimensions) {
  const tinygltf::Model model = load_glb(assets_->dir() / "trumpet.glb");
  const int root = find_node(model, "trumpet");
  ASSERT_GE(root, 0);
  EXPECT_EQ(model.scenes[0].nodes, std::vector<int>{root});
  for (const char* name :
       {"mouthpiece", "valve_1", "valve_2", "valve_3", "grip_left", "grip_right", "body"}) {
    const int node = find_node(model, name);
    ASSERT_GE(node, 0) << name;
    EXPECT_EQ(parent_of(model, node), root) << name;
  }
  // The mouthpiece rim is the root's origin; the instrument runs toward -Z to the bell rim.
  const auto mouthpiece = world_extent(model, "mouthpiece", 2);
  EXPECT_NEAR(mouthpiece[1], 0.0, 1e-6);
  const auto body_z = world_extent(model, "body", 2);
  EXPECT_NEAR(-body_z[0], dimensions_["trumpet"]["overall_length_mm"].get<double>() / 1000, 0.003);
  const auto body_x = world_extent(model, "body", 0);
  const auto body_y = world_extent(model, "body", 1);
  const double bell = dimensions_["trumpet"]["bell_diameter_mm"].get<double>() / 1000;
  EXPECT_GE(body_x[1] - body_x[0], bell);
  EXPECT_LT(body_x[1] - body_x[0], bell + 0.02);
  EXPECT_GE(body_y[1] - body_y[0], bell);
  // Pistons: origin at the button top, in a row along -Z (valve 1 nearest the player), each
  // with its travel from dimensions.json.
  const double travel = dimensions_["trumpet"]["piston_travel_mm"].get<double>();
  double previous_z = 1.0;
  for (const char* name : {"valve_1", "valve_2", "valve_3"}) {
    EXPECT_DOUBLE_EQ(extra(model, name, "travel_mm"), travel) << name;
    const int node = find_node(model, name);
    const auto& mesh = position_accessor(model, model.nodes[static_cast<std::size_t>(node)].mesh);
    EXPECT_NEAR(mesh.maxValues[1], 0.0, 1e-6) << name << ": the origin is the button top";
    // Pressed fully, the stem stays above the casing's bottom: it moves inside the casing.
    EXPECT_GT(world_origin(model, node)[1] - travel / 1000, body_y[0]);
    const double z = world_origin(model, node)[2];
    EXPECT_LT(z, previous_z);
    previous_z = z;
  }
}

TEST_F(BrassAndStage, TromboneSlideMaximumComesFromTheInstrumentFile) {
  const tinygltf::Model model = load_glb(assets_->dir() / "trombone.glb");
  const int root = find_node(model, "trombone");
  ASSERT_GE(root, 0);
  for (const char* name : {"bell_section", "slide", "mouthpiece", "grip_left"}) {
    ASSERT_GE(find_node(model, name), 0) << name;
    EXPECT_EQ(parent_of(model, find_node(model, name)), root) << name;
  }
  const int slide = find_node(model, "slide");
  ASSERT_GE(find_node(model, "grip_right"), 0);
  EXPECT_EQ(parent_of(model, find_node(model, "grip_right")), slide);
  auto instrument =
      brass_model::load_instrument(content_dir() / "instruments" / "trombone_tenor.json");
  ASSERT_TRUE(instrument.ok()) << instrument.error().message;
  EXPECT_GT(instrument->slide_length_mm, 500.0);
  EXPECT_DOUBLE_EQ(extra(model, "slide", "max_extension_mm"), instrument->slide_length_mm);
  // At rest the slide node has no offset (local -Z translation = extension), and at the
  // maximum the outer tubes still overlap the inner ones.
  EXPECT_TRUE(model.nodes[static_cast<std::size_t>(slide)].translation.empty());
  const auto inner = world_extent(model, "inner_slide", 2);
  const auto outer = world_extent(model, "slide", 2);
  EXPECT_GT(outer[1] - instrument->slide_length_mm / 1000, inner[0] + 0.02);
  const double bell = dimensions_["trombone"]["bell_diameter_mm"].get<double>() / 1000;
  const auto bell_x = world_extent(model, "bell_section", 0);
  EXPECT_GE(bell_x[1] - bell_x[0], bell);
  const auto bell_z = world_extent(model, "bell_section", 2);
  EXPECT_NEAR(-bell_z[0], dimensions_["trombone"]["bell_forward_mm"].get<double>() / 1000, 0.003);
}

// Euphonium and tuba: upright, the bell on top, four pistons in a row on the player's right.
TEST_F(BrassAndStage, UprightInstrumentsHaveFourPistonsAndTheirRealSize) {
  for (const char* name : {"euphonium", "tuba"}) {
    SCOPED_TRACE(name);
    const tinygltf::Model model = load_glb(assets_->dir() / (std::string(name) + ".glb"));
    const int root = find_node(model, name);
    ASSERT_GE(root, 0);
    for (const char* node : {"mouthpiece", "body", "valve_1", "valve_2", "valve_3", "valve_4",
                             "grip_left", "grip_right", "thumb_rest"}) {
      ASSERT_GE(find_node(model, node), 0) << node;
      EXPECT_EQ(parent_of(model, find_node(model, node)), root) << node;
    }
    const nlohmann::json& dims = dimensions_[name];
    const auto body_y = world_extent(model, "body", 1);
    EXPECT_NEAR(body_y[1] - body_y[0], dims["height_mm"].get<double>() / 1000, 0.02);
    EXPECT_NEAR(body_y[1], dims["top_above_mm"].get<double>() / 1000, 0.02);
    const auto body_x = world_extent(model, "body", 0);
    EXPECT_GE(body_x[1] - body_x[0], dims["bell_diameter_mm"].get<double>() / 1000);
    const double travel = dims["piston_travel_mm"].get<double>();
    double previous_z = 1.0;
    for (const char* valve : {"valve_1", "valve_2", "valve_3", "valve_4"}) {
      EXPECT_DOUBLE_EQ(extra(model, valve, "travel_mm"), travel) << valve;
      const int node = find_node(model, valve);
      const auto origin = world_origin(model, node);
      EXPECT_GT(origin[0], 0.0) << valve << ": on the player's right";
      EXPECT_NEAR(origin[1], -dims["button_drop_mm"].get<double>() / 1000, 1e-6) << valve;
      EXPECT_LT(origin[2], previous_z) << valve << ": valve 1 nearest the player";
      previous_z = origin[2];
    }
  }
}

// The horn: four rotors with their caps, three levers and the thumb's trigger on the player's
// left, the hook, the bell low on the right with the right palm's place inside it.
TEST_F(BrassAndStage, HornHasRotorsLeversATriggerAndItsBellOnTheRight) {
  const tinygltf::Model model = load_glb(assets_->dir() / "horn.glb");
  const int root = find_node(model, "horn");
  ASSERT_GE(root, 0);
  for (const char* node : {"mouthpiece", "body", "rotor_1", "rotor_2", "rotor_3", "rotor_4",
                           "valve_1", "valve_2", "valve_3", "valve_4", "hook", "grip_right"}) {
    ASSERT_GE(find_node(model, node), 0) << node;
    EXPECT_EQ(parent_of(model, find_node(model, node)), root) << node;
  }
  const nlohmann::json& dims = dimensions_["horn"];
  const double travel = dims["lever_travel_mm"].get<double>();
  for (const char* valve : {"valve_1", "valve_2", "valve_3", "valve_4"}) {
    EXPECT_DOUBLE_EQ(extra(model, valve, "travel_mm"), travel) << valve;
    EXPECT_LT(world_origin(model, find_node(model, valve))[0], 0.0) << valve << ": the left hand's";
  }
  const auto body_x = world_extent(model, "body", 0);
  EXPECT_GT(body_x[1], 0.2) << "the bell on the player's right";
  EXPECT_GE(body_x[1] - body_x[0], dims["bell_diameter_mm"].get<double>() / 1000);
  const auto grip = world_origin(model, find_node(model, "grip_right"));
  EXPECT_GT(grip[0], 0.1);
  EXPECT_LT(grip[1], -0.2) << "the right hand low, in the bell";
}

TEST_F(BrassAndStage, StageFloorTopIsAtZeroWithItsRealSize) {
  const tinygltf::Model model = load_glb(assets_->dir() / "stage.glb");
  ASSERT_GE(find_node(model, "stage"), 0);
  const auto floor_y = world_extent(model, "floor", 1);
  EXPECT_NEAR(floor_y[1], 0.0, 1e-7);
  const auto skirt_x = world_extent(model, "skirt", 0);
  const auto skirt_z = world_extent(model, "skirt", 2);
  EXPECT_NEAR(skirt_x[1] - skirt_x[0], dimensions_["stage"]["width_mm"].get<double>() / 1000, 1e-6);
  EXPECT_NEAR(skirt_z[1] - skirt_z[0], dimensions_["stage"]["depth_mm"].get<double>() / 1000, 1e-6);
  EXPECT_NEAR(-world_extent(model, "skirt", 1)[0],
              dimensions_["stage"]["platform_height_mm"].get<double>() / 1000, 1e-6);
}

}  // namespace
}  // namespace tutti::test
