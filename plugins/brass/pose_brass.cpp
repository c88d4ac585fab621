// SPDX-License-Identifier: MIT
#include <tutti/brass/pose_brass.hpp>

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

#include <tutti/brass/brass_components.hpp>
#include <tutti/brass_motion/brass_pose_system.hpp>
#include <tutti/components/body_motion.hpp>
#include <tutti/components/breath.hpp>
#include <tutti/components/mouth.hpp>
#include <tutti/components/slide.hpp>
#include <tutti/components/valve.hpp>
#include <tutti/model/world_matrices_below.hpp>
#include <tutti/stage/body_retarget.hpp>
#include <tutti/stage/fingertip_reach.hpp>
#include <tutti/spline_motion/plateau_envelope.hpp>
#include <tutti/stage/stage.hpp>
#include <tutti/stage/touching.hpp>

namespace tutti::brass {
namespace {

using stage::origin;
using stage::PlacedModel;

constexpr float kPi = 3.14159265f;
// The arms' eased last stretch (two_bone_ik.hpp): a trombonist's slide arm at the far positions
// stops up to 6 mm shorter, and its elbow straightens smoothly, not in a whip.
constexpr float kArmSoftReachM = 0.015f;

double min_jerk(double u) {
  u = std::clamp(u, 0.0, 1.0);
  return u * u * u * (10.0 - 15.0 * u + 6.0 * u * u);
}

// How far up the instrument is at t (0 = at rest in front of the body, 1 = at the lips): raised
// over a second, done well before a phrase's first note (the breath before it is taken with the
// instrument up), lowered over a second after its last.
double raised_at(const std::vector<std::array<double, 2>>& phrases, double t_s) {
  constexpr double kRaiseS = 1.0, kUpBeforeS = 1.6, kHoldAfterS = 0.6, kLowerS = 1.0;
  double raised = 0.0;
  for (const auto& [start, end] : phrases) {
    const double up = min_jerk((t_s - (start - kUpBeforeS - kRaiseS)) / kRaiseS);
    const double down = 1.0 - min_jerk((t_s - (end + kHoldAfterS)) / kLowerS);
    raised = std::max(raised, std::min(up, down));
  }
  return raised;
}

void pose_player(ecs::World& world, ecs::Entity performer, BrassRig& rig, double t_s) {
  auto* horn = world.try_get<PlacedModel>(rig.horn);
  if (horn == nullptr) return;
  const model::ModelAsset& horn_asset = *horn->asset;
  stage::reset_pose(horn_asset, horn->pose);
  if (const auto* valve = world.try_get<components::Valve>(rig.instrument)) {
    for (std::size_t v = 0; v < BrassRig::kMaxValves; ++v) {
      if (rig.valves[v] < 0) continue;
      horn->pose.local[static_cast<std::size_t>(rig.valves[v])].translation +=
          rig.valve_axis[v] * static_cast<float>(valve->press[v] * rig.valve_travel_m[v]);
      stage::turn(horn->pose, rig.rotors[v], 0.5f * kPi * valve->press[v], glm::vec3(0, 1, 0));
    }
  }
  // Between phrases the instrument comes down in front of the body (the hold's rest), the
  // hands with it, and a trombonist closes the slide.
  const float raised =
      rig.hold.has_rest ? static_cast<float>(raised_at(rig.phrases, t_s)) : 1.0f;
  // The body is set for the slide's planned reach (plan_slide_reach: never short of the slide,
  // eased), the hand then follows the slide itself.
  double slide_mm = 0.0;
  double reach_mm = 0.0;
  const auto* slide = rig.slide >= 0 ? world.try_get<components::Slide>(rig.instrument) : nullptr;
  if (slide != nullptr) {
    slide_mm = slide->extension_mm;
    reach_mm = slide_mm;
    if (const auto* handle = world.try_get<brass_motion::BrassPlayerMotionHandle>(performer);
        handle != nullptr && handle->motion != nullptr) {
      reach_mm = std::max(reach_mm, tutti::spline_motion::evaluate_plateau_envelope(
                                        handle->motion->motion.slide_reach, t_s));
    }
  }
  std::vector<glm::mat4>& horn_world = rig.scratch_horn_world;
  horn_world.resize(horn_asset.nodes.size());
  const glm::vec3 slide_closed =
      rig.slide >= 0 ? horn->pose.local[static_cast<std::size_t>(rig.slide)].translation
                     : glm::vec3(0.0f);
  const auto set_slide = [&](double extension_mm) {
    if (rig.slide >= 0) {
      horn->pose.local[static_cast<std::size_t>(rig.slide)].translation =
          slide_closed + rig.slide_axis * static_cast<float>(raised * extension_mm / 1000.0);
    }
    model::compute_world_matrices(horn_asset, horn->pose, rig.horn_correction, horn_world);
  };
  // The body is set for a slide a little farther out than planned, so the arm keeps its elbow
  // bent: at full stretch the elbow's plane turns wildly for a small move of the hand.
  constexpr double kReachSlackMm = 30.0;
  set_slide(slide != nullptr ? reach_mm + kReachSlackMm : 0.0);
  const glm::vec3 mouthpiece = rig.mouthpiece >= 0
                                   ? origin(horn_world[static_cast<std::size_t>(rig.mouthpiece)])
                                   : glm::vec3(0.0f);
  glm::mat4 facing = rig.placement;
  facing[3] = glm::vec4(0, 0, 0, 1);
  // Lips of a 1.75 m player, or the rig's mouth node.
  glm::vec3 lips = origin(rig.placement) + glm::vec3(facing * glm::vec4(0, 1.58f, 0.1f, 0));
  // A user's character: the families pose its stand-in (body_retarget.hpp).
  PlacedModel* body = stage::posed_body(world.try_get<PlacedModel>(rig.body), rig.body_retarget);
  const components::BodyMotion* body_motion = nullptr;
  std::vector<glm::mat4>& body_world = rig.scratch_body_world;
  if (body != nullptr) {
    const model::ModelAsset& body_asset = *body->asset;
    stage::reset_pose(body_asset, body->pose);
    const auto* mouth = world.try_get<components::Mouth>(performer);
    const auto* breath = world.try_get<components::Breath>(performer);
    body_motion = world.try_get<components::BodyMotion>(performer);
    // With ensemble motion the breathing body comes from it (per-player depth); without, from
    // the Breath component alone.
    stage::pose_body_base(rig.body_nodes, rig.seated, body_asset,
                          body_motion != nullptr ? nullptr : breath, body->pose);
    if (body_motion != nullptr) {
      stage::pose_body_motion(rig.body_nodes, rig.seated, body_asset, *body_motion, body->pose);
    }
    if (mouth != nullptr) {
      // A phrase that outlasts the air strains the face; with ensemble motion, as the player's
      // expression shapes it (BodyMotion::strain starts from Breath::strain).
      const double strain = body_motion != nullptr ? 0.8 * body_motion->strain
                            : breath != nullptr    ? 0.8 * breath->strain
                                                   : 0.0;
      stage::set_morph(body->pose, rig.body_nodes.morph_tension, std::max(mouth->tension, strain));
      stage::set_morph(body->pose, rig.body_nodes.morph_open, mouth->open);
    }
    body_world.resize(body_asset.nodes.size());
    model::compute_world_matrices(body_asset, body->pose, body->root, body_world);
    if (rig.body_nodes.mouth >= 0) {
      lips = origin(body_world[static_cast<std::size_t>(rig.body_nodes.mouth)]);
    }
  }
  float tilt = (rig.seated ? rig.hold.bell_tilt_seated_rad : rig.hold.bell_tilt_standing_rad) +
                     (body_motion != nullptr ? body_motion->bell_lift_rad : 0.0f);
  // The instrument hangs from the lips: its mouthpiece at the mouth, pointing where the player
  // faces, the bell a little down. The generated instruments point their bell along -Z (their
  // player at +Z); performers face +Z.
  const auto hang_instrument = [&] {
    const glm::vec3 rest_at =
        lips + glm::vec3(facing * glm::vec4(0, -rig.hold.rest_below_lips_m,
                                            rig.hold.rest_forward_m, 0));
    const glm::vec3 at = glm::mix(rest_at, lips, raised);
    const float bell_tilt = raised * tilt + (1.0f - raised) * rig.hold.rest_bell_tilt_rad;
    horn->root = glm::translate(glm::mat4(1.0f), at) * facing *
                 glm::rotate(glm::mat4(1.0f), kPi, glm::vec3(0, 1, 0)) *
                 glm::rotate(glm::mat4(1.0f), bell_tilt, glm::vec3(1, 0, 0)) *
                 glm::translate(glm::mat4(1.0f), -mouthpiece) * rig.horn_correction;
  };
  hang_instrument();
  if (body == nullptr) return;

  // Hands (content/instruments/holds/): a palm on its grip — the hand turned so the rig's grip
  // frame matches the instrument's, the arm solved so the wrist lands where that puts the palm on
  // the grip — or fingertips on their buttons (stage/fingertip_reach.hpp). The elbows hang down and out to
  // the player's sides (their left is +X when facing +Z).
  const model::ModelAsset& body_asset = *body->asset;
  const glm::vec3 left = glm::vec3(facing * glm::vec4(1, 0, 0, 0));
  const glm::vec3 back = glm::vec3(facing * glm::vec4(0, 0, -1, 0));
  const glm::vec3 down(0, -1, 0);
  const float body_scale = glm::length(glm::vec3(body->root[0]));
  // How far a valve button node is down, in world space (zero for any other node).
  const auto* valve = world.try_get<components::Valve>(rig.instrument);
  const auto button_travel = [&](int node, const glm::mat4& horn_frame) {
    for (std::size_t v = 0; valve != nullptr && v < BrassRig::kMaxValves; ++v) {
      if (rig.valves[v] != node) continue;
      const int parent = horn_asset.nodes[static_cast<std::size_t>(node)].parent;
      const glm::mat4 frame =
          parent >= 0 ? horn_frame * horn_world[static_cast<std::size_t>(parent)]
                      : horn_frame * rig.horn_correction;
      return glm::mat3(frame) *
             (rig.valve_axis[v] * static_cast<float>(valve->press[v] * rig.valve_travel_m[v]));
    }
    return glm::vec3(0.0f);
  };
  // Places both hands; returns how far each palm stayed from its grip (0 for fingertip holds).
  const auto place_hands = [&]() -> std::array<float, 2> {
    std::array<float, 2> short_by{0.0f, 0.0f};
    const glm::mat4 horn_frame = horn->root * glm::inverse(rig.horn_correction);
    for (int hand = 0; hand < 2; ++hand) {
      const auto side = static_cast<std::size_t>(hand);
      const HandHold& hold = rig.hold.hands[side];
      const stage::TwoBoneChain& arm =
          hand == 0 ? rig.body_nodes.arm_left : rig.body_nodes.arm_right;
      const glm::vec3 weights = hold.elbow_pole.value_or(rig.hold.elbow_pole);
      const glm::vec3 pole =
          weights.x * down + weights.y * (hand == 0 ? left : -left) + weights.z * back;
      stage::FingertipTargets targets;
      // The same targets with every button up: the hand is set on these, and the fingers alone
      // follow their buttons down (a player's hand stays still while the valves move; turning
      // it for each press flicked the wrist at up to 2000 deg/s).
      stage::FingertipTargets unpressed;
      bool by_fingertips = false;
      if (rig.hold.fingertips_place(hand) && arm.end >= 0) {
        for (std::size_t f = 0; f < 5; ++f) {
          const int node = rig.fingertip_on[side][f];
          if (node < 0) continue;
          const glm::mat4 button = horn_frame * horn_world[static_cast<std::size_t>(node)];
          // Above the button's top along its press axis (the pad's flesh between).
          const glm::vec3 press = glm::normalize(glm::mat3(button) * glm::vec3(0, -1, 0));
          targets.world[f] = origin(button) - press * hold.pad_above_button_m;
          targets.has[f] = true;
          unpressed.world[f] = targets.world[f] - button_travel(node, horn_frame);
          unpressed.has[f] = true;
          by_fingertips = true;
        }
      }
      glm::quat hand_rotation;
      glm::vec3 wrist;
      glm::vec3 palm_goal(0.0f);
      const int rig_grip = hand == 0 ? rig.body_nodes.grip_left : rig.body_nodes.grip_right;
      if (by_fingertips) {
        const glm::vec3 up = glm::normalize(glm::mat3(horn_frame) * glm::vec3(0, 1, 0));
        hand_rotation =
            stage::fingertip_hand_rotation(unpressed, up, hand, hold.metacarpal_lean_rad);
        wrist = stage::fingertip_wrist(body_asset, rig.body_nodes, hand, hold.curls(), unpressed,
                                       hand_rotation, body_scale);
      } else {
        const int grip = hand == 0 ? rig.grip_left : rig.grip_right;
        if (grip < 0) continue;
        const glm::mat4 grip_world = horn_frame * horn_world[static_cast<std::size_t>(grip)];
        palm_goal = glm::vec3(grip_world[3]);
        if (rig_grip < 0 || arm.end < 0) {
          stage::solve_two_bone_ik(body_asset, arm, palm_goal, pole, body->root, body->pose,
                                   body_world);
          continue;
        }
        const model::NodeTransform& grip_rest =
            body_asset.nodes[static_cast<std::size_t>(rig_grip)].rest;
        hand_rotation =
            glm::normalize(stage::rotation_of(grip_world) * glm::inverse(grip_rest.rotation));
        wrist = palm_goal - hand_rotation * (body_scale * grip_rest.translation);
      }
      stage::solve_two_bone_ik(body_asset, arm, wrist, pole, body->root, body->pose, body_world,
                               kArmSoftReachM);
      const int forearm = body_asset.nodes[static_cast<std::size_t>(arm.end)].parent;
      const glm::quat parent_rotation =
          forearm >= 0 ? stage::rotation_of(body_world[static_cast<std::size_t>(forearm)])
                       : stage::rotation_of(body->root);
      body->pose.local[static_cast<std::size_t>(arm.end)].rotation =
          glm::normalize(glm::inverse(parent_rotation) * hand_rotation);
      // Only the hand turned since the IK brought the arm's matrices up to date.
      model::update_world_matrices_below(body_asset, body->pose, body->root, arm.end, body_world);
      if (!by_fingertips && rig_grip >= 0) {
        short_by[side] =
            glm::distance(origin(body_world[static_cast<std::size_t>(rig_grip)]), palm_goal);
      }
      stage::pose_fingers(body_asset, rig.body_nodes, hand, hold.curls(),
                          by_fingertips ? &targets : nullptr, &rig.finger_limits, body_world,
                          body->pose);
    }
    return short_by;
  };
  std::array<float, 2> short_by = place_hands();
  // A grip out of the arm's reach (the trombone's far positions): the player turns the chest
  // toward that side and brings the shoulder forward — as much as the reach needs, up to 30°
  // each — keeping the head (and the instrument at the lips) facing where it faced; beyond that,
  // the instrument dips toward the shoulder (the hold's reach_dip_deg). Each pass turns by what
  // the last one left short.
  constexpr float kReachTolerance = 0.002f;
  constexpr float kMaxTurn = 30.0f * kPi / 180.0f;
  constexpr float kShoulderForwardPerRad = 0.33f;  // chest (0.18 m) + collarbone (0.15 m) arms
  float turned = 0.0f;
  float dipped = 0.0f;
  for (int pass = 0; pass < 6; ++pass) {
    const int side = short_by[1] >= short_by[0] ? 1 : 0;
    const float short_of = short_by[static_cast<std::size_t>(side)];
    if (short_of <= kReachTolerance) break;
    if (turned < kMaxTurn) {
      const float turn =
          std::min(kMaxTurn - turned,
                   std::asin(std::min(1.0f, 1.15f * short_of / kShoulderForwardPerRad)));
      turned += turn;
      // The right shoulder comes forward turning about +Y (the player faces +Z, their right is
      // -X).
      const float signed_turn = side == 1 ? turn : -turn;
      const stage::TwoBoneChain& arm =
          side == 0 ? rig.body_nodes.arm_left : rig.body_nodes.arm_right;
      const int shoulder =
          arm.upper >= 0 ? body_asset.nodes[static_cast<std::size_t>(arm.upper)].parent : -1;
      stage::turn(body->pose, rig.body_nodes.chest, signed_turn, glm::vec3(0, 1, 0));
      stage::turn(body->pose, rig.body_nodes.neck, -signed_turn, glm::vec3(0, 1, 0));
      stage::turn(body->pose, shoulder, signed_turn, glm::vec3(0, 1, 0));
      model::compute_world_matrices(body_asset, body->pose, body->root, body_world);
      if (rig.body_nodes.mouth >= 0) {
        lips = origin(body_world[static_cast<std::size_t>(rig.body_nodes.mouth)]);
      }
    } else if (dipped < rig.hold.reach_dip_rad) {
      // About 0.2 m of shoulder below the lips: each radian of dip brings a grip 0.7 m out
      // about 0.2 m nearer.
      const float dip = std::min(rig.hold.reach_dip_rad - dipped, 1.2f * short_of / 0.2f);
      dipped += dip;
      tilt -= dip;
    } else {
      break;
    }
    hang_instrument();
    short_by = place_hands();
  }
  if (slide != nullptr) {
    // The slide nearer than the body is set for: the turn and dip stay, the hands follow it.
    set_slide(slide_mm);
    hang_instrument();
    place_hands();
  }
}

// Where the player holds the instrument: each fingertip set on a node of it (valve buttons, the
// thumb's rest, a ring), each palm on its grip, and the lips on the mouthpiece while the
// instrument is up at them.
void touch_instrument(const BrassRig& rig, double t_s, stage::Touching& touching) {
  touching.clear();
  const auto body_node = [&rig](int node) {
    return rig.body_retarget ? rig.body_retarget->user_node_of(node) : node;
  };
  for (int hand = 0; hand < 2; ++hand) {
    const auto side = static_cast<std::size_t>(hand);
    if (rig.hold.fingertips_place(hand)) {
      for (std::size_t f = 0; f < 5; ++f) {
        touching.add({rig.body, body_node(rig.body_nodes.fingertips[side][f]), rig.horn,
                      rig.fingertip_on[side][f], -1});
      }
    } else {
      touching.add({rig.body, body_node(hand == 0 ? rig.body_nodes.grip_left : rig.body_nodes.grip_right),
                    rig.horn, hand == 0 ? rig.grip_left : rig.grip_right, -1});
    }
  }
  const double raised = rig.hold.has_rest ? raised_at(rig.phrases, t_s) : 1.0;
  if (raised >= 1.0) {
    touching.add({rig.body, body_node(rig.body_nodes.mouth), rig.horn, rig.mouthpiece, -1});
  }
}

}  // namespace

void brass_skeleton_system(ecs::World& world, const ecs::FrameTime& frame) {
  world.view<BrassRig>().each([&world, &frame](ecs::Entity performer, BrassRig& rig) {
    pose_player(world, performer, rig, frame.t_s);
    if (rig.body_retarget) {
      if (auto* user = world.try_get<PlacedModel>(rig.body)) {
        stage::apply_body_retarget(*rig.body_retarget, *user);
      }
    }
    if (auto* touching = world.try_get<stage::Touching>(performer)) {
      touch_instrument(rig, frame.t_s, *touching);
    }
  });
}

}  // namespace tutti::brass
