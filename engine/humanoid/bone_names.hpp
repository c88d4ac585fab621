// SPDX-License-Identifier: MIT
#pragma once
// Bone names as the rigs people ship spell them, reduced to a side and a plain base name:
//   "mixamorig:LeftForeArm" -> left, "forearm"      "Armature|rig_Hips" -> none, "hips"
//   "upperarm_l"            -> left, "upperarm"     "DEF-upper_arm.L"   -> left, "upperarm"
//   "f_index.01.R"          -> right, "findex01"    "Bip01 L Forearm"   -> left, "forearm"
//   "J_Bip_L_UpperArm"      -> left, "upperarm"     "LeftHandIndex1"    -> left, "handindex1"
// Namespaces (anything up to the last ':' or '|') and common rig prefixes (mixamorig, DEF-,
// ORG-, rig_, Bip01, CC_Base_, J_Bip_) are dropped; the words are split at separators and at
// lower-to-upper case changes, lower-cased, and the side words (l, r, left, right) taken out.

#include <string>
#include <string_view>

namespace tutti::humanoid {

enum class Side { none, left, right };

struct BoneName {
  Side side = Side::none;
  std::string base;  // the remaining words joined, lower case, digits kept ("spine001")
};

BoneName parse_bone_name(std::string_view name);

}  // namespace tutti::humanoid
