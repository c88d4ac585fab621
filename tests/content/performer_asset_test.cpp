// SPDX-License-Identifier: MIT
#include <tutti/generator/performer_asset.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include <tutti/content/json_reader.hpp>
#include <tutti/generator/dimensions.hpp>
#include <tutti/generator/hand_rig.hpp>
#include "gltf_test_support.hpp"
#include "rig_test_support.hpp"

namespace tutti::test {
namespace {

using Point = std::array<double, 3>;

std::vector<std::string> bone_names() {
  std::vector<std::string> names{"hips", "spine", "chest", "neck", "head"};
  for (const std::string side : {"_l", "_r"}) {
    for (const char* bone : {"shoulder", "upper_arm", "forearm", "hand", "thigh", "shin", "foot"}) {
      names.push_back(bone + side);
    }
    for (const char* finger : {"thumb", "index", "middle", "ring", "little"}) {
      for (int s = 1; s <= 3; ++s) names.push_back(finger + ("_" + std::to_string(s)) + side);
    }
  }
  return names;
}

double distance(const Point& a, const Point& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

class PerformerAsset : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    assets_ = new GeneratedAssets("performer");
    model_ = new tinygltf::Model(load_glb(assets_->dir() / "performer.glb"));
  }
  static void TearDownTestSuite() {
    delete model_;
    delete assets_;
  }
  static const tinygltf::Model& model() { return *model_; }
  static int node(const std::string& name) {
    const int n = find_node(model(), name);
    EXPECT_GE(n, 0) << name;
    return n;
  }
  static Point at(const std::string& name) { return world_origin(model(), node(name)); }

  // Every skinned vertex in the bind pose, with the weight it gives joint node `joint` (-1:
  // none asked).
  struct Vertex {
    Point p;
    double weight;
  };
  static std::vector<Vertex> vertices(int joint = -1) {
    std::vector<Vertex> out;
    const tinygltf::Model& m = model();
    for (const auto& n : m.nodes) {
      if (n.mesh < 0) continue;
      const auto& primitive = m.meshes[static_cast<std::size_t>(n.mesh)].primitives.at(0);
      const auto positions = read_accessor<float>(m, primitive.attributes.at("POSITION"));
      const auto joints = read_accessor<std::uint16_t>(m, primitive.attributes.at("JOINTS_0"));
      const auto weights = read_accessor<float>(m, primitive.attributes.at("WEIGHTS_0"));
      const auto& skin = m.skins.at(static_cast<std::size_t>(n.skin));
      for (std::size_t v = 0; v < positions.size() / 3; ++v) {
        double w = 0.0;
        for (std::size_t k = 0; k < 4; ++k) {
          if (skin.joints.at(joints[4 * v + k]) == joint) w += weights[4 * v + k];
        }
        out.push_back({{positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]}, w});
      }
    }
    return out;
  }

  static GeneratedAssets* assets_;
  static tinygltf::Model* model_;
};
GeneratedAssets* PerformerAsset::assets_ = nullptr;
tinygltf::Model* PerformerAsset::model_ = nullptr;

TEST_F(PerformerAsset, LoadsWithValidBuffersAndOneSkinOverEveryBone) {
  expect_valid_buffers(model());
  expect_valid_skins(model());
  ASSERT_EQ(model().skins.size(), 1u);
  const auto& skin = model().skins[0];
  for (const std::string& name : bone_names()) {
    const int n = node(name);
    EXPECT_NE(std::find(skin.joints.begin(), skin.joints.end(), n), skin.joints.end()) << name;
  }
  for (const char* attach : {"mouth", "grip_l", "grip_r", "performer"}) {
    EXPECT_EQ(std::find(skin.joints.begin(), skin.joints.end(), node(attach)), skin.joints.end())
        << attach << " is not a joint";
  }
  EXPECT_EQ(skin.skeleton, node("hips"));
  EXPECT_EQ(skin.joints.size(), bone_names().size());
  // Every mesh is skinned with it.
  for (const auto& n : model().nodes) {
    if (n.mesh >= 0) {
      EXPECT_EQ(n.skin, 0) << n.name;
    }
  }
}

TEST_F(PerformerAsset, GripsCarryTheHandAssetsFrame) {
  // An instrument's grip is in the hand asset's frame (fingers -Z, palm -Y): the performer's
  // grip nodes are turned into it, so the fingers (-Z of the grip) point down the hanging arm
  // and the palm (-Y) toward the body.
  for (const std::string x : {"_l", "_r"}) {
    const auto& n = model().nodes.at(static_cast<std::size_t>(node("grip" + x)));
    ASSERT_EQ(n.rotation.size(), 4u) << x;
    const glm::dquat q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);
    EXPECT_NEAR(glm::length(q), 1.0, 1e-9);
    const glm::dvec3 fingers = q * glm::dvec3(0, 0, -1);
    const glm::dvec3 palm = q * glm::dvec3(0, -1, 0);
    EXPECT_LT(fingers.y, -0.8) << x;
    const double sign = x == "_r" ? -1.0 : 1.0;
    EXPECT_LT(sign * palm.x, -0.5) << x << ": the palm faces the body";
  }
}

TEST_F(PerformerAsset, BonesFormTheChainsWithIdentityRestRotations) {
  for (const std::string& name : bone_names()) {
    const auto& n = model().nodes.at(static_cast<std::size_t>(node(name)));
    EXPECT_TRUE(n.rotation.empty() || (n.rotation[0] == 0 && n.rotation[1] == 0 &&
                                       n.rotation[2] == 0 && n.rotation[3] == 1))
        << name;
    EXPECT_TRUE(n.scale.empty()) << name;
    EXPECT_TRUE(n.matrix.empty()) << name;
  }
  auto parent = [&](const std::string& name) {
    const int p = parent_of(model(), node(name));
    return p < 0 ? std::string("-") : model().nodes[static_cast<std::size_t>(p)].name;
  };
  EXPECT_EQ(parent("performer"), "-");
  const auto& roots = model().scenes.at(0).nodes;
  EXPECT_NE(std::find(roots.begin(), roots.end(), node("performer")), roots.end());
  EXPECT_EQ(parent("hips"), "performer");
  EXPECT_EQ(parent("spine"), "hips");
  EXPECT_EQ(parent("chest"), "spine");
  EXPECT_EQ(parent("neck"), "chest");
  EXPECT_EQ(parent("head"), "neck");
  EXPECT_EQ(parent("mouth"), "head");
  for (const std::string x : {"_l", "_r"}) {
    EXPECT_EQ(parent("shoulder" + x), "chest");
    EXPECT_EQ(parent("upper_arm" + x), "shoulder" + x);
    EXPECT_EQ(parent("forearm" + x), "upper_arm" + x);
    EXPECT_EQ(parent("hand" + x), "forearm" + x);
    EXPECT_EQ(parent("grip" + x), "hand" + x);
    EXPECT_EQ(parent("thigh" + x), "hips");
    EXPECT_EQ(parent("shin" + x), "thigh" + x);
    EXPECT_EQ(parent("foot" + x), "shin" + x);
    for (const char* finger : {"thumb", "index", "middle", "ring", "little"}) {
      const std::string f = finger;
      EXPECT_EQ(parent(f + "_1" + x), "hand" + x);
      EXPECT_EQ(parent(f + "_2" + x), f + "_1" + x);
      EXPECT_EQ(parent(f + "_3" + x), f + "_2" + x);
    }
  }
}

TEST_F(PerformerAsset, StandsAbout175mTallOnTheFloorFacingPlusZ) {
  double lo = 1e9, hi = -1e9;
  double front = -1e9, back = 1e9;
  for (const Vertex& v : vertices()) {
    lo = std::min(lo, v.p[1]);
    hi = std::max(hi, v.p[1]);
    front = std::max(front, v.p[2]);
    back = std::min(back, v.p[2]);
  }
  EXPECT_GE(lo, -1e-4);
  EXPECT_LT(lo, 0.005);  // the soles on the floor
  EXPECT_GE(hi, 1.65);
  EXPECT_LE(hi, 1.85);
  // The toes point +Z: the body reaches further forward than back.
  EXPECT_GT(front, -back + 0.05);
  EXPECT_GT(at("foot_l")[1], 0.0);
  EXPECT_NEAR(at("performer")[0], 0.0, 1e-12);
  EXPECT_NEAR(at("performer")[1], 0.0, 1e-12);
}

TEST_F(PerformerAsset, MouthIsOnTheFrontOfTheFaceAtLipHeight) {
  const Point mouth = at("mouth");
  EXPECT_GE(mouth[1], 1.55);
  EXPECT_LE(mouth[1], 1.65);
  EXPECT_NEAR(mouth[0], 0.0, 1e-9);
  double head_front = -1e9;
  for (const Vertex& v : vertices(node("head"))) {
    if (v.weight > 0.99) head_front = std::max(head_front, v.p[2]);
  }
  EXPECT_NEAR(mouth[2], head_front, 0.02);
  EXPECT_GT(mouth[2], at("head")[2] + 0.05);  // in front of the neck
}

TEST_F(PerformerAsset, ArmsHangInAnAPoseWithTheHandsAtTheirSides) {
  for (const std::string x : {"_l", "_r"}) {
    const double sign = x == "_r" ? -1.0 : 1.0;  // facing +Z, the right side is at -X
    const Point shoulder = at("upper_arm" + x), elbow = at("forearm" + x), wrist = at("hand" + x);
    EXPECT_GT(sign * shoulder[0], 0.1) << x;
    EXPECT_GT(sign * wrist[0], 0.1) << x;
    // Down and out: the elbow below and outside the shoulder, the wrist further.
    EXPECT_LT(elbow[1], shoulder[1] - 0.2) << x;
    EXPECT_LT(wrist[1], elbow[1] - 0.2) << x;
    EXPECT_GT(sign * elbow[0], sign * shoulder[0] + 0.01) << x;
    EXPECT_GT(sign * wrist[0], sign * elbow[0] + 0.01) << x;
    // The wrist is at about the hips' height (a hanging arm), the grip in the palm below it.
    EXPECT_NEAR(wrist[1], at("hips")[1], 0.12) << x;
    const Point grip = at("grip" + x);
    EXPECT_LT(grip[1], wrist[1] - 0.03) << x;
    EXPECT_LT(distance(grip, wrist), 0.09) << x;
    // Fingertips below the grip; thumbs forward.
    EXPECT_LT(at("middle_tip" + x)[1], grip[1] - 0.05) << x;
    EXPECT_GT(at("thumb_1" + x)[2], at("little_1" + x)[2] + 0.02) << x;
    // Legs straight down.
    const Point hip = at("thigh" + x), knee = at("shin" + x), ankle = at("foot" + x);
    EXPECT_GT(sign * hip[0], 0.05) << x;
    for (const std::size_t a : {0u, 2u}) {
      EXPECT_NEAR(knee[a], hip[a], 1e-9) << x;
      EXPECT_NEAR(ankle[a], hip[a], 1e-9) << x;
    }
    EXPECT_LT(ankle[1], knee[1] - 0.3) << x;
    EXPECT_LT(knee[1], hip[1] - 0.3) << x;
  }
}

TEST_F(PerformerAsset, FaceHasTensionAndOpenMorphTargetsOnlyAroundTheMouth) {
  const Point mouth = at("mouth");
  int faces = 0;
  for (const auto& n : model().nodes) {
    if (n.mesh < 0) continue;
    const auto& mesh = model().meshes[static_cast<std::size_t>(n.mesh)];
    const auto& primitive = mesh.primitives.at(0);
    if (primitive.targets.empty()) continue;
    ++faces;
    ASSERT_TRUE(mesh.extras.Has("targetNames")) << mesh.name;
    const auto& names = mesh.extras.Get("targetNames");
    ASSERT_EQ(static_cast<std::size_t>(names.ArrayLen()), primitive.targets.size());
    const auto positions = read_accessor<float>(model(), primitive.attributes.at("POSITION"));
    bool has_tension = false, has_open = false;
    for (std::size_t t = 0; t < primitive.targets.size(); ++t) {
      const std::string name = names.Get(static_cast<int>(t)).Get<std::string>();
      has_tension = has_tension || name == "tension";
      has_open = has_open || name == "open";
      const auto deltas = read_accessor<float>(model(), primitive.targets[t].at("POSITION"));
      ASSERT_EQ(deltas.size(), positions.size());
      std::size_t moved = 0;
      double lower_dy = 0.0, corner_dx = 0.0;
      for (std::size_t v = 0; v < positions.size() / 3; ++v) {
        const Point d{deltas[3 * v], deltas[3 * v + 1], deltas[3 * v + 2]};
        if (d[0] == 0 && d[1] == 0 && d[2] == 0) continue;
        ++moved;
        const Point p{positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]};
        EXPECT_LT(distance(p, mouth), 0.06) << name << " vertex " << v;
        if (p[1] < mouth[1] - 0.004) lower_dy += d[1];
        if (std::abs(p[0] - mouth[0]) > 0.015) corner_dx += d[0] * (p[0] > mouth[0] ? 1 : -1);
      }
      EXPECT_GT(moved, 50u) << name;
      if (name == "open") {
        EXPECT_LT(lower_dy, -0.01) << "the lower lip drops";
      }
      if (name == "tension") {
        EXPECT_LT(corner_dx, -0.01) << "the corners draw in";
      }
    }
    EXPECT_TRUE(has_tension) << mesh.name;
    EXPECT_TRUE(has_open) << mesh.name;
    // Default weights: one per target (all 0).
    EXPECT_EQ(mesh.weights.size(), primitive.targets.size());
  }
  EXPECT_EQ(faces, 1);
}

// The performer section of dimensions.json drives the rig, and the defaults equal the file.
TEST(PerformerDimensions, ComeFromTheDataFileAndDefaultsEqualIt) {
  const auto right = content_generator::load_hand_rig(content_dir(), components::HandSide::right);
  const auto left = content_generator::load_hand_rig(content_dir(), components::HandSide::left);
  ASSERT_TRUE(right.ok() && left.ok());
  auto shipped =
      content_generator::AssetDimensions::load(content_dir() / "generator" / "dimensions.json");
  ASSERT_TRUE(shipped.ok()) << shipped.error().message;
  EXPECT_TRUE(content_generator::to_glb(
                  content_generator::build_performer(shipped->performer, *right, *left))
                  .value() == content_generator::to_glb(
                                  content_generator::build_performer(
                                      content_generator::PerformerDimensions{}, *right, *left))
                                  .value());
  content_generator::PerformerDimensions taller = shipped->performer;
  taller.thigh_length_mm += 50.0;
  const tinygltf::Model model = content_generator::build_performer(taller, *right, *left);
  const int hips = find_node(model, "hips");
  ASSERT_GE(hips, 0);
  EXPECT_NEAR(world_origin(model, hips)[1],
              (shipped->performer.ankle_height_mm + shipped->performer.shin_length_mm +
               shipped->performer.thigh_length_mm + 50.0) /
                  1000.0,
              1e-9);
}

TEST(PerformerDimensions, BadValuesAreOneLineErrorsWithTheJsonPath) {
  auto document = content::read_json_file(content_dir() / "generator" / "dimensions.json");
  ASSERT_TRUE(document.ok()) << document.error().message;
  struct Case {
    nlohmann::json json;
    const char* expected;
  };
  std::vector<Case> cases;
  cases.push_back({*document, "dimensions.json: /performer/head_height_mm: must be in"});
  cases.back().json["performer"]["head_height_mm"] = 20.0;
  cases.push_back({*document, "dimensions.json: /performer"});
  cases.back().json["performer"]["tail_length_mm"] = 100.0;
  cases.push_back({*document, "dimensions.json: /performer/arm_spread_deg"});
  cases.back().json["performer"].erase("arm_spread_deg");
  cases.push_back({*document, "dimensions.json: /performer: missing"});
  cases.back().json.erase("performer");
  cases.push_back({*document, "dimensions.json: /performer/thigh_length_mm"});
  cases.back().json["performer"]["thigh_length_mm"] = "long";
  for (const Case& c : cases) {
    auto result = content_generator::AssetDimensions::from_json(c.json, "dimensions.json");
    ASSERT_FALSE(result.ok()) << c.expected;
    EXPECT_EQ(result.error().message.rfind(c.expected, 0), 0u) << result.error().message;
    EXPECT_EQ(result.error().message.find('\n'), std::string::npos) << result.error().message;
  }
}

}  // namespace
}  // namespace tutti::test
