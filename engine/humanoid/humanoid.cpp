// SPDX-License-Identifier: MIT
#include <tutti/humanoid/humanoid.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <string>

#include <tutti/humanoid/bone_names.hpp>

namespace tutti::humanoid {
namespace {

constexpr const char* kFingers[5] = {"thumb", "index", "middle", "ring", "little"};

const std::vector<std::string>& role_storage() {
  static const std::vector<std::string> storage = [] {
    std::vector<std::string> names{"hips", "spine", "chest", "neck", "head"};
    for (const char* side : {"l", "r"}) {
      for (const char* limb : {"shoulder", "upper_arm", "forearm", "hand", "thigh", "shin", "foot"}) {
        names.push_back(std::string(limb) + "_" + side);
      }
    }
    for (const char* side : {"l", "r"}) {
      for (const char* finger : kFingers) {
        for (int joint = 1; joint <= 3; ++joint) {
          names.push_back(std::string(finger) + "_" + std::to_string(joint) + "_" + side);
        }
      }
    }
    return names;
  }();
  return storage;
}

std::string_view side_suffix(Side side) { return side == Side::left ? "_l" : "_r"; }

// The model's nodes as the recogniser sees them.
struct Skeleton {
  const model::ModelAsset& asset;
  std::vector<glm::mat4> world;
  std::vector<BoneName> names;
  std::vector<int> depth;
  std::vector<bool> weighted;  // some vertex is skinned to it
  bool any_weights = false;

  explicit Skeleton(const model::ModelAsset& a) : asset(a) {
    const std::size_t n = a.nodes.size();
    world.resize(n);
    model::compute_world_matrices(a, model::rest_pose(a), glm::mat4(1.0f), world);
    names.reserve(n);
    depth.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      names.push_back(parse_bone_name(a.nodes[i].name));
      const int parent = a.nodes[i].parent;
      depth[i] = parent < 0 ? 0 : depth[static_cast<std::size_t>(parent)] + 1;  // parents first
    }
    weighted.assign(n, false);
    for (const model::Node& node : a.nodes) {
      if (node.mesh < 0 || node.skin < 0) continue;
      const model::Skin& skin = a.skins[static_cast<std::size_t>(node.skin)];
      for (const model::Primitive& p : a.meshes[static_cast<std::size_t>(node.mesh)].primitives) {
        for (std::uint32_t v = 0; v < p.vertex_count; ++v) {
          const model::Vertex& vertex = a.vertices[p.first_vertex + v];
          for (int c = 0; c < 4; ++c) {
            if (vertex.weights[c] <= 0.01f || vertex.joints[c] >= skin.joints.size()) continue;
            weighted[static_cast<std::size_t>(skin.joints[vertex.joints[c]])] = true;
            any_weights = true;
          }
        }
      }
    }
  }

  glm::vec3 at(int node) const { return glm::vec3(world[static_cast<std::size_t>(node)][3]); }
  int parent(int node) const { return asset.nodes[static_cast<std::size_t>(node)].parent; }
  bool is_ancestor(int ancestor, int node) const {
    for (int n = parent(node); n >= 0; n = parent(n)) {
      if (n == ancestor) return true;
    }
    return false;
  }
  // Helpers, IK targets, twist and end bones: never a role.
  bool is_helper(int node) const {
    const std::string& b = names[static_cast<std::size_t>(node)].base;
    const auto has = [&](std::string_view w) { return b.find(w) != std::string::npos; };
    const auto ends = [&](std::string_view w) {
      return b.size() >= w.size() && b.compare(b.size() - w.size(), w.size(), w) == 0;
    };
    return has("twist") || has("roll") || has("helper") || has("corrective") || has("nub") ||
           has("socket") || has("attach") || has("pole") || has("target") || ends("end") ||
           ends("tip") || ends("ik") || b.rfind("ik", 0) == 0;
  }
  // The shallowest node on `side` whose base is one of `bases` (exactly, or followed by digits
  // when `numbered`), not a helper; -1 if none.
  int find(Side side, std::initializer_list<std::string_view> bases, bool numbered = false) const {
    int best = -1;
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (names[i].side != side || is_helper(static_cast<int>(i))) continue;
      const std::string& b = names[i].base;
      bool match = false;
      for (std::string_view want : bases) {
        if (b == want) match = true;
        if (numbered && b.size() > want.size() && b.compare(0, want.size(), want) == 0 &&
            std::all_of(b.begin() + static_cast<std::ptrdiff_t>(want.size()), b.end(),
                        [](char c) { return c >= '0' && c <= '9'; })) {
          match = true;
        }
      }
      if (match && (best < 0 || depth[i] < depth[static_cast<std::size_t>(best)])) {
        best = static_cast<int>(i);
      }
    }
    return best;
  }
};

class Recogniser {
 public:
  explicit Recogniser(const model::ModelAsset& asset) : s_(asset) {
    for (const std::string& role : role_storage()) out_.nodes.emplace_back(role, -1);
  }

  Humanoid run() {
    if (!s_.asset.humanoid_table.empty()) {
      out_.method = s_.asset.humanoid_table_source + " humanoid table";
      from_vrm();
    } else {
      out_.method = "bone names and hierarchy";
      from_names();
    }
    for (const auto& [role, node] : out_.nodes) {
      const auto required = humanoid::required_roles();
      const bool is_required = std::find(required.begin(), required.end(), role) != required.end();
      if (node >= 0) continue;
      (is_required ? out_.missing_required : out_.missing_optional).push_back(role);
    }
    bool skinned = false;
    for (const model::Node& node : s_.asset.nodes) skinned = skinned || (node.mesh >= 0 && node.skin >= 0);
    if (!skinned) out_.problems.emplace_back("no skin: no mesh follows its bones");
    measure();
    find_morphs();
    return std::move(out_);
  }

 private:
  void set(std::string_view role, int node) {
    for (auto& [r, n] : out_.nodes) {
      if (r == role && node >= 0) n = node;
    }
  }
  int get(std::string_view role) const { return out_.node(role); }

  void from_vrm() {
    const bool vrm1 = s_.asset.humanoid_table_source == "VRM 1.0";
    std::map<std::string, int> bones(s_.asset.humanoid_table.begin(), s_.asset.humanoid_table.end());
    const auto bone = [&](const std::string& name) {
      const auto it = bones.find(name);
      return it == bones.end() ? -1 : it->second;
    };
    set("hips", bone("hips"));
    set("spine", bone("spine"));
    set("chest", bone("upperChest") >= 0 ? bone("upperChest") : bone("chest"));
    set("neck", bone("neck"));
    set("head", bone("head"));
    for (const auto& [vrm_side, side] : {std::pair{"left", "_l"}, std::pair{"right", "_r"}}) {
      const std::string v = vrm_side;
      const std::string x = side;
      set("shoulder" + x, bone(v + "Shoulder"));
      set("upper_arm" + x, bone(v + "UpperArm"));
      set("forearm" + x, bone(v + "LowerArm"));
      set("hand" + x, bone(v + "Hand"));
      set("thigh" + x, bone(v + "UpperLeg"));
      set("shin" + x, bone(v + "LowerLeg"));
      set("foot" + x, bone(v + "Foot"));
      const char* thumb1 = vrm1 ? "ThumbMetacarpal" : "ThumbProximal";
      const char* thumb2 = vrm1 ? "ThumbProximal" : "ThumbIntermediate";
      set("thumb_1" + x, bone(v + thumb1));
      set("thumb_2" + x, bone(v + thumb2));
      set("thumb_3" + x, bone(v + "ThumbDistal"));
      for (const auto& [ours, theirs] : {std::pair{"index", "Index"}, std::pair{"middle", "Middle"},
                                        std::pair{"ring", "Ring"}, std::pair{"little", "Little"}}) {
        const std::string o = ours;
        set(o + "_1" + x, bone(v + theirs + "Proximal"));
        set(o + "_2" + x, bone(v + theirs + "Intermediate"));
        set(o + "_3" + x, bone(v + theirs + "Distal"));
      }
    }
    for (std::size_t side = 0; side < 2; ++side) {
      for (std::size_t f = 0; f < 5; ++f) {
        const std::string x = side == 0 ? "_l" : "_r";
        out_.finger_bones[side][f] = get(std::string(kFingers[f]) + "_1" + x) >= 0 ? 3 : 0;
      }
    }
  }

  void from_names() {
    for (const Side side : {Side::left, Side::right}) {
      const std::string x(side_suffix(side));
      // Hands and feet by name; the limbs up their parents, checked by name where it helps.
      const int hand = s_.find(side, {"hand", "wrist"});
      if (hand >= 0) {
        set("hand" + x, hand);
        const int forearm = parent_skipping_helpers(hand);
        set("forearm" + x, forearm);
        const int upper = forearm >= 0 ? parent_skipping_helpers(forearm) : -1;
        set("upper_arm" + x, upper);
        if (upper >= 0) {
          const int shoulder = parent_skipping_helpers(upper);
          if (shoulder >= 0 && s_.names[static_cast<std::size_t>(shoulder)].side == side) {
            set("shoulder" + x, shoulder);
          }
        }
      }
      const int foot = s_.find(side, {"foot", "ankle"});
      if (foot >= 0) {
        set("foot" + x, foot);
        const int shin = parent_skipping_helpers(foot);
        set("shin" + x, shin);
        if (shin >= 0) set("thigh" + x, parent_skipping_helpers(shin));
      }
      find_fingers(side);
    }
    // The hips: by name, else where the legs meet.
    int hips = s_.find(Side::none, {"hips", "hip", "pelvis"});
    const int thigh_l = get("thigh_l"), thigh_r = get("thigh_r");
    if (hips < 0 && thigh_l >= 0 && thigh_r >= 0 && s_.parent(thigh_l) == s_.parent(thigh_r)) {
      hips = s_.parent(thigh_l);
    }
    set("hips", hips);
    // The chest: where the arms meet (the shoulders' parent).
    const int arm_l = get("shoulder_l") >= 0 ? get("shoulder_l") : get("upper_arm_l");
    const int arm_r = get("shoulder_r") >= 0 ? get("shoulder_r") : get("upper_arm_r");
    int chest = -1;
    if (arm_l >= 0 && arm_r >= 0 && s_.parent(arm_l) == s_.parent(arm_r)) chest = s_.parent(arm_l);
    set("chest", chest);
    // The head: by name, else the top of the spine above the chest (Rigify's spine.006).
    int head = s_.find(Side::none, {"head"});
    if (head < 0 && chest >= 0) head = top_of_spine(chest);
    set("head", head);
    if (head >= 0 && chest >= 0 && s_.is_ancestor(chest, head)) {
      // The neck: the first bone above the chest toward the head.
      int n = head;
      while (s_.parent(n) >= 0 && s_.parent(n) != chest) n = s_.parent(n);
      if (n != head) set("neck", n);
    } else if (head >= 0) {
      set("neck", s_.find(Side::none, {"neck"}, true));
    }
    // The spine: the first bone above the hips toward the chest (or the head).
    const int above = chest >= 0 ? chest : head;
    if (hips >= 0 && above >= 0 && s_.is_ancestor(hips, above)) {
      int n = above;
      while (s_.parent(n) >= 0 && s_.parent(n) != hips) n = s_.parent(n);
      set("spine", n);
    }
  }

  // Up a limb: past helpers (twist, IK, end bones) and past a bone's later segments — Rigify's
  // deform rig splits the upper arm, forearm, thigh and shin in two, "DEF-forearm.L.001" under
  // "DEF-forearm.L": the first segment plays the role.
  int parent_skipping_helpers(int node) const {
    int p = s_.parent(node);
    while (p >= 0 && (s_.is_helper(p) || is_later_segment(p))) p = s_.parent(p);
    return p;
  }

  // A bone named as its parent with a number after it, on the same side.
  bool is_later_segment(int node) const {
    const int parent = s_.parent(node);
    if (parent < 0 || trailing_number(node) < 1) return false;
    const BoneName& own = s_.names[static_cast<std::size_t>(node)];
    const BoneName& up = s_.names[static_cast<std::size_t>(parent)];
    std::size_t digits = own.base.size();
    while (digits > 0 && own.base[digits - 1] >= '0' && own.base[digits - 1] <= '9') --digits;
    return own.side == up.side && !up.base.empty() && own.base.compare(0, digits, up.base) == 0 &&
           digits == up.base.size();
  }

  // Up from the chest along children named spine / neck / head: the last one.
  int top_of_spine(int chest) const {
    int at = chest;
    for (;;) {
      int next = -1;
      for (const int child : s_.asset.nodes[static_cast<std::size_t>(at)].children) {
        const BoneName& n = s_.names[static_cast<std::size_t>(child)];
        if (n.side == Side::none &&
            (n.base.rfind("spine", 0) == 0 || n.base.rfind("neck", 0) == 0)) {
          next = child;
        }
      }
      if (next < 0) return at == chest ? -1 : at;
      at = next;
    }
  }

  // The number a bone's name ends with ("handindex4" -> 4), -1 if none.
  int trailing_number(int node) const {
    const std::string& b = s_.names[static_cast<std::size_t>(node)].base;
    std::size_t i = b.size();
    while (i > 0 && b[i - 1] >= '0' && b[i - 1] <= '9') --i;
    if (i == b.size() || b.size() - i > 6) return -1;
    return std::stoi(b.substr(i));
  }

  static int finger_of(const std::string& base) {
    if (base.find("thumb") != std::string::npos || base == "finger0" ||
        base.rfind("finger0", 0) == 0) {
      return 0;
    }
    if (base.find("index") != std::string::npos || base.rfind("finger1", 0) == 0) return 1;
    if (base.find("middle") != std::string::npos || base.rfind("finger2", 0) == 0) return 2;
    if (base.find("ring") != std::string::npos || base.rfind("finger3", 0) == 0) return 3;
    if (base.find("pinky") != std::string::npos || base.find("little") != std::string::npos ||
        base.rfind("finger4", 0) == 0) {
      return 4;
    }
    return -1;
  }

  // Each finger: the nodes under the hand named for it, shallowest first; end bones (a leaf with
  // no weights, or named end / tip / nub) cut off; a fourth bone at the root is a metacarpal.
  void find_fingers(Side side) {
    const int hand = get(std::string("hand") + std::string(side_suffix(side)));
    if (hand < 0) return;
    const std::size_t s = side == Side::left ? 0 : 1;
    for (int f = 0; f < 5; ++f) {
      std::vector<int> chain;
      for (std::size_t i = 0; i < s_.names.size(); ++i) {
        const int node = static_cast<int>(i);
        if (!s_.is_ancestor(hand, node) || finger_of(s_.names[i].base) != f) continue;
        if (s_.names[i].side != side && s_.names[i].side != Side::none) continue;
        chain.push_back(node);
      }
      std::sort(chain.begin(), chain.end(), [&](int a, int b) {
        return s_.depth[static_cast<std::size_t>(a)] < s_.depth[static_cast<std::size_t>(b)];
      });
      // One line of bones: each the parent of the next (a branch elsewhere ends it).
      std::vector<int> line;
      for (const int node : chain) {
        if (line.empty() || s_.parent(node) == line.back()) line.push_back(node);
      }
      while (!line.empty()) {
        const int last = line.back();
        const bool leaf = s_.asset.nodes[static_cast<std::size_t>(last)].children.empty();
        // An end bone: no vertex follows it where the skin reaches the finger, or, without
        // weights on the finger to tell, numbered past the third joint ("LeftHandIndex4").
        bool finger_skinned = false;
        for (const int bone : line) finger_skinned = finger_skinned || s_.weighted[static_cast<std::size_t>(bone)];
        const bool end = finger_skinned ? !s_.weighted[static_cast<std::size_t>(last)]
                                        : trailing_number(last) >= 4;
        if (s_.is_helper(last) || (leaf && end && line.size() > 3)) {
          line.pop_back();
          continue;
        }
        break;
      }
      out_.finger_bones[s][static_cast<std::size_t>(f)] = static_cast<int>(line.size());
      if (line.size() < 3) continue;
      const std::size_t first = line.size() - 3;
      for (std::size_t j = 0; j < 3; ++j) {
        set(std::string(kFingers[f]) + "_" + std::to_string(j + 1) + std::string(side_suffix(side)),
            line[first + j]);
      }
    }
  }

  // Units, height, up, facing and rest pose from the rest pose's joints and skinned mesh.
  void measure() {
    const int hips = get("hips"), head = get("head");
    const int arm_l = get("upper_arm_l"), arm_r = get("upper_arm_r");
    if (hips >= 0 && head >= 0) {
      const glm::vec3 d = s_.at(head) - s_.at(hips);
      // A spine leans; the figure still stands on its file's axis when it is within 25 degrees.
      if (glm::length(d) > 1e-9f) out_.up = snapped(glm::normalize(d), 25.0f);
    }
    if (arm_l >= 0 && arm_r >= 0) {
      const glm::vec3 left = s_.at(arm_l) - s_.at(arm_r);
      const glm::vec3 across = left - glm::dot(left, out_.up) * out_.up;
      if (glm::length(across) > 1e-9f) {
        out_.facing = snapped(glm::normalize(glm::cross(across, out_.up)), 10.0f);
      }
      const int fore = get("forearm_l");
      if (fore >= 0) {
        const glm::vec3 bone = s_.at(fore) - s_.at(arm_l);
        if (glm::length(bone) > 1e-9f) {
          const double below = std::asin(std::clamp(
              static_cast<double>(-glm::dot(glm::normalize(bone), out_.up)), -1.0, 1.0));
          out_.arm_below_horizontal_deg = below * 180.0 / 3.14159265358979;
          out_.rest = out_.arm_below_horizontal_deg < 20.0   ? RestPose::t_pose
                      : out_.arm_below_horizontal_deg < 85.0 ? RestPose::a_pose
                                                             : RestPose::other;
        }
      }
    }
    // Height: the skinned (or drawn) rest mesh along `up`; without a mesh, the joints (+ a head).
    float low = 1e30f, high = -1e30f;
    const model::ModelPose pose = model::rest_pose(s_.asset);
    for (std::size_t n = 0; n < s_.asset.nodes.size(); ++n) {
      const model::Node& node = s_.asset.nodes[n];
      if (node.mesh < 0) continue;
      const model::Mesh& mesh = s_.asset.meshes[static_cast<std::size_t>(node.mesh)];
      for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const std::uint32_t count = mesh.primitives[p].vertex_count;
        const std::uint32_t step = std::max<std::uint32_t>(1, count / 20000);
        for (std::uint32_t v = 0; v < count; v += step) {
          const glm::vec3 at = model::deform_vertex(s_.asset, pose, s_.world, static_cast<int>(n),
                                                    static_cast<int>(p), v)
                                   .position;
          low = std::min(low, glm::dot(at, out_.up));
          high = std::max(high, glm::dot(at, out_.up));
        }
      }
    }
    if (!(high > low)) {
      for (std::size_t i = 0; i < s_.world.size(); ++i) {
        const float h = glm::dot(s_.at(static_cast<int>(i)), out_.up);
        low = std::min(low, h);
        high = std::max(high, h);
      }
      high += (high - low) * 0.07f;
      out_.notes.push_back("no mesh: the height is guessed from the joints");
    }
    const double units = high > low ? static_cast<double>(high - low) : 0.0;
    if (units > 30.0 && units < 300.0) {
      out_.metres_per_unit = 0.01;
      out_.units_guessed = true;
      char line[160];
      std::snprintf(line, sizeof line,
                    "units guessed: centimetres (the figure stands %.1f units tall in the file)",
                    units);
      out_.notes.emplace_back(line);
    } else if (units > 300.0 && units < 3000.0) {
      out_.metres_per_unit = 0.001;
      out_.units_guessed = true;
      out_.notes.emplace_back("units guessed: millimetres");
    } else if (units < 0.3 || units > 3.0) {
      out_.notes.emplace_back("unusual height: " + std::to_string(units) +
                              " units; taken as metres");
    }
    out_.height_m = units * out_.metres_per_unit;
    const glm::vec3 y(0, 1, 0);
    if (glm::dot(out_.up, y) < 0.9f) {
      out_.notes.emplace_back("the figure's up is not +Y in the file");
    }
  }

  // `v` on the nearest axis when it is within `degrees` of it.
  static glm::vec3 snapped(const glm::vec3& v, float degrees) {
    int best = 0;
    for (int c = 1; c < 3; ++c) {
      if (std::abs(v[c]) > std::abs(v[best])) best = c;
    }
    if (std::abs(v[best]) < std::cos(degrees * 3.14159265f / 180.0f)) return v;
    glm::vec3 axis(0.0f);
    axis[best] = v[best] > 0 ? 1.0f : -1.0f;
    return axis;
  }

  void find_morphs() {
    const auto lower = [](std::string t) {
      for (char& c : t) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      return t;
    };
    // tutti's two mouth morphs, and the names each is known by (tutti's own, ARKit, Ready Player
    // Me / Oculus visemes, VRM expressions and VRoid's, VRChat's).
    const std::pair<const char*, std::vector<std::string>> wanted[] = {
        {"tension",
         {"tension", "mouthpucker", "viseme_u", "ou", "u", "fcl_mth_u", "vrc.v_ou", "mouthfunnel"}},
        {"open", {"open", "jawopen", "viseme_aa", "aa", "a", "fcl_mth_a", "vrc.v_aa", "mouthopen"}},
    };
    for (const auto& [role, candidates] : wanted) {
      bool found = false;
      for (const std::string& candidate : candidates) {
        for (const model::Mesh& mesh : s_.asset.meshes) {
          for (const std::string& name : mesh.target_names) {
            if (!found && lower(name) == candidate) {
              out_.morphs.emplace_back(role, name);
              found = true;
            }
          }
        }
      }
    }
  }

  Skeleton s_;
  Humanoid out_;
};

}  // namespace

std::span<const std::string_view> roles() {
  static const std::vector<std::string_view> views = [] {
    std::vector<std::string_view> v;
    for (const std::string& r : role_storage()) v.push_back(r);
    return v;
  }();
  return views;
}

std::span<const std::string_view> required_roles() {
  static const std::vector<std::string_view> required{
      "hips", "spine", "head", "upper_arm_l", "upper_arm_r", "forearm_l", "forearm_r",
      "hand_l", "hand_r"};
  return required;
}

std::string_view rest_pose_name(RestPose pose) {
  switch (pose) {
    case RestPose::t_pose:
      return "T-pose";
    case RestPose::a_pose:
      return "A-pose";
    default:
      return "neither T nor A";
  }
}

std::string Humanoid::what_is_missing() const {
  std::string text;
  if (!missing_required.empty()) {
    text = "no ";
    for (std::size_t i = 0; i < missing_required.size(); ++i) {
      text += (i == 0 ? "" : ", ") + std::string(missing_required[i]);
    }
  }
  for (const std::string& problem : problems) text += (text.empty() ? "" : "; ") + problem;
  return text;
}

int Humanoid::node(std::string_view role) const {
  for (const auto& [r, n] : nodes) {
    if (r == role) return n;
  }
  return -1;
}

Humanoid recognise(const model::ModelAsset& asset) { return Recogniser(asset).run(); }

glm::dvec3 rotation_to_tutti_deg(const Humanoid& h) {
  const glm::dvec3 y = glm::normalize(glm::dvec3(h.up));
  glm::dvec3 z = glm::dvec3(h.facing) - glm::dot(glm::dvec3(h.facing), y) * y;
  z = glm::length(z) > 1e-9 ? glm::normalize(z) : glm::dvec3(0, 0, 1);
  const glm::dvec3 x = glm::cross(y, z);
  // The rotation's rows are the file's x, y, z (it maps them onto X, Y, Z); as Rz * Ry * Rx.
  const double r00 = x.x, r10 = y.x, r20 = z.x, r21 = z.y, r22 = z.z;
  const double deg = 180.0 / 3.14159265358979;
  const auto clean = [](double v) {
    return std::abs(v) < 1e-6 ? 0.0 : std::round(v * 1000.0) / 1000.0;
  };
  return {clean(std::atan2(r21, r22) * deg), clean(std::asin(std::clamp(-r20, -1.0, 1.0)) * deg),
          clean(std::atan2(r10, r00) * deg)};
}

}  // namespace tutti::humanoid
