// SPDX-License-Identifier: MIT
#include <tutti/piano/pose_piano.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <tutti/components/finger.hpp>
#include <tutti/components/hand.hpp>
#include <tutti/piano/idle_fingers_yield.hpp>
#include <tutti/piano/own_hands.hpp>
#include <tutti/piano/piano_components.hpp>
#include <tutti/stage/body_retarget.hpp>
#include <tutti/stage/fingertip_reach.hpp>
#include <tutti/stage/performer_rig.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::piano_family {
namespace {

using stage::PlacedModel;

// Keyboard frame (mm; x along the keys, y into them, z up) → the piano's `keyboard` node frame
// (metres, glTF axes): (x, y, z) → (x, z, -y) / 1000.
glm::vec3 keyboard_point(double x_mm, double y_mm, double z_mm) {
  return {static_cast<float>(x_mm / 1000.0), static_cast<float>(z_mm / 1000.0),
          static_cast<float>(-y_mm / 1000.0)};
}

// Wrist of a hand model placed at its middle-finger knuckle (the Hand reference point): behind
// it by about a palm and a little higher, in the keyboard frame (mm).
constexpr double kWristBehindKnuckleMm = 85.0;
constexpr double kWristAboveKnuckleMm = 12.0;

void pose_pianist_body(PlacedModel& body, PianoRig& rig, const std::array<glm::vec3, 2>& wrists) {
  const model::ModelAsset& asset = *body.asset;
  pose_seated_pianist(rig.body_nodes, asset, body.pose);
  for (int side : {0, 1}) {
    const int hand = rig.rig_hands[static_cast<std::size_t>(side)];
    if (hand >= 0) body.pose.local[static_cast<std::size_t>(hand)].scale = glm::vec3(0.0f);
  }
  std::vector<glm::mat4>& world = rig.scratch_world;
  world.resize(asset.nodes.size());
  model::compute_world_matrices(asset, body.pose, body.root, world);
  stage::solve_two_bone_ik(asset, rig.body_nodes.arm_right, wrists[0], pianist_elbow_pole(body.root, 0),
                           body.root, body.pose, world);
  stage::solve_two_bone_ik(asset, rig.body_nodes.arm_left, wrists[1], pianist_elbow_pole(body.root, 1),
                           body.root, body.pose, world);
}

// The key's top surface height (keyboard frame, mm) at depth y_mm, the key turned `angle` about
// its rail.
double key_surface_z_mm(const PianoRig& rig, int key, double angle, double y_mm) {
  const auto k = static_cast<std::size_t>(key);
  const double rail_y = rig.key_back_y_mm[k] + 1000.0 * static_cast<double>(rig.key_pivot_behind_m[k]);
  return rig.key_top_z_mm[k] - (rail_y - y_mm) * std::tan(angle);
}

// How far the seating may turn a finger's joints past the plan. Centring a pad on its key's
// centre line takes at most kMostSpreadCorrectionRad: a key further away is the plan's to reach
// (the hand's place, the finger's range), not a finger's to twist toward. Only a pad that would
// press beside or in front of its key's top (the thumb's tilted joint carries it there on a black
// key) turns further, and only as far as the key's outline less kPadInsideKeyMm.
constexpr double kMostSpreadCorrectionRad = 0.1;
constexpr double kMostSpreadOntoKeyRad = 0.35;
constexpr double kMostCurlOntoKeyRad = 0.35;
constexpr double kPadInsideKeyMm = 1.0;

// A seated finger's turn past its planned pose: its first joint's stroke (about -X) and spread
// (about the vertical) and its next joint's flexion (curl).
struct PadSeat {
  double stroke = 0.0;
  double spread = 0.0;
  double curl = 0.0;
};

// The pad of a pressing finger against its key (keyboard frame, mm): its lowest point's height
// over the key's top there, its centre's distance across from the key's centre line, and its
// centre's depth into the keys.
struct PadOnKey {
  double height_mm = 0.0;
  double side_mm = 0.0;
  double depth_mm = 0.0;
  double arm_mm = 0.0;  // the pad's horizontal distance from the finger's first joint
};

class PadSeater {
 public:
  PadSeater(PianoRig& rig, PlacedModel& hand_model, const components::Finger& finger, std::size_t side,
            std::size_t f, double key_angle)
      : rig_(rig), hand_model_(hand_model), finger_(finger), side_(side), f_(f), angle_(key_angle),
        mirror_(side == 0 ? 1.0f : -1.0f) {}

  void pose(const PadSeat& seat) {
    const auto& bones = rig_.finger_bones[side_][f_];
    const double stroke = (f_ == 0 ? finger_.abduction_rad : finger_.mcp_flexion_rad) + seat.stroke;
    hand_model_.pose.local[static_cast<std::size_t>(bones[0])].rotation =
        glm::angleAxis(-mirror_ * static_cast<float>(finger_.spread_rad + seat.spread), glm::vec3(0, 1, 0)) *
        glm::angleAxis(static_cast<float>(stroke), glm::vec3(-1, 0, 0));
    if (bones[1] >= 0) {
      const double curl = (f_ == 0 ? finger_.mcp_flexion_rad : finger_.pip_flexion_rad) + seat.curl;
      hand_model_.pose.local[static_cast<std::size_t>(bones[1])].rotation =
          glm::angleAxis(static_cast<float>(curl), glm::vec3(-1, 0, 0));
    }
  }

  PadOnKey measure(const PadSeat& seat) {
    pose(seat);
    const model::ModelAsset& asset = *hand_model_.asset;
    std::vector<glm::mat4>& hand_world = rig_.scratch_world;
    hand_world.resize(asset.nodes.size());
    model::compute_world_matrices(asset, hand_model_.pose, hand_model_.root, hand_world);
    const auto in_keyboard = [&](int node) {
      return glm::vec3(rig_.world_to_keyboard * hand_world[static_cast<std::size_t>(node)][3]);
    };
    const auto& bones = rig_.finger_bones[side_][f_];
    // glTF keyboard frame (m): x, y up, -z into the keys.
    const glm::vec3 tip_at = in_keyboard(rig_.finger_tips[side_][f_]);
    const glm::vec3 last_joint = in_keyboard(bones[2]);
    const glm::vec3 root = in_keyboard(bones[0]);
    const glm::vec3 along = glm::normalize(tip_at - last_joint);
    const double radius = static_cast<double>(stage::kFingertipPadRadiusM[f_]) * 1000.0;
    const glm::vec3 centre = tip_at - static_cast<float>(radius / 1000.0) * along;
    const auto key = static_cast<std::size_t>(finger_.key);
    PadOnKey pad;
    pad.depth_mm = -1000.0 * static_cast<double>(centre.z);
    pad.height_mm = 1000.0 * static_cast<double>(centre.y) - radius -
                    key_surface_z_mm(rig_, finger_.key, angle_, pad.depth_mm);
    pad.side_mm = 1000.0 * static_cast<double>(centre.x) - rig_.key_centre_x_mm[key];
    pad.arm_mm = 1000.0 * static_cast<double>(glm::length(glm::vec2(centre.x - root.x, centre.z - root.z)));
    return pad;
  }

  // How far the pad's centre lies outside its key's top less kPadInsideKeyMm: across, and in
  // front of (negative) or behind (positive) it. 0, 0 on it.
  glm::dvec2 off_key_mm(const PadOnKey& pad) const {
    const auto key = static_cast<std::size_t>(finger_.key);
    const double half_width = std::max(0.0, rig_.key_half_width_mm[key] - kPadInsideKeyMm);
    const double back = rig_.key_back_y_mm[key] - kPadInsideKeyMm;
    const double front = std::min(back, rig_.key_back_y_mm[key] - rig_.key_length_mm[key] + kPadInsideKeyMm);
    return {pad.side_mm - std::clamp(pad.side_mm, -half_width, half_width),
            pad.depth_mm - std::clamp(pad.depth_mm, front, back)};
  }

  // The pad's lowest point onto the key's top, its centre as near the key's centre line as
  // kMostSpreadCorrectionRad allows: the stroke corrects the height on an arm as long as the
  // pad's horizontal distance from the joint, the spread sideways on the same arm.
  PadSeat centre(PadSeat seat) {
    for (int round = 0; round < 4; ++round) {
      const PadOnKey pad = measure(seat);
      if (std::abs(pad.height_mm) < 0.05 && std::abs(pad.side_mm) < 0.2) break;
      if (pad.arm_mm < 10.0) break;
      seat.stroke += pad.height_mm / pad.arm_mm;
      // A larger spread carries the right hand's pads toward +x, the left's toward -x.
      seat.spread = std::clamp(seat.spread - static_cast<double>(mirror_) * pad.side_mm / pad.arm_mm,
                               -kMostSpreadCorrectionRad, kMostSpreadCorrectionRad);
    }
    pose(seat);
    return seat;
  }

  // A pad centred as far as allowed but still off its key's top: the stroke, spread and curl
  // together (Gauss-Newton on measured differences) put it on the top's edge less the margin,
  // its lowest point on the surface.
  void onto_key(PadSeat seat) {
    const auto residual = [&](const PadSeat& s) {
      const PadOnKey pad = measure(s);
      const glm::dvec2 off = off_key_mm(pad);
      return glm::dvec3(pad.height_mm, off.x, off.y);
    };
    const auto limited = [](PadSeat s) {
      s.spread = std::clamp(s.spread, -kMostSpreadOntoKeyRad, kMostSpreadOntoKeyRad);
      s.curl = std::clamp(s.curl, -kMostCurlOntoKeyRad, kMostCurlOntoKeyRad);
      return s;
    };
    constexpr double kStepRad = 0.01;
    for (int round = 0; round < 6; ++round) {
      const glm::dvec3 r = residual(seat);
      if (std::abs(r.x) < 0.05 && std::abs(r.y) < 0.05 && std::abs(r.z) < 0.05) break;
      glm::dmat3 jacobian(0.0);  // columns: d residual / d (stroke, spread, curl), mm per rad
      for (int j = 0; j < 3; ++j) {
        PadSeat moved = seat;
        (j == 0 ? moved.stroke : j == 1 ? moved.spread : moved.curl) += kStepRad;
        jacobian[j] = (residual(moved) - r) / kStepRad;
      }
      // Damped least squares: a small damping keeps a joint that barely moves the pad still.
      const glm::dmat3 normal = glm::transpose(jacobian) * jacobian + glm::dmat3(25.0);
      const glm::dvec3 step = -(glm::inverse(normal) * (glm::transpose(jacobian) * r));
      seat = limited({seat.stroke + step.x, seat.spread + step.y, seat.curl + step.z});
    }
    pose(seat);
  }

 private:
  PianoRig& rig_;
  PlacedModel& hand_model_;
  const components::Finger& finger_;
  std::size_t side_;
  std::size_t f_;
  double angle_;
  float mirror_;
};

void seat_pads_on_keys(ecs::World& world, PianoRig& rig, std::size_t side, PlacedModel& hand_model,
                       const std::array<double, 128>& key_down) {
  for (std::size_t f = 0; f < 5; ++f) {
    const auto* finger = world.try_get<components::Finger>(rig.fingers[side][f]);
    const auto& bones = rig.finger_bones[side][f];
    if (finger == nullptr || finger->key < 0 || finger->key > 127 || finger->press_depth <= 0.0 ||
        bones[0] < 0 || bones[2] < 0 || rig.finger_tips[side][f] < 0) {
      continue;
    }
    const auto key = static_cast<std::size_t>(finger->key);
    if (rig.key_nodes[key] < 0) continue;
    PadSeater seater(rig, hand_model, *finger, side, f, key_down[key] * rig.key_dip_rad[key]);
    const PadSeat centred = seater.centre({});
    const glm::dvec2 off = seater.off_key_mm(seater.measure(centred));
    if (std::abs(off.x) > 0.0 || std::abs(off.y) > 0.0) seater.onto_key(centred);
    else seater.pose(centred);
  }
}

void pose_pianist(ecs::World& world, PianoRig& rig) {
  auto* piano = world.try_get<PlacedModel>(rig.piano);
  if (piano == nullptr) return;
  std::array<glm::vec3, 2> wrists{};
  std::array<double, 128> key_down{};
  stage::reset_pose(*piano->asset, piano->pose);
  for (int side = 0; side < 2; ++side) {
    const auto* hand = world.try_get<components::Hand>(rig.hands[static_cast<std::size_t>(side)]);
    auto* hand_model = rig.hand_models[static_cast<std::size_t>(side)].is_null()
                           ? &rig.hand_targets[static_cast<std::size_t>(side)]
                           : world.try_get<PlacedModel>(rig.hand_models[static_cast<std::size_t>(side)]);
    if (hand_model == nullptr || hand_model->asset == nullptr) continue;
    stage::reset_pose(*hand_model->asset, hand_model->pose);
    if (hand == nullptr) continue;
    hand_model->root =
        rig.keyboard_to_world *
        glm::translate(glm::mat4(1.0f), keyboard_point(hand->x_mm, hand->y_mm, hand->z_mm));
    wrists[static_cast<std::size_t>(side)] =
        glm::vec3(rig.keyboard_to_world *
                  glm::vec4(keyboard_point(hand->x_mm, hand->y_mm - kWristBehindKnuckleMm,
                                           hand->z_mm + kWristAboveKnuckleMm),
                            1.0f));
    const float mirror = side == 0 ? 1.0f : -1.0f;
    for (std::size_t f = 0; f < 5; ++f) {
      const auto* finger =
          world.try_get<components::Finger>(rig.fingers[static_cast<std::size_t>(side)][f]);
      if (finger == nullptr) continue;
      const auto& bones = rig.finger_bones[static_cast<std::size_t>(side)][f];
      // The generator's posing contract (content/generator/README.md), set absolutely:
      // first bone R(+Y, -m spread) R(-X, flexion), then R(-X, ...) for the next two; the thumb's
      // three bones take abduction, MCP and IP flexion.
      const double flexion[3] = {f == 0 ? finger->abduction_rad : finger->mcp_flexion_rad,
                                 f == 0 ? finger->mcp_flexion_rad : finger->pip_flexion_rad,
                                 f == 0 ? finger->pip_flexion_rad : finger->dip_flexion_rad};
      for (std::size_t s = 0; s < 3; ++s) {
        if (bones[s] < 0) continue;
        glm::quat rotation = glm::angleAxis(static_cast<float>(flexion[s]), glm::vec3(-1, 0, 0));
        if (s == 0) {
          rotation =
              glm::angleAxis(-mirror * static_cast<float>(finger->spread_rad), glm::vec3(0, 1, 0)) *
              rotation;
        }
        hand_model->pose.local[static_cast<std::size_t>(bones[s])].rotation = rotation;
      }
      if (finger->key >= 0 && finger->key < 128) {
        double& down = key_down[static_cast<std::size_t>(finger->key)];
        down = std::max(down, finger->press_depth);
      }
    }
  }
  // The planned chain is a planar model of the finger; the hand model's joints are not quite it
  // (the thumb turns about a tilted axis). Where a finger touches its key, its stroke joint is
  // corrected on the posed model until the pad's lowest point lies on the key's top there.
  for (int side = 0; side < 2; ++side) {
    auto* hand_model = rig.hand_models[static_cast<std::size_t>(side)].is_null()
                           ? &rig.hand_targets[static_cast<std::size_t>(side)]
                           : world.try_get<PlacedModel>(rig.hand_models[static_cast<std::size_t>(side)]);
    if (hand_model == nullptr || hand_model->asset == nullptr) continue;
    seat_pads_on_keys(world, rig, static_cast<std::size_t>(side), *hand_model, key_down);
  }
  {
    std::array<PlacedModel*, 2> hand_models{};
    for (std::size_t side = 0; side < 2; ++side) {
      hand_models[side] = rig.hand_models[side].is_null() ? &rig.hand_targets[side]
                                                          : world.try_get<PlacedModel>(rig.hand_models[side]);
    }
    idle_fingers_yield(world, rig, hand_models);
  }
  // A key two fingers hold (one handing it to the other, or both hands) goes down once: as far
  // as the deeper of them holds it.
  for (std::size_t key = 0; key < key_down.size(); ++key) {
    const int node = rig.key_nodes[key];
    if (node < 0 || key_down[key] <= 0.0) continue;
    const auto angle = static_cast<float>(key_down[key] * rig.key_dip_rad[key]);
    stage::turn(piano->pose, node, angle, {1, 0, 0});
    // About the rail behind the visible key: the rail point (0, 0, -d) stays where it is, so the
    // key's back edge goes down with its front.
    const float d = rig.key_pivot_behind_m[key];
    if (d > 0.0f) stage::move(piano->pose, node, {0.0f, -d * std::sin(angle), d * (std::cos(angle) - 1.0f)});
  }

  // A user's hand models: placed where tutti's play; the body's arms reach their wrists.
  if (rig.hands_retarget) {
    if (auto* hands = world.try_get<PlacedModel>(rig.user_hands)) {
      wrists = pose_user_hands(world, rig.hands_retarget->proxy, rig);
      stage::apply_body_retarget(*rig.hands_retarget, *hands);
    }
  }
  auto* body = world.try_get<PlacedModel>(rig.body);
  if (body == nullptr) return;
  if (!rig.body_retarget) {
    pose_pianist_body(*body, rig, wrists);
    return;
  }
  if (rig.hands_retarget) {
    // A user's character with a user's hands: its arms reach them, its own hands folded away.
    pose_pianist_body(rig.body_retarget->proxy, rig, wrists);
    stage::apply_body_retarget(*rig.body_retarget, *body);
    for (const int hand : {rig.body_nodes.arm_right.end, rig.body_nodes.arm_left.end}) {
      const int own = rig.body_retarget->user_node_of(hand);
      if (own >= 0) body->pose.local[static_cast<std::size_t>(own)].scale = glm::vec3(0.0f);
    }
    return;
  }
  pose_pianist_with_own_hands(world, rig.body_retarget->proxy, rig);
  stage::apply_body_retarget(*rig.body_retarget, *body);
}

}  // namespace

void piano_skeleton_system(ecs::World& world, const ecs::FrameTime&) {
  world.view<PianoRig>().each([&world](PianoRig& rig) { pose_pianist(world, rig); });
}

}  // namespace tutti::piano_family
