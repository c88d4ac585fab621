// SPDX-License-Identifier: MIT
// Humanoids recognised by themselves (engine/humanoid): one skeleton, spelled the way each
// convention spells it (Mixamo with and without a namespace, Unreal with twist bones and
// metacarpals, Rigify's metarig with palm bones and a spine chain, Blender .L/.R, Unity-like,
// VRoid, 3ds Max biped), and as VRM 0.x and 1.0 tables over meaningless node names. Every role
// lands on the node that convention gives it; units, height, up, facing and rest pose are read.
#include <tutti/humanoid/humanoid.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <functional>
#include <map>
#include <string>

#include "gltf_test_builder.hpp"

namespace tutti::humanoid {
namespace {

using test::GltfBuilder;

struct Joint {
  std::string role;    // tutti's role ("" for a node no role should take)
  std::string parent;  // role or name of the parent ("" for the root)
  glm::vec3 at;        // world position, metres, facing +Z, up +Y
};

// The canonical figure: 1.75 m, facing +Z (its left hand at +X), arms in a T or an A.
std::vector<Joint> figure(bool t_pose) {
  std::vector<Joint> j = {{"hips", "", {0, 0.95f, 0}},       {"spine", "hips", {0, 1.05f, 0}},
                          {"chest", "spine", {0, 1.30f, 0}}, {"neck", "chest", {0, 1.50f, 0}},
                          {"head", "neck", {0, 1.60f, 0}}};
  const float down = t_pose ? 0.0f : 0.7071f;
  const float out = t_pose ? 1.0f : 0.7071f;
  for (const float sign : {1.0f, -1.0f}) {
    const std::string x = sign > 0 ? "_l" : "_r";
    const glm::vec3 shoulder{sign * 0.03f, 1.45f, 0};
    const glm::vec3 upper{sign * 0.18f, 1.45f, 0};
    const glm::vec3 dir{sign * out, -down, 0};
    const glm::vec3 fore = upper + 0.28f * dir;
    const glm::vec3 hand = fore + 0.25f * dir;
    j.push_back({"shoulder" + x, "chest", shoulder});
    j.push_back({"upper_arm" + x, "shoulder" + x, upper});
    j.push_back({"forearm" + x, "upper_arm" + x, fore});
    j.push_back({"hand" + x, "forearm" + x, hand});
    const char* fingers[5] = {"thumb", "index", "middle", "ring", "little"};
    for (int f = 0; f < 5; ++f) {
      glm::vec3 at = hand + 0.05f * dir + glm::vec3(0, 0, 0.03f - 0.015f * static_cast<float>(f));
      if (f == 0) at = hand + 0.02f * dir + glm::vec3(0, 0, 0.04f);
      std::string parent = "hand" + x;
      for (int k = 1; k <= 3; ++k) {
        const std::string role = std::string(fingers[f]) + "_" + std::to_string(k) + x;
        j.push_back({role, parent, at});
        parent = role;
        at += 0.03f * dir;
      }
    }
    j.push_back({"thigh" + x, "hips", {sign * 0.09f, 0.92f, 0}});
    j.push_back({"shin" + x, "thigh" + x, {sign * 0.09f, 0.50f, 0}});
    j.push_back({"foot" + x, "shin" + x, {sign * 0.09f, 0.08f, 0.0f}});
  }
  return j;
}

// Node names of a convention for tutti's roles, and its extra nodes: (name, parent's name or
// role, offset from the parent); an extra whose `insert_above` names a role sits between that
// role and its parent.
struct Convention {
  std::string name;
  std::function<std::string(const std::string& role)> spell;
  struct Extra {
    std::string name, parent, insert_above;
    glm::vec3 offset{0};
  };
  std::vector<Extra> extras;
};

std::string side_of(const std::string& role) { return role.substr(role.size() - 2) == "_l" ? "L" : "R"; }
std::string limb_of(const std::string& role) { return role.substr(0, role.size() - 2); }
bool sided(const std::string& role) {
  return role.size() > 2 && (role.substr(role.size() - 2) == "_l" || role.substr(role.size() - 2) == "_r");
}
int finger_index(const std::string& limb, std::string* finger) {
  for (const char* f : {"thumb", "index", "middle", "ring", "little"}) {
    if (limb.rfind(f, 0) == 0) {
      *finger = f;
      return limb.back() - '0';
    }
  }
  return 0;
}

std::string mixamo(const std::string& role, const std::string& ns) {
  static const std::map<std::string, std::string> body{
      {"hips", "Hips"},         {"spine", "Spine"},       {"chest", "Spine2"},
      {"neck", "Neck"},         {"head", "Head"},         {"shoulder", "Shoulder"},
      {"upper_arm", "Arm"},     {"forearm", "ForeArm"},   {"hand", "Hand"},
      {"thigh", "UpLeg"},       {"shin", "Leg"},          {"foot", "Foot"}};
  if (!sided(role)) return ns + body.at(role);
  const std::string side = side_of(role) == "L" ? "Left" : "Right";
  std::string finger;
  const int k = finger_index(limb_of(role), &finger);
  if (k > 0) {
    std::string f = finger == "little" ? "Pinky" : finger;
    f[0] = static_cast<char>(std::toupper(f[0]));
    return ns + side + "Hand" + f + std::to_string(k);
  }
  return ns + side + body.at(limb_of(role));
}

std::vector<Convention> conventions() {
  std::vector<Convention> all;
  // Mixamo: Spine1 between Spine and Spine2, HeadTop_End, a 4th end bone on every finger.
  for (const std::string ns : {"mixamorig:", "", "Armature|mixamorig:", "rig_"}) {
    Convention c{"mixamo " + ns, [ns](const std::string& r) { return mixamo(r, ns); }, {}};
    c.extras.push_back({ns + "Spine1", "", "chest", {0, 0.12f, 0}});
    c.extras.push_back({ns + "HeadTop_End", "head", "", {0, 0.18f, 0}});
    for (const char* side : {"Left", "Right"}) {
      for (const char* f : {"Thumb", "Index", "Middle", "Ring", "Pinky"}) {
        const std::string x = side;
        const std::string role = std::string(f == std::string("Pinky") ? "little" : f) + "_3_" +
                                 (x == "Left" ? "l" : "r");
        std::string lower_role = role;
        lower_role[0] = static_cast<char>(std::tolower(lower_role[0]));
        c.extras.push_back({ns + x + "Hand" + f + "4", lower_role, "", {0.0f, -0.02f, 0}});
      }
    }
    all.push_back(c);
  }
  // Unreal: pelvis, spine_01..03, clavicle, upperarm/lowerarm, calf, twist bones, metacarpals.
  {
    Convention c{"unreal",
                 [](const std::string& r) -> std::string {
                   static const std::map<std::string, std::string> body{
                       {"hips", "pelvis"},  {"spine", "spine_01"},       {"chest", "spine_03"},
                       {"neck", "neck_01"}, {"head", "head"},            {"shoulder", "clavicle"},
                       {"upper_arm", "upperarm"}, {"forearm", "lowerarm"}, {"hand", "hand"},
                       {"thigh", "thigh"},  {"shin", "calf"},            {"foot", "foot"}};
                   if (!sided(r)) return body.at(r);
                   const std::string x = side_of(r) == "L" ? "_l" : "_r";
                   std::string finger;
                   const int k = finger_index(limb_of(r), &finger);
                   if (k > 0) return (finger == "little" ? "pinky" : finger) + "_0" + std::to_string(k) + x;
                   return body.at(limb_of(r)) + x;
                 },
                 {}};
    c.extras.push_back({"spine_02", "", "chest", {0, 0.12f, 0}});
    for (const char* x : {"_l", "_r"}) {
      const std::string s = x;
      c.extras.push_back({"upperarm_twist_01" + s, "upper_arm" + s, "", {0.1f, 0, 0}});
      c.extras.push_back({"lowerarm_twist_01" + s, "forearm" + s, "", {0.1f, 0, 0}});
      for (const char* f : {"index", "middle", "ring", "pinky"}) {
        const std::string role = std::string(f == std::string("pinky") ? "little" : f) + "_1" + s;
        c.extras.push_back({std::string(f) + "_metacarpal" + s, "", role, {-0.04f, 0, 0}});
      }
    }
    all.push_back(c);
  }
  // Rigify's metarig: spine, spine.001 .. spine.006 (the head), palm bones, .L / .R.
  {
    Convention c{"rigify",
                 [](const std::string& r) -> std::string {
                   static const std::map<std::string, std::string> body{
                       {"hips", "spine"},   {"spine", "spine.001"},  {"chest", "spine.003"},
                       {"neck", "spine.004"}, {"head", "spine.006"}, {"shoulder", "shoulder"},
                       {"upper_arm", "upper_arm"}, {"forearm", "forearm"}, {"hand", "hand"},
                       {"thigh", "thigh"},  {"shin", "shin"},        {"foot", "foot"}};
                   if (!sided(r)) return body.at(r);
                   const std::string x = "." + side_of(r);
                   std::string finger;
                   const int k = finger_index(limb_of(r), &finger);
                   if (k == 0) return body.at(limb_of(r)) + x;
                   if (finger == "thumb") return "thumb.0" + std::to_string(k) + x;
                   return "f_" + (finger == "little" ? std::string("pinky") : finger) + ".0" +
                          std::to_string(k) + x;
                 },
                 {}};
    c.extras.push_back({"spine.002", "", "chest", {0, 0.12f, 0}});
    c.extras.push_back({"spine.005", "", "head", {0, 0.05f, 0}});
    c.extras.push_back({"face", "head", "", {0, 0.05f, 0.05f}});
    for (const char* x : {"L", "R"}) {
      const std::string s = x;
      const std::string r = s == "L" ? "_l" : "_r";
      c.extras.push_back({"palm.01." + s, "", "index_1" + r, {-0.04f, 0, 0}});
      c.extras.push_back({"palm.02." + s, "", "middle_1" + r, {-0.04f, 0, 0}});
      c.extras.push_back({"heel.02." + s, "foot" + r, "", {0, -0.05f, -0.05f}});
    }
    all.push_back(c);
  }
  // Blender-style .L / .R with Unity-like words; Unity-like; VRoid; 3ds Max biped.
  const auto unity = [](const std::string& r, const std::string& pre, const std::string& left,
                        const std::string& right, bool suffix, const std::string& joint) {
    static const std::map<std::string, std::string> body{
        {"hips", "Hips"},     {"spine", "Spine"},          {"chest", "Chest"},
        {"neck", "Neck"},     {"head", "Head"},            {"shoulder", "Shoulder"},
        {"upper_arm", "UpperArm"}, {"forearm", "LowerArm"}, {"hand", "Hand"},
        {"thigh", "UpperLeg"}, {"shin", "LowerLeg"},       {"foot", "Foot"}};
    if (!sided(r)) return pre + body.at(r);
    const std::string side = side_of(r) == "L" ? left : right;
    std::string finger;
    const int k = finger_index(limb_of(r), &finger);
    std::string part;
    if (k > 0) {
      std::string f = finger;
      f[0] = static_cast<char>(std::toupper(f[0]));
      const char* unity_joint[3] = {"Proximal", "Intermediate", "Distal"};
      part = f + (joint == "numbers" ? std::to_string(k) : unity_joint[k - 1]);
    } else {
      part = body.at(limb_of(r));
    }
    return suffix ? pre + part + side : pre + side + part;
  };
  all.push_back({"blender", [unity](const std::string& r) { return unity(r, "", ".L", ".R", true, "numbers"); }, {}});
  all.push_back({"unity", [unity](const std::string& r) { return unity(r, "", "Left", "Right", false, "unity"); }, {}});
  all.push_back({"vroid", [unity](const std::string& r) { return unity(r, "J_Bip_", "L_", "R_", false, "unity"); }, {}});
  all.push_back({"biped", [unity](const std::string& r) {
                   std::string name = unity(r, "Bip01 ", "L ", "R ", false, "numbers");
                   return name;
                 }, {}});
  return all;
}

// The figure as a glTF skeleton, every node placed by a translation from its parent, with a box
// "body" mesh from the soles to the top of the head (for the height). `scale` multiplies all
// positions (a file in centimetres is 100); `root_scale` is the root node's own scale.
GltfBuilder skeleton(const Convention& c, bool t_pose, float scale = 1.0f, float root_scale = 1.0f,
                     float turn_deg = 0.0f) {
  std::vector<Joint> joints = figure(t_pose);
  struct N {
    std::string name, parent;
    glm::vec3 at;
  };
  std::vector<N> nodes;
  std::map<std::string, std::string> name_of_role;
  for (const Joint& j : joints) name_of_role[j.role] = c.spell(j.role);
  std::map<std::string, glm::vec3> at;
  for (const Joint& j : joints) {
    nodes.push_back({name_of_role[j.role], j.parent.empty() ? "" : name_of_role[j.parent], j.at});
    at[name_of_role[j.role]] = j.at;
  }
  for (const auto& e : c.extras) {
    if (!e.insert_above.empty()) {
      const std::string child = name_of_role.at(e.insert_above);
      for (N& n : nodes) {
        if (n.name == child) {
          const glm::vec3 p = n.at - e.offset;
          nodes.push_back({e.name, n.parent, p});
          n.parent = e.name;
          at[e.name] = p;
          break;
        }
      }
    } else {
      const std::string parent = name_of_role.count(e.parent) ? name_of_role.at(e.parent) : e.parent;
      nodes.push_back({e.name, parent, at.at(parent) + e.offset});
      at[e.name] = at.at(parent) + e.offset;
    }
  }
  GltfBuilder b;
  std::map<std::string, int> index;
  for (std::size_t i = 0; i < nodes.size(); ++i) index[nodes[i].name] = static_cast<int>(i);
  for (const N& n : nodes) {
    const glm::vec3 local = n.parent.empty() ? n.at : n.at - at.at(n.parent);
    nlohmann::json node = {{"name", n.name},
                           {"translation", {local.x * scale, local.y * scale, local.z * scale}}};
    if (n.parent.empty()) {
      node["translation"] = {local.x * scale, local.y * scale, local.z * scale};
      if (root_scale != 1.0f) node["scale"] = {root_scale, root_scale, root_scale};
      if (turn_deg != 0.0f) {
        const float h = turn_deg * 3.14159265f / 360.0f;
        node["rotation"] = {0, std::sin(h), 0, std::cos(h)};
      }
    }
    std::vector<int> children;
    for (const N& other : nodes) {
      if (other.parent == n.name) children.push_back(index[other.name]);
    }
    if (!children.empty()) node["children"] = children;
    b.add_node(node);
  }
  // The body: a thin box from the soles (y 0) to the crown (1.75 m), under the root.
  const float s = scale;
  test::add_triangle_mesh(b, "body",
                          {{-0.2f * s, 0, 0}, {0.2f * s, 0, 0}, {0, 1.75f * s, 0}},
                          {0, 1, 2});
  // Skinned to the root joint (identity bind: the triangle rides the hips, its height unchanged).
  const std::vector<std::uint8_t> skin_joints(12, 0);
  const std::vector<float> skin_weights = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
  b.json["meshes"][0]["primitives"][0]["attributes"]["JOINTS_0"] =
      b.add_data(skin_joints, test::kUnsignedByte, "VEC4");
  b.json["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"] =
      b.add_data(skin_weights, test::kFloat, "VEC4");
  b.json["skins"] = nlohmann::json::array({{{"joints", {0}}}});
  const int body = b.add_node({{"name", "body"}, {"mesh", 0}, {"skin", 0}});
  b.json["nodes"][0]["children"].push_back(body);
  b.set_scene({0});
  return b;
}

model::ModelAsset load(const GltfBuilder& b, const std::string& name) {
  auto asset = test::load_bytes(b.glb(), name);
  EXPECT_TRUE(asset) << asset.error().message;
  return asset ? *asset : model::ModelAsset{};
}

TEST(Humanoid, EveryConventionsRolesLandOnTheirNodes) {
  for (const Convention& c : conventions()) {
    for (const bool t_pose : {true, false}) {
      const model::ModelAsset asset = load(skeleton(c, t_pose), c.name + ".glb");
      const Humanoid h = recognise(asset);
      EXPECT_TRUE(h.playable()) << c.name;
      EXPECT_TRUE(h.missing_optional.empty()) << c.name << ": " << h.missing_optional.size()
                                              << " missing, first " << (h.missing_optional.empty() ? "" : std::string(h.missing_optional[0]));
      for (const auto& [role, node] : h.nodes) {
        const std::string expected = c.spell(std::string(role));
        EXPECT_EQ(node < 0 ? std::string("(none)") : asset.nodes[static_cast<std::size_t>(node)].name,
                  expected)
            << c.name << " " << role;
      }
      EXPECT_EQ(h.method, "bone names and hierarchy");
      EXPECT_NEAR(h.height_m, 1.75, 0.01) << c.name;
      EXPECT_EQ(h.metres_per_unit, 1.0) << c.name;
      EXPECT_NEAR(h.up.y, 1.0f, 1e-4f) << c.name;
      EXPECT_NEAR(h.facing.z, 1.0f, 1e-4f) << c.name;
      EXPECT_EQ(h.rest, t_pose ? RestPose::t_pose : RestPose::a_pose) << c.name;
    }
  }
}

TEST(Humanoid, MetacarpalsAndEndBonesAreCounted) {
  const std::vector<Convention> all = conventions();
  const Humanoid unreal = recognise(load(skeleton(all[4], false), "unreal.glb"));
  ASSERT_EQ(all[4].name, "unreal");
  EXPECT_EQ(unreal.finger_bones[0][0], 3);  // the thumb has none
  EXPECT_EQ(unreal.finger_bones[0][1], 4);  // index: a metacarpal, skipped
}

// Units: a file in centimetres whose root scales it by 0.01 is in metres (the scale applied
// once); one without the root scale is guessed to be in centimetres, with a note.
TEST(Humanoid, UnitsComeFromTheFileAndAreGuessedOnlyWhenNeeded) {
  const Convention mixamo = conventions()[0];
  const Humanoid scaled = recognise(load(skeleton(mixamo, false, 100.0f, 0.01f), "scaled.glb"));
  EXPECT_EQ(scaled.metres_per_unit, 1.0);
  EXPECT_FALSE(scaled.units_guessed);
  EXPECT_NEAR(scaled.height_m, 1.75, 0.01);
  const Humanoid cm = recognise(load(skeleton(mixamo, false, 100.0f), "cm.glb"));
  EXPECT_EQ(cm.metres_per_unit, 0.01);
  EXPECT_TRUE(cm.units_guessed);
  EXPECT_NEAR(cm.height_m, 1.75, 0.01);
  ASSERT_FALSE(cm.notes.empty());
  EXPECT_NE(cm.notes[0].find("centimetres"), std::string::npos);
}

TEST(Humanoid, FacingIsReadFromTheShoulders) {
  const Humanoid turned = recognise(load(skeleton(conventions()[0], true, 1.0f, 1.0f, 90.0f), "turned.glb"));
  EXPECT_NEAR(turned.facing.x, 1.0f, 1e-4f);  // +Z turned 90 degrees about +Y
  EXPECT_NEAR(turned.facing.z, 0.0f, 1e-4f);
}

// VRM: the humanoid table is authoritative, whatever the nodes are called (0.x and 1.0).
TEST(Humanoid, VrmTablesAreTakenAsTheyAre) {
  const Convention plain{"node", [](const std::string& r) { return "node_" + r; }, {}};
  GltfBuilder b = skeleton(plain, true);
  std::map<std::string, std::string> vrm_name;  // our role -> VRM bone name (1.0)
  const std::map<std::string, std::string> body{
      {"hips", "hips"}, {"spine", "spine"}, {"chest", "chest"}, {"neck", "neck"}, {"head", "head"},
      {"shoulder", "Shoulder"}, {"upper_arm", "UpperArm"}, {"forearm", "LowerArm"},
      {"hand", "Hand"}, {"thigh", "UpperLeg"}, {"shin", "LowerLeg"}, {"foot", "Foot"}};
  nlohmann::json bones1 = nlohmann::json::object();
  nlohmann::json bones0 = nlohmann::json::array();
  for (std::size_t i = 0; i < b.json["nodes"].size(); ++i) {
    const std::string name = b.json["nodes"][i]["name"];
    if (name.rfind("node_", 0) != 0) continue;
    const std::string role = name.substr(5);
    std::string vrm1, vrm0;
    if (!sided(role)) {
      vrm1 = vrm0 = body.at(role);
    } else {
      const std::string side = side_of(role) == "L" ? "left" : "right";
      std::string finger;
      const int k = finger_index(limb_of(role), &finger);
      if (k == 0) {
        vrm1 = vrm0 = side + body.at(limb_of(role));
      } else {
        std::string f = finger;
        f[0] = static_cast<char>(std::toupper(f[0]));
        const char* joint0[3] = {"Proximal", "Intermediate", "Distal"};
        const char* thumb1[3] = {"Metacarpal", "Proximal", "Distal"};
        vrm0 = side + f + joint0[k - 1];
        vrm1 = side + f + (finger == "thumb" ? thumb1[k - 1] : joint0[k - 1]);
      }
    }
    bones1[vrm1] = {{"node", i}};
    bones0.push_back({{"bone", vrm0}, {"node", i}});
  }
  for (const bool one : {true, false}) {
    GltfBuilder v = b;
    v.json["extensionsUsed"] = {one ? "VRMC_vrm" : "VRM"};
    if (one) {
      v.json["extensions"]["VRMC_vrm"] = {{"specVersion", "1.0"}, {"humanoid", {{"humanBones", bones1}}}};
    } else {
      v.json["extensions"]["VRM"] = {{"humanoid", {{"humanBones", bones0}}}};
    }
    const model::ModelAsset asset = load(v, "avatar.vrm");
    const Humanoid h = recognise(asset);
    EXPECT_EQ(h.method, one ? "VRM 1.0 humanoid table" : "VRM 0.x humanoid table");
    EXPECT_TRUE(h.playable());
    EXPECT_TRUE(h.missing_optional.empty());
    for (const auto& [role, node] : h.nodes) {
      ASSERT_GE(node, 0) << role;
      EXPECT_EQ(asset.nodes[static_cast<std::size_t>(node)].name, "node_" + std::string(role));
    }
  }
}

// Not a humanoid: the roles it lacks are listed.
TEST(Humanoid, AnUnrecognisedRigListsWhatIsMissing) {
  const Convention numbers{"numbers", [](const std::string& r) { return "bone_" + std::to_string(std::hash<std::string>{}(r) % 100000); }, {}};
  const Humanoid h = recognise(load(skeleton(numbers, true), "numbers.glb"));
  EXPECT_FALSE(h.playable());
  EXPECT_EQ(h.missing_required.size(), required_roles().size());
}

// Bones but no skin: nothing would follow them; not playable, and said so.
TEST(Humanoid, ARigWithoutASkinIsNotPlayable) {
  GltfBuilder b = skeleton(conventions()[0], true);
  b.json.erase("skins");
  for (auto& node : b.json["nodes"]) node.erase("skin");
  const Humanoid h = recognise(load(b, "unskinned.glb"));
  EXPECT_TRUE(h.missing_required.empty());
  EXPECT_FALSE(h.playable());
  EXPECT_EQ(h.what_is_missing(), "no skin: no mesh follows its bones");
}

TEST(Humanoid, FaceMorphsAreFoundByTheirNames) {
  GltfBuilder b = skeleton(conventions()[0], true);
  const std::vector<glm::vec3> deltas(3, {0, 0, 0.01f});
  const int d1 = b.add_vec3s(deltas), d2 = b.add_vec3s(deltas), d3 = b.add_vec3s(deltas);
  b.json["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", d1}}, {{"POSITION", d2}}, {{"POSITION", d3}}};
  b.json["meshes"][0]["extras"]["targetNames"] = {"browInnerUp", "jawOpen", "mouthPucker"};
  const Humanoid h = recognise(load(b, "arkit.glb"));
  ASSERT_EQ(h.morphs.size(), 2u);
  EXPECT_EQ(h.morphs[0], (std::pair<std::string, std::string>{"tension", "mouthPucker"}));
  EXPECT_EQ(h.morphs[1], (std::pair<std::string, std::string>{"open", "jawOpen"}));
}

}  // namespace
}  // namespace tutti::humanoid
