// SPDX-License-Identifier: MIT
#include <tutti/generator/piano_asset.hpp>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "gltf_test_support.hpp"
#include <tutti/piano_model/keyboard.hpp>

namespace tutti::test {
namespace {

piano_model::Keyboard keyboard() {
  auto loaded = piano_model::Keyboard::load(content_dir() / "piano" / "keyboard.json");
  EXPECT_TRUE(loaded.ok()) << (loaded.ok() ? "" : loaded.error().message);
  return loaded.ok() ? *loaded : piano_model::Keyboard{};
}

class PianoAsset : public ::testing::Test {
 protected:
  void SetUp() override {
    assets_ = std::make_unique<GeneratedAssets>("piano");
    model_ = load_glb(assets_->dir() / "piano.glb");
  }
  std::unique_ptr<GeneratedAssets> assets_;
  tinygltf::Model model_;
};

TEST_F(PianoAsset, Has88KeyNodesUnderTheKeyboardNode) {
  const int keyboard_node = find_node(model_, "keyboard");
  ASSERT_GE(keyboard_node, 0);
  EXPECT_EQ(parent_of(model_, keyboard_node), find_node(model_, "piano"));
  int keys = 0;
  for (const auto& node : model_.nodes) keys += node.name.rfind("key_", 0) == 0 ? 1 : 0;
  EXPECT_EQ(keys, 88);
  for (int key = 21; key <= 108; ++key) {
    const int node = find_node(model_, "key_" + std::to_string(key));
    ASSERT_GE(node, 0) << key;
    EXPECT_EQ(parent_of(model_, node), keyboard_node) << key;
  }
  EXPECT_EQ(find_node(model_, "key_20"), -1);
  EXPECT_EQ(find_node(model_, "key_109"), -1);
  ASSERT_EQ(model_.scenes.size(), 1u);
  EXPECT_EQ(model_.scenes[0].nodes, std::vector<int>{find_node(model_, "piano")});
}

// The keyboard family's other instruments: the same build, each with its compass and its id as
// the root's name (content/piano/instruments.json).
TEST_F(PianoAsset, TheOrgansManualHasItsOwnCompassAndName) {
  const tinygltf::Model organ = load_glb(assets_->dir() / "keyboard_organ.glb");
  const int root = find_node(organ, "organ");
  ASSERT_GE(root, 0);
  EXPECT_EQ(organ.scenes[0].nodes, std::vector<int>{root});
  EXPECT_EQ(find_node(organ, "piano"), -1);
  for (int key = 36; key <= 96; ++key) EXPECT_GE(find_node(organ, "key_" + std::to_string(key)), 0);
  EXPECT_EQ(find_node(organ, "key_35"), -1);
  EXPECT_EQ(find_node(organ, "key_97"), -1);
  // Its keys start at the left edge of its own lowest key (C2), as the piano's at A0.
  EXPECT_NEAR(translation(organ, find_node(organ, "key_36"), kX), 0.01175, 1e-9);
  // Its pedalboard: pedal_36..pedal_67 under `pedalboard`, naturals 63.5 mm apart.
  const int pedalboard = find_node(organ, "pedalboard");
  ASSERT_GE(pedalboard, 0);
  EXPECT_EQ(parent_of(organ, pedalboard), root);
  for (int key = 36; key <= 67; ++key) {
    const int pedal = find_node(organ, "pedal_" + std::to_string(key));
    ASSERT_GE(pedal, 0) << key;
    EXPECT_EQ(parent_of(organ, pedal), pedalboard);
  }
  EXPECT_EQ(find_node(organ, "pedal_68"), -1);
  EXPECT_NEAR(translation(organ, find_node(organ, "pedal_38"), kX) -
                  translation(organ, find_node(organ, "pedal_36"), kX),
              0.0635, 1e-6);
  EXPECT_NEAR(translation(organ, find_node(organ, "pedal_52"), kX), 0.0, 1e-6) << "E3 centred";
  EXPECT_GT(translation(organ, find_node(organ, "pedal_37"), kY), 0.0) << "sharps stand higher";
  EXPECT_EQ(find_node(load_glb(assets_->dir() / "keyboard_synth.glb"), "pedalboard"), -1);
}

// The harpsichord's keys are narrower (a 152.4 mm octave, instruments.json) and its black keys
// with them; the piano's octave is 164.5 mm.
TEST_F(PianoAsset, TheHarpsichordsKeysAreNarrower) {
  const tinygltf::Model harpsichord = load_glb(assets_->dir() / "keyboard_harpsichord.glb");
  const auto x = [&](const tinygltf::Model& m, int key) {
    return translation(m, find_node(m, "key_" + std::to_string(key)), kX);
  };
  EXPECT_NEAR(x(harpsichord, 72) - x(harpsichord, 60), 0.1524, 1e-6);
  EXPECT_NEAR(x(model_, 72) - x(model_, 60), 0.1645, 1e-6);
  const auto mesh_width = [](const tinygltf::Model& m, int node) {
    const auto& mesh = m.meshes[static_cast<std::size_t>(m.nodes[static_cast<std::size_t>(node)].mesh)];
    const auto& accessor = m.accessors[static_cast<std::size_t>(mesh.primitives[0].attributes.at("POSITION"))];
    return accessor.maxValues[0] - accessor.minValues[0];
  };
  EXPECT_NEAR(mesh_width(harpsichord, find_node(harpsichord, "key_61")) /
                  mesh_width(model_, find_node(model_, "key_61")),
              152.4 / 164.5, 1e-4)
      << "a black key narrower by as much as the octave";
}

TEST_F(PianoAsset, KeyNodesSitAtTheKeyboardsXPositionsInMetres) {
  const piano_model::Keyboard board = keyboard();
  for (int key = 21; key <= 108; ++key) {
    const int node = find_node(model_, "key_" + std::to_string(key));
    ASSERT_GE(node, 0);
    EXPECT_NEAR(translation(model_, node, kX), board.x_mm(key) / 1000.0, 0.0001) << key;
  }
  // Spot checks against the standard layout: A0 centre 11.75 mm, middle C 23 white keys on.
  EXPECT_NEAR(translation(model_, find_node(model_, "key_21"), kX), 0.01175, 1e-9);
  EXPECT_NEAR(translation(model_, find_node(model_, "key_60"), kX), 0.01175 + 23 * 0.0235, 1e-9);
}

TEST_F(PianoAsset, WhiteAndBlackKeysUseTheirOwnMeshesWithRealDimensions) {
  const piano_model::Keyboard board = keyboard();
  int white_mesh = -1;
  int black_mesh = -1;
  for (int key = 21; key <= 108; ++key) {
    const int mesh =
        model_.nodes[static_cast<std::size_t>(find_node(model_, "key_" + std::to_string(key)))]
            .mesh;
    ASSERT_GE(mesh, 0);
    int& expected = board.is_black(key) ? black_mesh : white_mesh;
    if (expected < 0) expected = mesh;
    EXPECT_EQ(mesh, expected) << key;
  }
  ASSERT_NE(white_mesh, black_mesh);
  EXPECT_EQ(model_.meshes[static_cast<std::size_t>(white_mesh)].name, "white_key");
  EXPECT_EQ(model_.meshes[static_cast<std::size_t>(black_mesh)].name, "black_key");
  // Width (x), height (y), length (z) in metres.
  EXPECT_NEAR(mesh_extent(model_, white_mesh, kX), 0.0225, 1e-6);
  EXPECT_NEAR(mesh_extent(model_, white_mesh, kY), 0.022, 1e-6);
  EXPECT_NEAR(mesh_extent(model_, white_mesh, kZ), 0.150, 1e-6);
  EXPECT_NEAR(mesh_extent(model_, black_mesh, kX), 0.011, 1e-6);
  EXPECT_NEAR(mesh_extent(model_, black_mesh, kZ), 0.095, 1e-6);
  // Materials: near-white and near-black base colours, metallic-roughness.
  auto colour = [&](int mesh) {
    const auto& primitive = model_.meshes[static_cast<std::size_t>(mesh)].primitives[0];
    return model_.materials[static_cast<std::size_t>(primitive.material)]
        .pbrMetallicRoughness.baseColorFactor;
  };
  EXPECT_GT(colour(white_mesh)[0], 0.7);
  EXPECT_LT(colour(black_mesh)[0], 0.1);
}

TEST_F(PianoAsset, KeyOriginsAreAtTheBackPivotAndBlackKeysStandHigher) {
  const piano_model::Keyboard board = keyboard();
  const double white_top = world_translation(model_, find_node(model_, "key_60"), kY);
  EXPECT_NEAR(white_top, 0.72, 1e-6);  // key top above the floor
  for (int key = 21; key <= 108; ++key) {
    const int node = find_node(model_, "key_" + std::to_string(key));
    const int mesh = model_.nodes[static_cast<std::size_t>(node)].mesh;
    const auto& positions = position_accessor(model_, mesh);
    // The key hangs from its origin: nothing above it or behind it, all of it toward +Z.
    EXPECT_NEAR(positions.maxValues[kY], 0.0, 1e-9);
    EXPECT_NEAR(positions.minValues[kZ], 0.0, 1e-9);
    const double top = world_translation(model_, node, kY) + positions.maxValues[kY];
    if (board.is_black(key)) {
      EXPECT_NEAR(top - white_top, 0.012, 1e-6) << key;
    } else {
      EXPECT_NEAR(top, white_top, 1e-9) << key;
    }
    // Every pivot on the same back line, 150 mm behind the white keys' front edge (Z = 0).
    EXPECT_NEAR(world_translation(model_, node, kZ), -0.150, 1e-9) << key;
  }
  // The keyboard is centred on the piano's origin: A0's left edge and C8's right edge mirror.
  const double left = world_translation(model_, find_node(model_, "key_21"), kX) - 0.01175;
  const double right = world_translation(model_, find_node(model_, "key_108"), kX) + 0.01175;
  EXPECT_NEAR(left, -right, 1e-9);
  EXPECT_NEAR(right - left, 52 * 0.0235, 1e-9);
}

TEST_F(PianoAsset, HasACaseAroundTheKeysAndValidBuffers) {
  const int case_node = find_node(model_, "case");
  ASSERT_GE(case_node, 0);
  EXPECT_EQ(parent_of(model_, case_node), find_node(model_, "piano"));
  const int mesh = model_.nodes[static_cast<std::size_t>(case_node)].mesh;
  ASSERT_GE(mesh, 0);
  const auto& positions = position_accessor(model_, mesh);
  EXPECT_GT(mesh_extent(model_, mesh, kX), 52 * 0.0235);  // wider than the keys
  EXPECT_NEAR(positions.minValues[kY], 0.0, 1e-9);        // stands on the floor
  EXPECT_GT(positions.maxValues[kY], 1.0);                // an upright's cabinet
  expect_valid_buffers(model_);
}

TEST(PianoModel, BuildsFromAnyKeyboardItIsGiven) {
  // A 61-key keyboard (C2..C7) made from the same document shape as content/piano/keyboard.json.
  nlohmann::json document = {
      {"lowest_key", 36},
      {"highest_key", 96},
      {"white_key_width_mm", 23.5},
      {"black_key_centres_mm",
       {{"C#", 20.5625}, {"D#", 47.9792}, {"F#", 89.1042}, {"G#", 116.5208}, {"A#", 143.9375}}}};
  auto board = piano_model::Keyboard::from_json(document, "small.json");
  ASSERT_TRUE(board.ok()) << board.error().message;
  const tinygltf::Model model = content_generator::build_piano(*board);
  int keys = 0;
  for (const auto& node : model.nodes) keys += node.name.rfind("key_", 0) == 0 ? 1 : 0;
  EXPECT_EQ(keys, 61);
  EXPECT_GE(find_node(model, "key_36"), 0);
  EXPECT_GE(find_node(model, "key_96"), 0);
  EXPECT_EQ(find_node(model, "key_35"), -1);
}

}  // namespace
}  // namespace tutti::test
