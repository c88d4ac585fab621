// SPDX-License-Identifier: MIT
#include <tutti/generator/hand_asset.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include <tutti/content/json_reader.hpp>
#include <tutti/core/file_io.hpp>
#include <tutti/finger_motion/evaluate_hand_pose.hpp>
#include <tutti/finger_motion/finger_chain.hpp>
#include <tutti/finger_motion/plan_finger_motion.hpp>
#include "gltf_test_support.hpp"
#include <tutti/piano_model/hand_model.hpp>
#include <tutti/piano_model/keyboard.hpp>
#include "rig_test_support.hpp"

namespace tutti::test {
namespace {

using components::HandSide;
using finger_motion::FingerMotionPlan;

constexpr const char* kFingers[5] = {"thumb", "index", "middle", "ring", "little"};

// The motion model with no notes: every finger at rest (what the renderer sees between notes).
FingerMotionPlan rest_plan() {
  auto keyboard = piano_model::Keyboard::load(content_dir() / "piano" / "keyboard.json");
  EXPECT_TRUE(keyboard.ok());
  auto hands = piano_model::HandModel::load(content_dir() / "piano" / "hands.json", "",
                                            keyboard->white_key_width_mm());
  EXPECT_TRUE(hands.ok());
  auto params = finger_motion::load_finger_motion_params(
      finger_motion::finger_motion_params_path(content_dir()));
  EXPECT_TRUE(params.ok());
  auto plan = finger_motion::plan_finger_motion(
      music::Score{}, fingering_planner::ScorePlan{}, spline_motion::HandPath{},
      spline_motion::HandPath{}, *keyboard, *hands, *params);
  EXPECT_TRUE(plan.ok()) << plan.error().message;
  return *plan;
}

// Flexion about the bone's local -X: the contract in README.md, written out independently.
std::vector<double> flexion(double radians) {
  return {-std::sin(radians / 2), 0.0, 0.0, std::cos(radians / 2)};
}

std::string bone(int finger, int segment, const std::string& suffix) {
  return std::string(kFingers[finger - 1]) + "_" + std::to_string(segment) + suffix;
}

class HandAsset : public ::testing::Test {
 protected:
  void SetUp() override {
    assets_ = std::make_unique<GeneratedAssets>("hands");
    right_ = load_glb(assets_->dir() / "hand_right.glb");
    left_ = load_glb(assets_->dir() / "hand_left.glb");
    plan_ = rest_plan();
  }
  const tinygltf::Model& model(HandSide side) const {
    return side == HandSide::left ? left_ : right_;
  }
  static std::string suffix(HandSide side) { return side == HandSide::left ? "_l" : "_r"; }

  // Fingertip in the keyboard frame relative to the hand's reference point, mm: the end of the
  // distal segment, from the node transforms.
  std::array<double, 3> tip_mm(const tinygltf::Model& m, HandSide side, int finger) const {
    const int distal = find_node(m, bone(finger, 3, suffix(side)));
    EXPECT_GE(distal, 0);
    const double length = plan_.geometry[static_cast<std::size_t>(finger - 1)].phalanges_mm[2];
    const auto p = apply(world_matrix(m, distal), {0, 0, -length / 1000});
    return {p[0] * 1000, -p[2] * 1000, p[1] * 1000};
  }
  // The motion model's tip relative to the reference point (middle finger root).
  std::array<double, 3> relative(double x, double y, double z) const {
    return {x, y - plan_.geometry[2].root_y_mm, z - plan_.geometry[2].root_z_mm};
  }

  std::unique_ptr<GeneratedAssets> assets_;
  tinygltf::Model right_;
  tinygltf::Model left_;
  FingerMotionPlan plan_;
};

TEST_F(HandAsset, BothHandsLoadWithTheirBonesAndAValidSkin) {
  for (const HandSide side : {HandSide::right, HandSide::left}) {
    const tinygltf::Model& m = model(side);
    SCOPED_TRACE(suffix(side));
    expect_valid_buffers(m);
    expect_valid_skins(m);
    ASSERT_EQ(m.skins.size(), 1u);
    const int hand = find_node(m, "hand" + suffix(side));
    ASSERT_GE(hand, 0);
    EXPECT_EQ(parent_of(m, hand), -1);
    std::vector<int> expected_joints{hand};
    for (int f = 1; f <= 5; ++f) {
      int parent = hand;
      for (int s = 1; s <= 3; ++s) {
        const int node = find_node(m, bone(f, s, suffix(side)));
        ASSERT_GE(node, 0) << bone(f, s, suffix(side));
        EXPECT_EQ(parent_of(m, node), parent);
        expected_joints.push_back(node);
        parent = node;
      }
      const int tip = find_node(m, std::string(kFingers[f - 1]) + "_tip" + suffix(side));
      ASSERT_GE(tip, 0);
      EXPECT_EQ(parent_of(m, tip), parent);
    }
    std::vector<int> joints = m.skins[0].joints;
    std::sort(joints.begin(), joints.end());
    std::sort(expected_joints.begin(), expected_joints.end());
    EXPECT_EQ(joints, expected_joints);
    // Every bone carries weight: no joint without vertices.
    const auto& primitive = m.meshes.at(0).primitives.at(0);
    const auto joint_ids = read_accessor<std::uint16_t>(m, primitive.attributes.at("JOINTS_0"));
    const auto weights = read_accessor<float>(m, primitive.attributes.at("WEIGHTS_0"));
    std::vector<double> carried(m.skins[0].joints.size(), 0.0);
    for (std::size_t i = 0; i < joint_ids.size(); ++i) carried[joint_ids[i]] += weights[i];
    for (std::size_t j = 0; j < carried.size(); ++j) EXPECT_GT(carried[j], 10.0) << j;
  }
}

TEST_F(HandAsset, AtRestEveryFingertipIsWhereTheMotionModelPutsIt) {
  for (const HandSide side : {HandSide::right, HandSide::left}) {
    for (int f = 1; f <= 5; ++f) {
      finger_motion::FingerPose pose;
      finger_motion::evaluate_finger_pose(plan_, side, f, 0.0, 0.0, pose);
      const auto expected = relative(pose.tip_x_mm, pose.tip_y_mm, pose.tip_z_mm);
      // As stored (the rest pose) ...
      const auto at_rest = tip_mm(model(side), side, f);
      // ... and with the motion model's angles put on the bones per the contract.
      tinygltf::Model posed = model(side);
      const double angles[3] = {f == 1 ? pose.abduction_rad : pose.mcp_flexion_rad,
                                f == 1 ? pose.mcp_flexion_rad : pose.pip_flexion_rad,
                                f == 1 ? pose.pip_flexion_rad : pose.dip_flexion_rad};
      EXPECT_DOUBLE_EQ(pose.spread_rad, 0.0);
      for (int s = 1; s <= 3; ++s) {
        posed.nodes[static_cast<std::size_t>(find_node(posed, bone(f, s, suffix(side))))].rotation =
            flexion(angles[s - 1]);
      }
      const auto with_angles = tip_mm(posed, side, f);
      // The tip node agrees with the end of the distal segment.
      const auto tip_node = world_origin(
          model(side),
          find_node(model(side), std::string(kFingers[f - 1]) + "_tip" + suffix(side)));
      for (std::size_t a = 0; a < 3; ++a) {
        EXPECT_NEAR(at_rest[a], expected[a], 1.0)
            << kFingers[f - 1] << suffix(side) << " axis " << a;
        EXPECT_NEAR(with_angles[a], expected[a], 1.0) << kFingers[f - 1] << suffix(side);
      }
      EXPECT_NEAR(tip_node[0] * 1000, at_rest[0], 1e-3);
      EXPECT_NEAR(-tip_node[2] * 1000, at_rest[1], 1e-3);
      EXPECT_NEAR(tip_node[1] * 1000, at_rest[2], 1e-3);
    }
  }
  // Spot check of the data path: the right index tip rests left of the middle finger's
  // (hands.json: index reach [-2, 0.5] white keys) and 8 mm above the keys (hover lift).
  finger_motion::FingerPose index;
  finger_motion::evaluate_finger_pose(plan_, HandSide::right, 2, 0.0, 0.0, index);
  EXPECT_NEAR(tip_mm(right_, HandSide::right, 2)[0], -0.75 * 23.5, 1.0);
  EXPECT_NEAR(tip_mm(right_, HandSide::right, 2)[2] + plan_.geometry[2].root_z_mm, 8.0, 1.0);
}

TEST_F(HandAsset, FlexedFingertipsFollowTheFingerChain) {
  for (const HandSide side : {HandSide::right, HandSide::left}) {
    const auto& rest = plan_.hand(side).rest_offset_mm;
    for (int f = 1; f <= 5; ++f) {
      const auto& g = plan_.geometry[static_cast<std::size_t>(f - 1)];
      for (const double bend : {0.0, 0.2, 0.95, 1.4}) {
        for (const double drop : {-5.0, 20.0, 50.0}) {
          const finger_motion::ChainShape shape = finger_motion::chain_shape(g, bend);
          // Out of reach the model clamps the drop; the chain cannot follow the asked height.
          if (drop * drop >= shape.forward_mm * shape.forward_mm + shape.down_mm * shape.down_mm) {
            continue;
          }
          const finger_motion::StrokeSolution stroke = finger_motion::solve_stroke(shape, drop);
          tinygltf::Model posed = model(side);
          const double angles[3] = {stroke.joint1_rad, shape.bend_rad, shape.joint3_rad};
          for (int s = 1; s <= 3; ++s) {
            posed.nodes[static_cast<std::size_t>(find_node(posed, bone(f, s, suffix(side))))]
                .rotation = flexion(angles[s - 1]);
          }
          const auto tip = tip_mm(posed, side, f);
          const auto expected = relative(rest[static_cast<std::size_t>(f - 1)] - rest[2],
                                         g.root_y_mm + stroke.reach_y_mm, g.root_z_mm - drop);
          for (std::size_t a = 0; a < 3; ++a) {
            EXPECT_NEAR(tip[a], expected[a], 1e-3)
                << kFingers[f - 1] << suffix(side) << " bend " << bend << " drop " << drop;
          }
        }
      }
    }
  }
}

TEST_F(HandAsset, LeftHandIsTheMirrorImageOfTheRight) {
  for (std::size_t n = 0; n < right_.nodes.size(); ++n) {
    std::string name = right_.nodes[n].name;
    const std::size_t at = name.rfind("_r");
    ASSERT_NE(at, std::string::npos) << name;
    const std::string left_name = name.substr(0, at) + "_l" + name.substr(at + 2);
    const int left = find_node(left_, left_name);
    ASSERT_GE(left, 0) << left_name;
    const auto r = world_origin(right_, static_cast<int>(n));
    const auto l = world_origin(left_, left);
    EXPECT_NEAR(l[0], -r[0], 1e-7) << name;
    EXPECT_NEAR(l[1], r[1], 1e-7) << name;
    EXPECT_NEAR(l[2], r[2], 1e-7) << name;
  }
  // The flesh too: same vertex count, mirrored bounds.
  const auto& r = position_accessor(right_, 0);
  const auto& l = position_accessor(left_, 0);
  EXPECT_EQ(r.count, l.count);
  EXPECT_NEAR(l.minValues[0], -r.maxValues[0], 1e-6);
  EXPECT_NEAR(l.maxValues[1], r.maxValues[1], 1e-6);
}

TEST_F(HandAsset, JointLimitsFromTheDataFileAreInEachBonesExtras) {
  auto document = content::read_json_file(content_dir() / "generator" / "hand_rig.json");
  ASSERT_TRUE(document.ok());
  for (const HandSide side : {HandSide::right, HandSide::left}) {
    const tinygltf::Model& m = model(side);
    for (int f = 1; f <= 5; ++f) {
      for (int s = 1; s <= 3; ++s) {
        const auto& limits = (*document)["joint_limits_deg"][bone(f, s, "")];
        const auto& node =
            m.nodes[static_cast<std::size_t>(find_node(m, bone(f, s, suffix(side))))];
        for (const char* key : {"flexion_min_deg", "flexion_max_deg"}) {
          ASSERT_TRUE(node.extras.Has(key)) << node.name;
          EXPECT_DOUBLE_EQ(node.extras.Get(key).GetNumberAsDouble(), limits[key].get<double>());
        }
        EXPECT_EQ(node.extras.Has("spread_min_deg"), s == 1) << node.name;
        // The rest pose lies inside the limits.
        const auto& q = node.rotation;
        const double angle_deg =
            q.empty() ? 0.0 : -2.0 * std::atan2(q[0], q[3]) * 180 / std::numbers::pi;
        EXPECT_GE(angle_deg, limits["flexion_min_deg"].get<double>()) << node.name;
        EXPECT_LE(angle_deg, limits["flexion_max_deg"].get<double>()) << node.name;
      }
    }
  }
}

TEST_F(HandAsset, BadHandRigFileIsAOneLineErrorWithTheJsonPathAndNothingIsWritten) {
  const std::filesystem::path dir = unique_temp_path("bad-hand-rig");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  auto document = content::read_json_file(content_dir() / "generator" / "hand_rig.json");
  ASSERT_TRUE(document.ok());
  struct Case {
    const char* name;
    nlohmann::json json;
    const char* expected;
  };
  nlohmann::json inverted = *document;
  inverted["joint_limits_deg"]["ring_2"]["flexion_min_deg"] = 120.0;
  nlohmann::json unknown = *document;
  unknown["joint_limits_deg"]["index_4"] = unknown["joint_limits_deg"]["index_3"];
  nlohmann::json missing = *document;
  missing["joint_limits_deg"]["thumb_1"].erase("spread_max_deg");
  nlohmann::json range = *document;
  range["shape_mm"]["palm_length_mm"] = 1000.0;
  const Case cases[] = {
      {"inverted", inverted, "hand_rig.json: /joint_limits_deg/ring_2/flexion_min_deg"},
      {"unknown", unknown, "hand_rig.json: /joint_limits_deg: unknown key \"index_4\""},
      {"missing", missing, "hand_rig.json: /joint_limits_deg/thumb_1"},
      {"range", range, "hand_rig.json: /shape_mm/palm_length_mm"},
  };
  for (const Case& c : cases) {
    const std::filesystem::path content = dir / c.name;
    std::filesystem::copy(content_dir(), content, std::filesystem::copy_options::recursive);
    ASSERT_TRUE(write_file_atomically(content / "generator" / "hand_rig.json", c.json.dump()).ok());
    const Status status = content_generator::generate_assets(content, dir / "out");
    ASSERT_FALSE(status.ok()) << c.name;
    EXPECT_NE(status.error().message.find(c.expected), std::string::npos) << status.error().message;
    EXPECT_EQ(status.error().message.find('\n'), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(dir / "out")) << c.name;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tutti::test
