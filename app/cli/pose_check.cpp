// SPDX-License-Identifier: MIT
#include <tutti/cli/pose_check.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include <tutti/brass/brass_components.hpp>
#include <tutti/stage/finger_joint_limits.hpp>
#include <tutti/stage/fingertip_reach.hpp>
#include <tutti/components/finger.hpp>
#include <tutti/components/note.hpp>
#include <tutti/content/content_dir.hpp>
#include <tutti/content/json_reader.hpp>
#include <tutti/components/performer.hpp>
#include <tutti/components/slide.hpp>
#include <tutti/components/valve.hpp>
#include <tutti/piano/hand_capsules.hpp>
#include <tutti/piano/piano_components.hpp>
#include <tutti/piano/pose_feet.hpp>
#include <tutti/piano_model/pedal_geometry.hpp>

namespace tutti::cli {
namespace {

constexpr const char* kFingerNames[5] = {"thumb", "index", "middle", "ring", "little"};
// The fingertip pad's radius (content/generator/hand_rig.json: finger radius × tip ratio).
constexpr double kPadRadiusMm[5] = {
    1000.0 * stage::kFingertipPadRadiusM[0], 1000.0 * stage::kFingertipPadRadiusM[1],
    1000.0 * stage::kFingertipPadRadiusM[2], 1000.0 * stage::kFingertipPadRadiusM[3],
    1000.0 * stage::kFingertipPadRadiusM[4]};
// The head as a capsule: from the head node up its local +Y, and its radius.
constexpr float kHeadLengthM = 0.12f;
constexpr float kHeadRadiusM = 0.095f;
// The torso as a capsule from the hips to the neck, as thick as the mannequin's chest is deep.
constexpr float kTorsoRadiusM = 0.10f;
// The sleeves as capsules (content/generator/performer_asset.cpp): the upper arm's is 50 to 41 mm,
// the forearm's 40 to 35 mm and ends 30 mm short of the wrist, where the hand begins to hold.
constexpr float kUpperArmRadiusM = 0.045f;
constexpr float kForearmRadiusM = 0.037f;
constexpr float kSleeveShortOfWristM = 0.03f;
// How fast a joint may turn, from one sampled frame to the next (deg/s; at check-pose's default
// 30 frames a second, the mean over 33 ms). Outside strokes, 1000: issue 29's figure, above what
// a player's sway, breathing, cues and hand shifts need (the pianist's arms reach 509 on
// third-party music, a brass player's 176) and below a one-frame snap (a 43 deg turn in one frame
// is 1290). A finger striking a key or pressing a valve moves faster: 2500 (the pianist's little
// finger reaches 2176 in the octaves of pianoplayer's test_octaves.xml). The slide arm moving
// the slide, a stroke as quick as the slide's top speed (4 m/s,
// content/instruments/trombone_tenor.json), bends the elbow at up to 1620: 2000.
constexpr double kBodyJointSpeedLimitDegPerS = 1000.0;
constexpr double kFingerJointSpeedLimitDegPerS = 2500.0;
constexpr double kSlideArmJointSpeedLimitDegPerS = 2000.0;

// A model's finger joints: [one hand, the other][thumb .. little][joint from the knuckle out],
// -1 where it has none (stage::BodyNodes::fingers).
using FingerNodes = std::array<std::array<std::array<int, 3>, 5>, 2>;

glm::vec3 origin(const glm::mat4& m) { return glm::vec3(m[3]); }

// World matrices of a placed model's nodes as posed.
void world_of(const stage::PlacedModel& placed, std::vector<glm::mat4>& out) {
  out.resize(placed.asset->nodes.size());
  model::compute_world_matrices(*placed.asset, placed.pose, placed.root, out);
}

double distance_to_line(const glm::vec3& p, const glm::vec3& on_line, const glm::vec3& direction) {
  const glm::vec3 d = glm::normalize(direction);
  const glm::vec3 v = p - on_line;
  return static_cast<double>(glm::length(v - glm::dot(v, d) * d));
}

double distance_to_segment(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
  const glm::vec3 ab = b - a;
  const float t = std::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-12f), 0.0f, 1.0f);
  return static_cast<double>(glm::length(p - (a + t * ab)));
}

// How far inside the box [lo, hi]'s outline across x and y the segment [a, b] passes, where it
// crosses the box (slab clipping); 0 when it misses the box.
double edge_into_box(const glm::vec3& a, const glm::vec3& b, const glm::vec3& lo, const glm::vec3& hi) {
  float enter = 0.0f, leave = 1.0f;
  const glm::vec3 d = b - a;
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(d[axis]) < 1e-9f) {
      if (a[axis] < lo[axis] || a[axis] > hi[axis]) return 0.0;
      continue;
    }
    float t0 = (lo[axis] - a[axis]) / d[axis], t1 = (hi[axis] - a[axis]) / d[axis];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
    if (enter > leave) return 0.0;
  }
  const glm::vec3 mid = a + d * (0.5f * (enter + leave));
  return static_cast<double>(
      std::min({mid.x - lo.x, hi.x - mid.x, mid.y - lo.y, hi.y - mid.y}));
}

using piano_family::HandCapsule;

std::string name_of(const ecs::World& world, ecs::Entity performer) {
  const auto* about = world.try_get<components::Performer>(performer);
  return about != nullptr ? about->name : std::string("?");
}

class Checker {
 public:
  Checker(stage::Stage& stage, PoseReport& report, const stage::FingerJointLimits& limits)
      : stage_(stage), report_(report), limits_(limits) {}

  void at_time(double t_s, double dt_s) {
    t_s_ = t_s;
    dt_s_ = dt_s;
  }

  // The fastest-turning joints of a posed model since the last frame (deg/s), by their local
  // rotations: a one-frame snap of an arm or a finger shows here as an angular speed no player
  // has. Strokes are measured apart, as they are quicker than any other motion: the finger joints
  // (`fingers`, -1 where a model has none), which strike keys and press valves, and the slide arm
  // (`slide_arm`, when given: while the slide moves).
  void joint_speeds(const std::string& who, const stage::PlacedModel& placed,
                    const FingerNodes& fingers, const stage::TwoBoneChain* slide_arm = nullptr) {
    std::vector<glm::quat>& last = last_rotations_[&placed];
    const std::vector<model::NodeTransform>& now = placed.pose.local;
    if (last.size() == now.size()) {
      enum Kind : std::uint8_t { kBody, kFinger, kSlideArm, kKinds };
      joint_kind_.assign(now.size(), kBody);
      const auto mark = [&](int node, Kind kind) {
        if (node >= 0 && static_cast<std::size_t>(node) < now.size()) {
          joint_kind_[static_cast<std::size_t>(node)] = kind;
        }
      };
      for (const auto& hand : fingers) {
        for (const auto& finger : hand) {
          for (const int node : finger) mark(node, kFinger);
        }
      }
      if (slide_arm != nullptr) {
        for (const int node : {slide_arm->upper, slide_arm->lower, slide_arm->end}) {
          mark(node, kSlideArm);
        }
      }
      std::array<double, kKinds> fastest{};
      std::array<std::size_t, kKinds> fastest_node{};
      for (std::size_t n = 0; n < now.size(); ++n) {
        const double cos_half = std::min(1.0, static_cast<double>(std::abs(glm::dot(last[n], now[n].rotation))));
        const double degrees = 2.0 * std::acos(cos_half) * 180.0 / 3.14159265358979323846;
        const auto kind = static_cast<Kind>(joint_kind_[n]);
        if (degrees > fastest[kind]) fastest[kind] = degrees, fastest_node[kind] = n;
      }
      static constexpr const char* kNames[kKinds] = {
          ": fastest joint's angular speed outside strokes",
          ": fastest finger joint's angular speed", ": slide arm's fastest joint while the slide moves"};
      static constexpr double kLimits[kKinds] = {kBodyJointSpeedLimitDegPerS,
                                                 kFingerJointSpeedLimitDegPerS,
                                                 kSlideArmJointSpeedLimitDegPerS};
      for (std::size_t kind = 0; kind < kKinds; ++kind) {
        if (kind == kSlideArm && slide_arm == nullptr) continue;
        measure(who + kNames[kind], "deg/s", kLimits[kind])
            .add(fastest[kind] / dt_s_, t_s_,
                 fastest[kind] > 0.0 ? placed.asset->nodes[fastest_node[kind]].name : std::string());
      }
    }
    last.resize(now.size());
    for (std::size_t n = 0; n < now.size(); ++n) last[n] = now[n].rotation;
  }

  PoseMeasure& measure(const std::string& name, const char* unit, double limit = -1.0,
                       bool by_p95 = false) {
    for (PoseMeasure& m : report_.measures) {
      if (m.name == name) return m;
    }
    PoseMeasure added;
    added.name = name;
    added.unit = unit;
    added.limit = limit;
    added.by_p95 = by_p95;
    report_.measures.push_back(std::move(added));
    return report_.measures.back();
  }

  // How deep the deepest of `points` is inside the head's capsule (0 = all outside).
  void head_clearance(const std::string& who, int head, const std::vector<glm::vec3>& points) {
    if (head < 0) return;
    const glm::mat4& h = body_world_[static_cast<std::size_t>(head)];
    const glm::vec3 bottom = origin(h);
    const glm::vec3 top = bottom + glm::normalize(glm::vec3(h[1])) * kHeadLengthM;
    double clearance = 1e9;
    for (const glm::vec3& p : points) {
      clearance = std::min(clearance, distance_to_segment(p, bottom, top) - kHeadRadiusM);
    }
    measure(who + ": hands and fingertips inside the head (depth; 0 = outside)", "mm", 0.0)
        .add(std::max(0.0, -clearance) * 1000.0, t_s_);
  }

  // How deep the deepest of `points` is inside the torso's capsule (hips to neck).
  void torso_clearance(const std::string& who, int hips, int neck,
                       const std::vector<glm::vec3>& points) {
    if (hips < 0 || neck < 0) return;
    const glm::vec3 bottom = origin(body_world_[static_cast<std::size_t>(hips)]);
    const glm::vec3 top = origin(body_world_[static_cast<std::size_t>(neck)]);
    double clearance = 1e9;
    for (const glm::vec3& p : points) {
      clearance = std::min(clearance, distance_to_segment(p, bottom, top) - kTorsoRadiusM);
    }
    measure(who + ": hands, fingertips and elbows inside the torso (depth; 0 = outside)", "mm",
            0.0)
        .add(std::max(0.0, -clearance) * 1000.0, t_s_);
  }

  // How deep the instrument's surface reaches into either arm's sleeve (shoulder to elbow, elbow to
  // the cuff): an arm passing through a tube or the bell shows here. Hands are left out: they hold.
  void arms_clear_of_instrument(const std::string& who, const stage::PlacedModel& horn,
                                const stage::BodyNodes& nodes) {
    struct Capsule {
      glm::vec3 a, b;
      float radius;
      const char* name;
    };
    std::vector<Capsule> arms;
    for (const stage::TwoBoneChain* arm : {&nodes.arm_left, &nodes.arm_right}) {
      if (arm->upper < 0 || arm->lower < 0 || arm->end < 0) continue;
      const bool left = arm == &nodes.arm_left;
      const glm::vec3 shoulder = origin(body_world_[static_cast<std::size_t>(arm->upper)]);
      const glm::vec3 elbow = origin(body_world_[static_cast<std::size_t>(arm->lower)]);
      const glm::vec3 wrist = origin(body_world_[static_cast<std::size_t>(arm->end)]);
      const float forearm = glm::distance(elbow, wrist);
      if (forearm <= kSleeveShortOfWristM) continue;
      const glm::vec3 cuff = elbow + (wrist - elbow) * ((forearm - kSleeveShortOfWristM) / forearm);
      arms.push_back({shoulder, elbow, kUpperArmRadiusM, left ? "left upper arm" : "right upper arm"});
      arms.push_back({elbow, cuff, kForearmRadiusM, left ? "left forearm" : "right forearm"});
    }
    if (arms.empty()) return;
    double depth = 0.0;
    const Capsule* deepest_arm = nullptr;
    std::size_t deepest_node = 0;
    const model::ModelAsset& asset = *horn.asset;
    for (std::size_t n = 0; n < asset.nodes.size(); ++n) {
      const model::Node& node = asset.nodes[n];
      if (node.mesh < 0 || node.skin >= 0) continue;
      const glm::mat4& world = horn_world_[n];
      for (const model::Primitive& primitive : asset.meshes[static_cast<std::size_t>(node.mesh)].primitives) {
        for (std::uint32_t v = 0; v < primitive.vertex_count; ++v) {
          const glm::vec3 p =
              world * glm::vec4(asset.vertices[primitive.first_vertex + v].position, 1.0f);
          for (const Capsule& arm : arms) {
            const double into = static_cast<double>(arm.radius) - distance_to_segment(p, arm.a, arm.b);
            if (into > depth) depth = into, deepest_arm = &arm, deepest_node = n;
          }
        }
      }
    }
    measure(who + ": instrument inside an arm's sleeve (depth; 0 = clear)", "mm", 0.0)
        .add(depth * 1000.0, t_s_,
             deepest_arm == nullptr
                 ? std::string()
                 : asset.nodes[deepest_node].name + " in the " + deepest_arm->name);
  }

  // A stand model's desk panel in the desk node's frame (node -1: none), read once per model.
  struct DeskPanel {
    int node = -1;
    glm::vec3 lo{0.0f}, hi{0.0f};
  };
  const DeskPanel& desk_panel(const model::ModelAsset& asset) {
    auto [it, added] = desk_panels_.try_emplace(&asset);
    if (!added) return it->second;
    const int desk = asset.find_node("desk");
    if (desk < 0 || asset.nodes[static_cast<std::size_t>(desk)].mesh < 0) return it->second;
    glm::vec3 lo(1e9f), hi(-1e9f);
    const int mesh = asset.nodes[static_cast<std::size_t>(desk)].mesh;
    for (const model::Primitive& primitive : asset.meshes[static_cast<std::size_t>(mesh)].primitives) {
      for (std::uint32_t v = 0; v < primitive.vertex_count; ++v) {
        const glm::vec3& p = asset.vertices[primitive.first_vertex + v].position;
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
      }
    }
    hi.z = std::min(hi.z, 0.0f);
    if (lo.x < hi.x && lo.y < hi.y && lo.z < hi.z) it->second = {desk, lo, hi};
    return it->second;
  }

  // How far the instrument passes through its music stand's desk (a slide dipped too far goes
  // through the music): any edge of the instrument's triangles crossing the desk's panel, measured
  // inward from the panel's nearest side (0 = clear). The panel is the desk mesh's outline with
  // its face at z = 0 of the desk's frame, the thickness behind it
  // (content/generator/props.hpp); the ledge in front of it is left out.
  void instrument_clear_of_desk(const std::string& who, const stage::PlacedModel& horn,
                                const stage::PlacedModel& stand) {
    const DeskPanel& panel = desk_panel(*stand.asset);
    if (panel.node < 0) return;
    const glm::vec3 lo = panel.lo, hi = panel.hi;
    world_of(stand, stand_world_);
    const glm::mat4 into_desk = glm::inverse(stand_world_[static_cast<std::size_t>(panel.node)]);
    double depth = 0.0;
    std::size_t deepest_node = 0;
    const model::ModelAsset& asset = *horn.asset;
    for (std::size_t n = 0; n < asset.nodes.size(); ++n) {
      const model::Node& node = asset.nodes[n];
      if (node.mesh < 0 || node.skin >= 0) continue;
      const glm::mat4 to_desk = into_desk * horn_world_[n];
      for (const model::Primitive& primitive : asset.meshes[static_cast<std::size_t>(node.mesh)].primitives) {
        local_points_.resize(primitive.vertex_count);
        for (std::uint32_t v = 0; v < primitive.vertex_count; ++v) {
          local_points_[v] = to_desk * glm::vec4(asset.vertices[primitive.first_vertex + v].position, 1.0f);
        }
        for (std::uint32_t i = 0; i + 2 < primitive.index_count; i += 3) {
          const std::uint32_t* corner = &asset.indices[primitive.first_index + i];
          for (int e = 0; e < 3; ++e) {
            const double inward = edge_into_box(local_points_[corner[e]],
                                                local_points_[corner[(e + 1) % 3]], lo, hi);
            if (inward > depth) depth = inward, deepest_node = n;
          }
        }
      }
    }
    measure(who + ": instrument through the music stand's desk (depth; 0 = clear)", "mm", 0.0)
        .add(depth * 1000.0, t_s_, depth > 0.0 ? asset.nodes[deepest_node].name : std::string());
  }

  // A hand held in the bell (the horn's right hand: its palm_at node inside the bell): how far its
  // fingertips' pads reach through the bell's wall, by the profile the model's bell_rim carries.
  void hand_in_bell(const std::string& who, const stage::PlacedModel& horn,
                    const brass_family::BrassRig& rig) {
    const int rim = horn.asset->find_node("bell_rim");
    if (rim < 0) return;
    const model::Node& rim_node = horn.asset->nodes[static_cast<std::size_t>(rim)];
    const double rim_mm = rim_node.number("rim_radius_mm", 0.0);
    const double d0_mm = rim_node.number("flare_d0_mm", 0.0);
    const double flare_mm = rim_node.number("flare_mm", 0.0);
    if (rim_mm <= 0.0 || d0_mm <= 0.0 || flare_mm <= 0.0) return;
    const glm::mat4 into_bell = glm::inverse(horn_world_[static_cast<std::size_t>(rim)]);
    for (std::size_t side = 0; side < 2; ++side) {
      const int grip = side == 0 ? rig.grip_left : rig.grip_right;
      if (rig.hold.hands[side].palm_at.empty() || grip < 0) continue;
      // Only a grip inside the bell makes this a hand in the bell.
      const glm::vec3 g = into_bell * horn_world_[static_cast<std::size_t>(grip)][3];
      if (g.z >= 0.0f) continue;
      double through = 0.0;
      for (std::size_t f = 0; f < 5; ++f) {
        const int tip = rig.body_nodes.fingertips[side][f];
        if (tip < 0) continue;
        const glm::vec3 local = into_bell * body_world_[static_cast<std::size_t>(tip)][3];
        const double behind_mm = -static_cast<double>(local.z) * 1000.0;
        const double off_axis_mm = std::hypot(static_cast<double>(local.x), static_cast<double>(local.y)) * 1000.0;
        if (behind_mm < 0.0) {
          through = std::max(through, -behind_mm);  // out past the rim
          continue;
        }
        const double wall_mm = rim_mm * d0_mm / (std::min(behind_mm, flare_mm) + d0_mm);
        through = std::max(through, off_axis_mm + kPadRadiusMm[f] - wall_mm);
      }
      measure(who + (side == 0 ? ": left" : ": right") +
                  " fingertips through the bell's wall or out past its rim",
              "mm", 0.0)
          .add(through, t_s_);
    }
  }

  // The worst finger joint (index .. little) of a posed hand past its limits.
  void finger_limits(const std::string& who, const model::ModelAsset& asset,
                     const model::ModelPose& pose, const stage::BodyNodes& nodes) {
    double worst = 0.0;
    int worst_node = -1;
    for (std::size_t side = 0; side < 2; ++side) {
      for (std::size_t f = 1; f < 5; ++f) {
        for (std::size_t j = 0; j < 3; ++j) {
          const int node = nodes.fingers[side][f][j];
          const int child = j < 2 ? nodes.fingers[side][f][j + 1] : nodes.fingertips[side][f];
          if (node < 0 || child < 0) continue;
          const double past = stage::past_limit(pose.local[static_cast<std::size_t>(node)].rotation,
                                         asset.nodes[static_cast<std::size_t>(child)].rest.translation,
                                         static_cast<int>(side), limits_[f][j]);
          if (past > worst) worst = past, worst_node = node;
        }
      }
    }
    measure(who + ": finger joints past their limits (worst joint)", "deg", 0.5)
        .add(worst, t_s_, worst_node < 0 ? std::string() : asset.nodes[static_cast<std::size_t>(worst_node)].name);
  }

  void brass(ecs::Entity performer, const brass_family::BrassRig& rig) {
    const ecs::World& world = stage_.world();
    const auto* horn = world.try_get<stage::PlacedModel>(rig.horn);
    // A user's character is measured on its stand-in, whose joints its own follow exactly.
    const auto* body =
        stage::posed_body(world.try_get<stage::PlacedModel>(rig.body), rig.body_retarget);
    if (horn == nullptr || body == nullptr) return;
    const std::string who = name_of(world, performer);
    world_of(*horn, horn_world_);
    world_of(*body, body_world_);
    // The slide moves in this frame when it is moving now or has moved since the last frame.
    bool slide_moves = false;
    if (const auto* slide = world.try_get<components::Slide>(rig.instrument)) {
      const auto [last, added] = last_slide_mm_.try_emplace(performer.bits(), slide->extension_mm);
      slide_moves = slide->speed_mm_per_s != 0.0 || (!added && last->second != slide->extension_mm);
      last->second = slide->extension_mm;
    }
    joint_speeds(who, *body, rig.body_nodes.fingers,
                 slide_moves ? &rig.body_nodes.arm_right : nullptr);
    const model::ModelAsset& body_asset = *body->asset;
    const auto body_point = [&](const std::string& node) -> const glm::mat4* {
      const int n = body_asset.find_node(node);
      return n < 0 ? nullptr : &body_world_[static_cast<std::size_t>(n)];
    };
    if (const auto* valve = world.try_get<components::Valve>(rig.instrument)) {
      for (std::size_t v = 0; v < brass_family::BrassRig::kMaxValves; ++v) {
        if (rig.valves[v] < 0 || valve->press[v] <= 0.5f) continue;
        // The finger the hold puts on this valve's button; when it puts none (a palm hold), the
        // right index, middle, ring and little fingers on valves 1-4, as players finger them.
        bool held = false;
        for (const auto& hand : rig.fingertip_on) {
          for (const int node : hand) held = held || node == rig.valves[v];
        }
        for (std::size_t side = 0; side < 2; ++side) {
          for (std::size_t f = 0; f < 5; ++f) {
            const bool on_it = held ? rig.fingertip_on[side][f] == rig.valves[v]
                                    : side == 1 && f == v + 1;
            if (!on_it) continue;
            const int tip = rig.body_nodes.fingertips[side][f];
            if (tip < 0) continue;
            const glm::vec3 button = origin(horn_world_[static_cast<std::size_t>(rig.valves[v])]);
            measure(who + ": pressing fingertip to its button top", "mm", 10.0, true)
                .add(static_cast<double>(glm::distance(
                                       origin(body_world_[static_cast<std::size_t>(tip)]), button)) *
                                   1000.0, t_s_);
          }
        }
      }
    }
    // A left hand wrapped round the valve casings: its origin (the wrist) to the casings' axis.
    if (rig.hold.hands[0].wraps_valves && rig.valves[1] >= 0 && rig.body_nodes.arm_left.end >= 0) {
      const int casing = rig.valves[1];
      const int parent = horn->asset->nodes[static_cast<std::size_t>(casing)].parent;
      const glm::mat3 frame = parent >= 0 ? glm::mat3(horn_world_[static_cast<std::size_t>(parent)])
                                          : glm::mat3(horn->root);
      const glm::vec3 wrist =
          origin(body_world_[static_cast<std::size_t>(rig.body_nodes.arm_left.end)]);
      measure(who + ": left hand's origin (wrist) to the valve casings' axis", "mm", 60.0)
          .add(distance_to_line(
                                 wrist, origin(horn_world_[static_cast<std::size_t>(casing)]),
                                 frame * rig.valve_axis[1]) *
                             1000.0, t_s_);
    }
    // Palms that hold a grip (the hold's palm_at): the palm's centre to it.
    for (std::size_t side = 0; side < 2; ++side) {
      const int grip = side == 0 ? rig.grip_left : rig.grip_right;
      const int palm = side == 0 ? rig.body_nodes.grip_left : rig.body_nodes.grip_right;
      if (rig.hold.hands[side].palm_at.empty() || grip < 0 || palm < 0) continue;
      const double distance =
          static_cast<double>(glm::distance(origin(body_world_[static_cast<std::size_t>(palm)]),
                                            origin(horn_world_[static_cast<std::size_t>(grip)]))) *
          1000.0;
      measure(who + (side == 0 ? ": left palm to its grip (" : ": right palm to its grip (") +
                  rig.hold.hands[side].palm_at + ")",
              "mm", 20.0)
          .add(distance, t_s_);
    }
    if (const auto* slide = world.try_get<components::Slide>(rig.instrument);
        slide != nullptr && slide->speed_mm_per_s != 0.0 && rig.grip_right >= 0 &&
        rig.body_nodes.grip_right >= 0) {
      const glm::vec3 palm = origin(body_world_[static_cast<std::size_t>(rig.body_nodes.grip_right)]);
      const glm::vec3 brace = origin(horn_world_[static_cast<std::size_t>(rig.grip_right)]);
      measure(who + ": right palm to the slide grip while the slide moves", "mm", 20.0)
          .add(static_cast<double>(glm::distance(palm, brace)) * 1000.0, t_s_);
    }
    std::vector<glm::vec3> hands;
    for (const char* node : {"hand_l", "hand_r"}) {
      if (const glm::mat4* m = body_point(node)) hands.push_back(origin(*m));
    }
    for (int f = 0; f < 5; ++f) {
      for (const char* side : {"_l", "_r"}) {
        if (const glm::mat4* m = body_point(std::string(kFingerNames[f]) + "_tip" + side)) {
          hands.push_back(origin(*m));
        }
      }
    }
    head_clearance(who, rig.body_nodes.head, hands);
    for (const int elbow : {rig.body_nodes.arm_left.lower, rig.body_nodes.arm_right.lower}) {
      if (elbow >= 0) hands.push_back(origin(body_world_[static_cast<std::size_t>(elbow)]));
    }
    torso_clearance(who, rig.body_nodes.hips, rig.body_nodes.neck, hands);
    arms_clear_of_instrument(who, *horn, rig.body_nodes);
    if (const auto* stand = world.try_get<stage::PlacedModel>(rig.stand)) {
      instrument_clear_of_desk(who, *horn, *stand);
    }
    hand_in_bell(who, *horn, rig);
    finger_limits(who, body_asset, body->pose, rig.body_nodes);
  }

  void piano(ecs::Entity performer, const piano_family::PianoRig& rig, double t_s, double dt_s) {
    const ecs::World& world = stage_.world();
    const auto* piano = world.try_get<stage::PlacedModel>(rig.piano);
    if (piano == nullptr) return;
    const std::string who = name_of(world, performer);
    world_of(*piano, horn_world_);
    std::vector<glm::vec3> tips;
    // A user's hands play: a hand model's stand-in, else a user's character's own (its
    // stand-in's fingertips and last joints).
    const auto* body =
        stage::posed_body(world.try_get<stage::PlacedModel>(rig.body), rig.body_retarget);
    if (body != nullptr) {
      world_of(*body, body_world_);
      joint_speeds(who, *body, rig.body_nodes.fingers);
    }
    const stage::PlacedModel* own = nullptr;
    const stage::BodyNodes* own_nodes = nullptr;
    if (rig.hands_retarget) {
      own = &rig.hands_retarget->proxy;
      own_nodes = &rig.hands_nodes;
      world_of(*own, hand_world_);
    } else if (rig.body_retarget && body != nullptr) {
      own = body;
      own_nodes = &rig.body_nodes;
    }
    for (std::size_t side = 0; side < 2; ++side) {
      const auto* hand = world.try_get<stage::PlacedModel>(rig.hand_models[side]);
      if (hand != nullptr && own == nullptr) {
        world_of(*hand, hand_world_);
        FingerNodes fingers;
        for (auto& hand_fingers : fingers) {
          for (auto& finger : hand_fingers) finger.fill(-1);
        }
        fingers[0] = rig.finger_bones[side];
        joint_speeds(who, *hand, fingers);
      }
      const std::size_t body_side = side == 0 ? 1 : 0;  // the rig's _r is its side 1
      // The fingertip and its last joint (-1 when the hand has none).
      const auto joints = [&](std::size_t f, glm::vec3& tip, glm::vec3& dip) {
        if (own != nullptr) {
          const int t = own_nodes->fingertips[body_side][f];
          const int d = own_nodes->fingers[body_side][f][2];
          if (t < 0 || d < 0) return false;
          const std::vector<glm::mat4>& w = own == body ? body_world_ : hand_world_;
          tip = origin(w[static_cast<std::size_t>(t)]);
          dip = origin(w[static_cast<std::size_t>(d)]);
          return true;
        }
        if (hand == nullptr) return false;
        const std::string suffix = side == 0 ? "_r" : "_l";
        const int t = hand->asset->find_node(std::string(kFingerNames[f]) + "_tip" + suffix);
        if (t < 0) return false;
        tip = origin(hand_world_[static_cast<std::size_t>(t)]);
        const int d = hand->asset->find_node(std::string(kFingerNames[f]) + "_3" + suffix);
        dip = d >= 0 ? origin(hand_world_[static_cast<std::size_t>(d)]) : tip + glm::vec3(0, 1, 0);
        return true;
      };
      collect_hand_capsules(rig, side, own, own_nodes, body_side, hand);
      for (std::size_t f = 0; f < 5; ++f) {
        glm::vec3 tip, dip;
        if (!joints(f, tip, dip)) continue;
        tips.push_back(tip);
        const auto* finger = world.try_get<components::Finger>(rig.fingers[side][f]);
        if (finger == nullptr || finger->press_depth < 0.999 || finger->key < 0 ||
            finger->key > 127) {
          continue;
        }
        const int key_node = rig.key_nodes[static_cast<std::size_t>(finger->key)];
        if (key_node < 0) continue;
        // The key's top surface is its node's y = 0 plane (the pivot at the top's back edge). The
        // flesh ends in a rounded cap whose outermost point is the tip node: the pad's lowest
        // point is the cap's centre less its radius.
        const glm::vec3 last_bone = tip - dip;
        const float radius = static_cast<float>(kPadRadiusMm[f] / 1000.0);
        const glm::vec3 cap_centre = tip - radius * glm::normalize(last_bone);
        const glm::mat4 key_frame = glm::inverse(horn_world_[static_cast<std::size_t>(key_node)]);
        const glm::vec3 centre_local = key_frame * glm::vec4(cap_centre, 1.0f);
        // Key frames carry no scale: a length in it is a length in the world.
        // The thumb strikes with the side of its tip: reported on its own.
        PoseMeasure& pad = measure(who + (f == 0 ? ": thumb's" : ": pressing fingertip's") +
                                       " pad above its key's top at key bottom",
                                   "mm", 3.0);
        pad.two_sided = true;
        // The pad's lowest point over the key's top: off its outline (a black key struck in front
        // of its front edge, a key missed to the side) it presses nothing.
        // The key's outline, from its mesh when the rig was bound (PianoRig::key_half_width_mm).
        const auto key = static_cast<std::size_t>(finger->key);
        const double half_width_m = rig.key_half_width_mm[key] / 1000.0;
        const double length_m = rig.key_length_mm[key] / 1000.0;
        const double off_side =
            std::max(0.0, std::abs(static_cast<double>(centre_local.x)) - half_width_m);
        const double off_end = std::max({0.0, -static_cast<double>(centre_local.z),
                                         static_cast<double>(centre_local.z) - length_m});
        measure(who + ": pressing pad off its key's top (0 = on it)", "mm", 1.0)
            .add(std::hypot(off_side, off_end) * 1000.0, t_s_,
                 (side == 0 ? "right " : "left ") + std::string(kFingerNames[f]) + " on key " +
                     std::to_string(finger->key) +
                     (off_end > off_side ? (centre_local.z > 0.0f ? ", in front of it" : ", behind it")
                                         : ", beside it"));
        pad.add((static_cast<double>(centre_local.y) - kPadRadiusMm[f] / 1000.0) * 1000.0, t_s_,
                (side == 0 ? "right " : "left ") + std::string(kFingerNames[f]) + " on key " +
                    std::to_string(finger->key));
      }
    }
    hands_apart(who);
    // The keys: how far each is down, and whether a note of it sounds (or is being struck or
    // released: 0.1 s before the onset to 0.1 s after the offset).
    KeyTally& tally = key_tallies_[who];
    for (int key = 0; key < 128; ++key) {
      const int node = rig.key_nodes[static_cast<std::size_t>(key)];
      const double dip = rig.key_dip_rad[static_cast<std::size_t>(key)];
      if (node < 0 || dip <= 0.0) continue;
      tally.all_seconds += dt_s;
      const glm::quat& r = piano->pose.local[static_cast<std::size_t>(node)].rotation;
      const double angle = 2.0 * std::asin(std::min(
                                     1.0, static_cast<double>(glm::length(glm::vec3(r.x, r.y, r.z)))));
      const double down = angle / dip;
      if (down <= 1e-4) continue;
      bool sounding = false;
      bool striking = false;
      for (const auto& [e, note] : notes_) {
        if (note->pitch != key || note->performer != performer) continue;
        sounding = sounding || note->sounding;
        striking = striking || (t_s >= note->onset_s - 0.1 && t_s <= note->offset_s + 0.1);
      }
      tally.down_seconds += dt_s;
      if (down > 0.25 && down < 0.75 && !sounding) {
        tally.mid_silent += dt_s;
        if (!striking) {
          tally.mid_resting += dt_s;
          if (tally.hanging_key < 0) tally.hanging_key = key, tally.hanging_at_s = t_s;
        }
      }
    }
    if (body != nullptr) toes_on_pedals(who, rig, t_s);
    head_tips_ = tips;
    if (body != nullptr) head_clearance(who, rig.body_nodes.head, head_tips_);
  }

  // An organist's toes: each one holding its pedal all the way down is on the pedal's top, inside
  // its outline (in the pedal's frame: x across, y up from the top, z along from the hinge).
  void toes_on_pedals(const std::string& who, const piano_family::PianoRig& rig, double t_s) {
    using piano::PedalGeometry;
    for (int foot : {piano_family::kRightFoot, piano_family::kLeftFoot}) {
      const components::Foot* state = piano_family::foot_of(stage_.world(), rig, foot);
      if (state == nullptr || state->press_depth < 0.999 || state->key < 0 || state->key > 127) {
        continue;
      }
      const int pedal = rig.pedal_nodes[static_cast<std::size_t>(state->key)];
      const int toe = foot == piano_family::kRightFoot ? rig.body_nodes.toe_right
                                                       : rig.body_nodes.toe_left;
      if (pedal < 0 || toe < 0) continue;
      const glm::vec3 local = glm::inverse(horn_world_[static_cast<std::size_t>(pedal)]) *
                              glm::vec4(origin(body_world_[static_cast<std::size_t>(toe)]), 1.0f);
      const double length = piano::pedal_is_sharp(state->key) ? PedalGeometry::kSharpLength_m
                                                              : PedalGeometry::kNaturalLength_m;
      const double off_side = std::max(
          0.0, std::abs(static_cast<double>(local.x)) - PedalGeometry::kPedalWidth_m / 2.0);
      const double off_end = std::max({0.0, -static_cast<double>(local.z),
                                       static_cast<double>(local.z) - length});
      const double off_top = std::abs(static_cast<double>(local.y));
      measure(who + ": pressing toe off its pedal's top (0 = on it)", "mm", 3.0)
          .add(std::sqrt(off_side * off_side + off_end * off_end + off_top * off_top) * 1000.0,
               t_s, std::string(foot == piano_family::kRightFoot ? "right" : "left") +
                        " toe on pedal " + std::to_string(state->key));
    }
  }

  // The pianist's hand `side` as capsules (world space): each finger's bones, knuckle to tip, and
  // the palm across the knuckles. From a user's hands (`own`) or tutti's hand model.
  void collect_hand_capsules(const piano_family::PianoRig& rig, std::size_t side,
                             const stage::PlacedModel* own, const stage::BodyNodes* own_nodes,
                             std::size_t body_side, const stage::PlacedModel* hand) {
    std::vector<HandCapsule>& out = hand_capsules_[side];
    out.clear();
    const std::vector<glm::mat4>* world = nullptr;
    piano_family::FingerChains chain{};
    if (own != nullptr) {
      world = rig.hands_retarget && own == &rig.hands_retarget->proxy ? &hand_world_ : &body_world_;
      for (std::size_t f = 0; f < 5; ++f) {
        for (std::size_t j = 0; j < 3; ++j) chain[f][j] = own_nodes->fingers[body_side][f][j];
        chain[f][3] = own_nodes->fingertips[body_side][f];
      }
    } else if (hand != nullptr) {
      world = &hand_world_;
      for (std::size_t f = 0; f < 5; ++f) {
        for (std::size_t j = 0; j < 3; ++j) chain[f][j] = rig.finger_bones[side][f][j];
        chain[f][3] = rig.finger_tips[side][f];
      }
    } else {
      return;
    }
    piano_family::collect_hand_capsules(chain, *world, out);
  }

  // How deep one hand's capsules reach into the other's: hands cross over each other, never
  // through.
  void hands_apart(const std::string& who) {
    if (hand_capsules_[0].empty() || hand_capsules_[1].empty()) return;
    double depth = 0.0;
    const HandCapsule* deepest_right = nullptr;
    const HandCapsule* deepest_left = nullptr;
    for (const HandCapsule& right : hand_capsules_[0]) {
      for (const HandCapsule& left : hand_capsules_[1]) {
        const double into = piano_family::overlap_m(right, left);
        if (into > depth) depth = into, deepest_right = &right, deepest_left = &left;
      }
    }
    measure(who + ": one hand inside the other (depth; 0 = apart)", "mm", 0.0)
        .add(depth * 1000.0, t_s_,
             deepest_right == nullptr ? std::string()
                                      : std::string("right ") + deepest_right->name + " in left " +
                                            deepest_left->name);
  }

  // A key's top in its own frame: from the pivot (its back edge, z = 0) toward the player, as
  // wide and as long as its mesh.
  void collect_notes() {
    notes_.clear();
    stage_.world().view<const components::Note>().each(
        [&](ecs::Entity e, const components::Note& note) { notes_.emplace_back(e, &note); });
  }

  void finish() {
    for (const auto& [who, tally] : key_tallies_) {
      if (tally.down_seconds <= 0.0) continue;
      // Of every animated key's seconds (all the piano's keys over the range): the figure.
      measure(who + ": keys half down (25-75 %), no note sounding, of all keys' seconds", "%",
              1.0)
          .add(100.0 * tally.mid_silent / tally.all_seconds, t_s_);
      // Of the seconds keys are off their rest (stricter, informational): a key passes through
      // half travel before its hammer escapes and after its damper falls, on every stroke and
      // release.
      measure(who + ": key-seconds half down (25-75 %) with no note of the key sounding", "%")
          .add(100.0 * tally.mid_silent / tally.down_seconds, t_s_);
      measure(who + ": ... of them outside the keys' strokes (a key left hanging)", "%", 1.0)
          .add(100.0 * tally.mid_resting / tally.down_seconds, tally.hanging_at_s,
               tally.hanging_key < 0 ? std::string()
                                     : "the first: key " + std::to_string(tally.hanging_key));
    }
  }

 private:
  stage::Stage& stage_;
  PoseReport& report_;
  std::vector<glm::mat4> horn_world_, body_world_, hand_world_, stand_world_;
  std::vector<glm::vec3> local_points_;
  std::vector<glm::vec3> head_tips_;
  stage::FingerJointLimits limits_;
  std::vector<std::pair<ecs::Entity, const components::Note*>> notes_;
  // Each pianist's keys over the checked range (seconds summed over keys).
  struct KeyTally {
    double all_seconds = 0.0;   // every animated key
    double down_seconds = 0.0;  // keys off their rest
    double mid_silent = 0.0;    // half down with no note of the key sounding
    double mid_resting = 0.0;   // ... and not being struck or released
    int hanging_key = -1;       // the first key seen left hanging, and when
    double hanging_at_s = 0.0;
  };
  std::map<std::string, KeyTally> key_tallies_;
  double t_s_ = 0.0;
  double dt_s_ = 1.0 / 30.0;
  std::map<const stage::PlacedModel*, std::vector<glm::quat>> last_rotations_;
  std::vector<std::uint8_t> joint_kind_;
  std::map<std::uint64_t, double> last_slide_mm_;  // per performer entity
  std::array<std::vector<HandCapsule>, 2> hand_capsules_;  // the pianist posed: right, left
  std::map<const model::ModelAsset*, DeskPanel> desk_panels_;
};

}  // namespace

double PoseMeasure::percentile(double p) const {
  if (samples.empty()) return 0.0;
  std::vector<double> sorted = samples;
  std::sort(sorted.begin(), sorted.end());
  const double at = std::clamp(p, 0.0, 1.0) * static_cast<double>(sorted.size() - 1);
  return sorted[static_cast<std::size_t>(std::ceil(at))];
}

void PoseMeasure::add(double value, double t_s, const std::string& of) {
  const auto size = [&](double x) { return two_sided ? std::abs(x) : x; };
  if (samples.empty() || size(value) > size(samples[worst_index_])) {
    worst_index_ = samples.size();
    worst_at_s = t_s;
    worst_of = of;
  }
  samples.push_back(value);
}

bool PoseMeasure::within_limit() const {
  if (limit < 0.0) return true;
  if (two_sided) return std::max(-percentile(0.0), worst()) <= limit;
  return (by_p95 ? percentile(0.95) : worst()) <= limit;
}

const PoseMeasure* PoseReport::find(const std::string& name) const {
  for (const PoseMeasure& m : measures) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

Result<PoseReport> check_pose(stage::Stage& stage, const PoseCheckOptions& options) {
  if (options.fps < 1 || options.fps > 240) return Error{"fps must be 1..240"};
  if (!(options.to_s > options.from_s)) return Error{"nothing to check: the range is empty"};
  auto limits = stage::load_finger_joint_limits(options.content_dir);
  if (!limits) return limits.error();
  PoseReport report;
  Checker checker(stage, report, *limits);
  checker.collect_notes();
  const double dt = 1.0 / options.fps;
  const auto frames = static_cast<std::int64_t>(std::ceil((options.to_s - options.from_s) * options.fps));
  for (std::int64_t k = 0; k < frames; ++k) {
    const double t = options.from_s + static_cast<double>(k) * dt;
    stage.run({t, dt});
    ++report.frames;
    checker.at_time(t, dt);
    for (ecs::Entity performer : stage.performers()) {
      if (const auto* rig = stage.world().try_get<brass_family::BrassRig>(performer)) {
        checker.brass(performer, *rig);
      }
      if (const auto* rig = stage.world().try_get<piano_family::PianoRig>(performer)) {
        checker.piano(performer, *rig, t, dt);
      }
    }
  }
  checker.finish();
  return report;
}

std::string format_pose_report(const PoseReport& report) {
  std::string out;
  char line[512];
  std::snprintf(line, sizeof line, "%zu frames\n%-80s %7s %7s %7s %7s %7s %10s  %s\n",
                report.frames, "measure", "samples", "min", "median", "p95", "max", "limit",
                "worst at");
  out += line;
  for (const PoseMeasure& m : report.measures) {
    char limit[32] = "";
    if (m.limit >= 0.0) {
      std::snprintf(limit, sizeof limit, "%s%g %s", m.by_p95 ? "p95<=" : m.two_sided ? "|x|<=" : "<=",
                    m.limit, m.within_limit() ? "ok" : "OVER");
    }
    char at[96] = "";
    if (m.samples.size() > 1 || !m.worst_of.empty()) {
      std::snprintf(at, sizeof at, "%.2f s%s%s%s", m.worst_at_s, m.worst_of.empty() ? "" : " (",
                    m.worst_of.c_str(), m.worst_of.empty() ? "" : ")");
    }
    std::snprintf(line, sizeof line, "%-80s %7zu %7.1f %7.1f %7.1f %7.1f %10s  %s\n",
                  (m.name + " (" + m.unit + ")").c_str(), m.samples.size(), m.percentile(0.0),
                  m.percentile(0.5), m.percentile(0.95), m.worst(), limit, at);
    out += line;
  }
  return out;
}

}  // namespace tutti::cli
