// SPDX-License-Identifier: MIT
// Bone names from the rigs people ship, reduced to a side and a base (engine/humanoid).
#include <tutti/humanoid/bone_names.hpp>

#include <gtest/gtest.h>

namespace tutti::humanoid {
namespace {

TEST(BoneNames, SidesAndBasesAcrossConventions) {
  const struct {
    const char* name;
    Side side;
    const char* base;
  } cases[] = {
      {"mixamorig:LeftForeArm", Side::left, "forearm"},
      {"LeftHandIndex1", Side::left, "handindex1"},
      {"Armature|mixamorig:RightUpLeg", Side::right, "upleg"},
      {"rig_Hips", Side::none, "hips"},
      {"upperarm_l", Side::left, "upperarm"},
      {"index_metacarpal_r", Side::right, "indexmetacarpal"},
      {"DEF-upper_arm.L", Side::left, "upperarm"},
      {"f_index.01.R", Side::right, "findex01"},
      {"spine.006", Side::none, "spine006"},
      {"UpperArm.L", Side::left, "upperarm"},
      {"Index1.R", Side::right, "index1"},
      {"Bip01 L Forearm", Side::left, "forearm"},
      {"Bip01 R Finger0", Side::right, "finger0"},
      {"J_Bip_L_UpperArm", Side::left, "upperarm"},
      {"CC_Base_R_Hand", Side::right, "hand"},
      {"LeftThumbProximal", Side::left, "thumbproximal"},
      {"Head", Side::none, "head"},
      {"lowerarm_l", Side::left, "lowerarm"},
  };
  for (const auto& c : cases) {
    const BoneName n = parse_bone_name(c.name);
    EXPECT_EQ(n.side, c.side) << c.name;
    EXPECT_EQ(n.base, c.base) << c.name;
  }
}

}  // namespace
}  // namespace tutti::humanoid
