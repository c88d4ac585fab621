// SPDX-License-Identifier: MIT
// The brass family's `check-pose` measures (stage/pose_checker.hpp): each pressing fingertip on
// its valve button, the palms on their grips, a left hand round the valve casings, the slide
// hand while the slide moves, fingertips in the bell, and the measures every family shares
// (joint speeds, hands clear of the head and torso, the instrument clear of the arms and the
// music stand, finger joint limits).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <tutti/brass/brass_components.hpp>
#include <tutti/brass/brass_plugin.hpp>
#include <tutti/components/slide.hpp>
#include <tutti/components/valve.hpp>
#include <tutti/stage/body_retarget.hpp>
#include <tutti/stage/pose_checker.hpp>
#include <vector>

namespace tutti::brass {
namespace {

using stage::origin;
using stage::pose::distance_to_line;
using stage::pose::kFingerNames;
using stage::pose::kPadRadiusMm;

// A hand held in the bell (the horn's right hand: its palm_at node inside the bell): how far its
// fingertips' pads reach through the bell's wall, by the profile the model's bell_rim carries.
void hand_in_bell(stage::PoseChecker& c, const std::string& who, const stage::PlacedModel& horn,
                  const BrassRig& rig) {
  const int rim = horn.asset->find_node("bell_rim");
  if (rim < 0) return;
  const model::Node& rim_node = horn.asset->nodes[static_cast<std::size_t>(rim)];
  const double rim_mm = rim_node.number("rim_radius_mm", 0.0);
  const double d0_mm = rim_node.number("flare_d0_mm", 0.0);
  const double flare_mm = rim_node.number("flare_mm", 0.0);
  if (rim_mm <= 0.0 || d0_mm <= 0.0 || flare_mm <= 0.0) return;
  const glm::mat4 into_bell = glm::inverse(c.instrument_world()[static_cast<std::size_t>(rim)]);
  for (std::size_t side = 0; side < 2; ++side) {
    const int grip = side == 0 ? rig.grip_left : rig.grip_right;
    if (rig.hold.hands[side].palm_at.empty() || grip < 0) continue;
    // Only a grip inside the bell makes this a hand in the bell.
    const glm::vec3 g = into_bell * c.instrument_world()[static_cast<std::size_t>(grip)][3];
    if (g.z >= 0.0f) continue;
    double through = 0.0;
    for (std::size_t f = 0; f < 5; ++f) {
      const int tip = rig.body_nodes.fingertips[side][f];
      if (tip < 0) continue;
      const glm::vec3 local = into_bell * c.body_world()[static_cast<std::size_t>(tip)][3];
      const double behind_mm = -static_cast<double>(local.z) * 1000.0;
      const double off_axis_mm =
          std::hypot(static_cast<double>(local.x), static_cast<double>(local.y)) * 1000.0;
      if (behind_mm < 0.0) {
        through = std::max(through, -behind_mm);  // out past the rim
        continue;
      }
      const double wall_mm = rim_mm * d0_mm / (std::min(behind_mm, flare_mm) + d0_mm);
      through = std::max(through, off_axis_mm + kPadRadiusMm[f] - wall_mm);
    }
    c.measure(who + (side == 0 ? ": left" : ": right") +
                  " fingertips through the bell's wall or out past its rim",
              "mm", 0.0)
        .add(through, c.t_s());
  }
}

// One brass player in the frame just posed.
void check_brass_player(stage::PoseChecker& c, ecs::Entity performer, const BrassRig& rig) {
  const ecs::World& world = c.world();
  const auto* horn = world.try_get<stage::PlacedModel>(rig.horn);
  // A user's character is measured on its stand-in, whose joints its own follow exactly.
  const auto* body =
      stage::posed_body(world.try_get<stage::PlacedModel>(rig.body), rig.body_retarget);
  if (horn == nullptr || body == nullptr) return;
  const std::string who = c.performer_name(performer);
  stage::pose::world_of(*horn, c.instrument_world());
  stage::pose::world_of(*body, c.body_world());
  // The slide moves in this frame when it is moving now or has moved since the last frame.
  bool slide_moves = false;
  if (const auto* slide = world.try_get<components::Slide>(rig.instrument)) {
    auto& last_slide_mm = c.family_state<std::map<std::uint64_t, double>>("brass: slide extension");
    const auto [last, added] = last_slide_mm.try_emplace(performer.bits(), slide->extension_mm);
    slide_moves = slide->speed_mm_per_s != 0.0 || (!added && last->second != slide->extension_mm);
    last->second = slide->extension_mm;
  }
  c.joint_speeds(who, *body, rig.body_nodes.fingers,
                 slide_moves ? &rig.body_nodes.arm_right : nullptr,
                 "slide arm's fastest joint while the slide moves");
  const model::ModelAsset& body_asset = *body->asset;
  const auto body_point = [&](const std::string& node) -> const glm::mat4* {
    const int n = body_asset.find_node(node);
    return n < 0 ? nullptr : &c.body_world()[static_cast<std::size_t>(n)];
  };
  if (const auto* valve = world.try_get<components::Valve>(rig.instrument)) {
    for (std::size_t v = 0; v < BrassRig::kMaxValves; ++v) {
      if (rig.valves[v] < 0 || valve->press[v] <= 0.5f) continue;
      // The finger the hold puts on this valve's button; when it puts none (a palm hold), the
      // right index, middle, ring and little fingers on valves 1-4, as players finger them.
      bool held = false;
      for (const auto& hand : rig.fingertip_on) {
        for (const int node : hand) held = held || node == rig.valves[v];
      }
      for (std::size_t side = 0; side < 2; ++side) {
        for (std::size_t f = 0; f < 5; ++f) {
          const bool on_it =
              held ? rig.fingertip_on[side][f] == rig.valves[v] : side == 1 && f == v + 1;
          if (!on_it) continue;
          const int tip = rig.body_nodes.fingertips[side][f];
          if (tip < 0) continue;
          const glm::vec3 button =
              origin(c.instrument_world()[static_cast<std::size_t>(rig.valves[v])]);
          c.measure(who + ": pressing fingertip to its button top", "mm", 10.0, true)
              .add(static_cast<double>(glm::distance(
                       origin(c.body_world()[static_cast<std::size_t>(tip)]), button)) *
                       1000.0,
                   c.t_s());
        }
      }
    }
  }
  // A left hand wrapped round the valve casings: its origin (the wrist) to the casings' axis.
  if (rig.hold.hands[0].wraps_valves && rig.valves[1] >= 0 && rig.body_nodes.arm_left.end >= 0) {
    const int casing = rig.valves[1];
    const int parent = horn->asset->nodes[static_cast<std::size_t>(casing)].parent;
    const glm::mat3 frame = parent >= 0
                                ? glm::mat3(c.instrument_world()[static_cast<std::size_t>(parent)])
                                : glm::mat3(horn->root);
    const glm::vec3 wrist =
        origin(c.body_world()[static_cast<std::size_t>(rig.body_nodes.arm_left.end)]);
    c.measure(who + ": left hand's origin (wrist) to the valve casings' axis", "mm", 60.0)
        .add(distance_to_line(wrist, origin(c.instrument_world()[static_cast<std::size_t>(casing)]),
                              frame * rig.valve_axis[1]) *
                 1000.0,
             c.t_s());
  }
  // Palms that hold a grip (the hold's palm_at): the palm's centre to it.
  for (std::size_t side = 0; side < 2; ++side) {
    const int grip = side == 0 ? rig.grip_left : rig.grip_right;
    const int palm = side == 0 ? rig.body_nodes.grip_left : rig.body_nodes.grip_right;
    if (rig.hold.hands[side].palm_at.empty() || grip < 0 || palm < 0) continue;
    const double distance = static_cast<double>(glm::distance(
                                origin(c.body_world()[static_cast<std::size_t>(palm)]),
                                origin(c.instrument_world()[static_cast<std::size_t>(grip)]))) *
                            1000.0;
    c.measure(who + (side == 0 ? ": left palm to its grip (" : ": right palm to its grip (") +
                  rig.hold.hands[side].palm_at + ")",
              "mm", 20.0)
        .add(distance, c.t_s());
  }
  if (const auto* slide = world.try_get<components::Slide>(rig.instrument);
      slide != nullptr && slide->speed_mm_per_s != 0.0 && rig.grip_right >= 0 &&
      rig.body_nodes.grip_right >= 0) {
    const glm::vec3 palm =
        origin(c.body_world()[static_cast<std::size_t>(rig.body_nodes.grip_right)]);
    const glm::vec3 brace = origin(c.instrument_world()[static_cast<std::size_t>(rig.grip_right)]);
    c.measure(who + ": right palm to the slide grip while the slide moves", "mm", 20.0)
        .add(static_cast<double>(glm::distance(palm, brace)) * 1000.0, c.t_s());
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
  c.head_clearance(who, rig.body_nodes.head, hands);
  for (const int elbow : {rig.body_nodes.arm_left.lower, rig.body_nodes.arm_right.lower}) {
    if (elbow >= 0) hands.push_back(origin(c.body_world()[static_cast<std::size_t>(elbow)]));
  }
  c.torso_clearance(who, rig.body_nodes.hips, rig.body_nodes.neck, hands);
  c.arms_clear_of_instrument(who, *horn, rig.body_nodes);
  if (const auto* stand = world.try_get<stage::PlacedModel>(rig.stand)) {
    c.instrument_clear_of_desk(who, *horn, *stand);
  }
  hand_in_bell(c, who, *horn, rig);
  c.finger_limits(who, body_asset, body->pose, rig.body_nodes);
}

}  // namespace

void BrassPlugin::check_pose(stage::PoseChecker& checker, ecs::Entity performer) const {
  if (const auto* rig = checker.world().try_get<BrassRig>(performer)) {
    check_brass_player(checker, performer, *rig);
  }
}

}  // namespace tutti::brass
