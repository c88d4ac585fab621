// The per-frame half of the stage: systems write components (Phase::evaluate), then the pose
// step below turns the components into node transforms and morph weights.
#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <tutti/components/body_motion.hpp>
#include <tutti/components/breath.hpp>
#include <tutti/components/finger.hpp>
#include <tutti/components/hand.hpp>
#include <tutti/components/mouth.hpp>
#include <tutti/components/slide.hpp>
#include <tutti/components/valve.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::stage {
namespace {

constexpr float kPi = 3.14159265f;

glm::vec3 origin(const glm::mat4& m) { return glm::vec3(m[3]); }

// Rotation of a matrix with uniform scale.
glm::quat rotation_of(const glm::mat4& m) {
  glm::mat3 r(m);
  r[0] = glm::normalize(r[0]);
  r[1] = glm::normalize(r[1]);
  r[2] = glm::normalize(r[2]);
  return glm::normalize(glm::quat_cast(r));
}

glm::vec3 to_vec3(const scene::Vec3& v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}
glm::vec3 to_vec3(const scene::Color& c) {
  return {static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b)};
}

void reset_pose(const model::ModelAsset& asset, model::ModelPose& pose) {
  for (std::size_t n = 0; n < asset.nodes.size(); ++n) pose.local[n] = asset.nodes[n].rest;
  std::fill(pose.morph_weights.begin(), pose.morph_weights.end(), 0.0f);
}

void turn(model::ModelPose& pose, int node, float radians, const glm::vec3& axis) {
  if (node < 0) return;
  glm::quat& r = pose.local[static_cast<std::size_t>(node)].rotation;
  r = glm::normalize(r * glm::angleAxis(radians, axis));
}

void set_morph(model::ModelPose& pose, int index, double value) {
  if (index >= 0) {
    pose.morph_weights[static_cast<std::size_t>(index)] =
        static_cast<float>(std::clamp(value, 0.0, 1.0));
  }
}

void pose_body_base(const BodyNodes& n, bool seated, const model::ModelAsset& body,
                    const components::Breath* breath, model::ModelPose& pose) {
  if (seated) {
    // Thighs forward, shins down again, the hips lowered onto a 460 mm seat.
    turn(pose, n.thigh_left, -kPi / 2, {1, 0, 0});
    turn(pose, n.thigh_right, -kPi / 2, {1, 0, 0});
    turn(pose, n.shin_left, kPi / 2, {1, 0, 0});
    turn(pose, n.shin_right, kPi / 2, {1, 0, 0});
    if (n.hips >= 0 && n.thigh_left >= 0 && n.shin_left >= 0) {
      const auto& rest = body.nodes;
      const float thigh_length =
          glm::length(rest[static_cast<std::size_t>(n.shin_left)].rest.translation);
      pose.local[static_cast<std::size_t>(n.hips)].translation.y -= thigh_length * 0.92f;
      pose.local[static_cast<std::size_t>(n.hips)].translation.z -= 0.05f;
    }
  }
  if (breath != nullptr) {
    // Inhaling lifts the chest and leans back a little; the preparation before a long rest's
    // breath starts the motion early.
    const float lift = static_cast<float>(std::max(breath->inhale, 0.5 * breath->preparing));
    turn(pose, n.chest, -0.06f * lift, {1, 0, 0});
    turn(pose, n.neck, 0.04f * lift, {1, 0, 0});
  }
}

// The ensemble's motion on the default rig (player facing +Z, their left +X, identity rest
// rotations): weight on one foot, knees, sway and twist from the spine, the breathing chest, the
// head's nod.
void pose_body_motion(const BodyNodes& n, bool seated, const model::ModelAsset& body,
                      const components::BodyMotion& m, model::ModelPose& pose) {
  if (n.hips >= 0) {
    glm::vec3& hips = pose.local[static_cast<std::size_t>(n.hips)].translation;
    hips.x += m.hips_shift_m;
    if (!seated && m.knee_flex_m > 0.0f && n.shin_left >= 0) {
      // Thigh forward and shin back by the same angle keep the feet where they were.
      const float leg =
          glm::length(body.nodes[static_cast<std::size_t>(n.shin_left)].rest.translation);
      const float angle = std::acos(std::clamp(1.0f - m.knee_flex_m / (2.0f * leg), 0.5f, 1.0f));
      for (int thigh : {n.thigh_left, n.thigh_right}) turn(pose, thigh, -angle, {1, 0, 0});
      for (int shin : {n.shin_left, n.shin_right}) turn(pose, shin, 2.0f * angle, {1, 0, 0});
      hips.y -= 2.0f * leg * (1.0f - std::cos(angle));
    }
  }
  turn(pose, n.spine, -m.sway_rad, {0, 0, 1});
  turn(pose, n.spine, m.twist_rad, {0, 1, 0});
  turn(pose, n.chest, -m.lean_back_rad, {1, 0, 0});
  turn(pose, n.neck, 0.6f * m.lean_back_rad, {1, 0, 0});
  if (n.chest >= 0)
    pose.local[static_cast<std::size_t>(n.chest)].translation.y += m.shoulder_lift_m;
  turn(pose, n.head, m.head_nod_rad, {1, 0, 0});
}

void pose_brass(Stage& stage, BrassSeat& seat) {
  PlacedModel& horn = stage.placed[seat.horn];
  const model::ModelAsset& horn_asset = *stage.models[horn.model];
  reset_pose(horn_asset, horn.pose);
  if (const auto* valve = stage.world.try_get<components::Valve>(seat.instrument)) {
    for (std::size_t v = 0; v < 3; ++v) {
      if (seat.valves[v] < 0) continue;
      horn.pose.local[static_cast<std::size_t>(seat.valves[v])].translation +=
          seat.valve_axis[v] * static_cast<float>(valve->press[v] * seat.valve_travel_m[v]);
    }
  }
  if (const auto* slide = stage.world.try_get<components::Slide>(seat.instrument);
      slide != nullptr && seat.slide >= 0) {
    horn.pose.local[static_cast<std::size_t>(seat.slide)].translation +=
        seat.slide_axis * static_cast<float>(slide->extension_mm / 1000.0);
  }

  std::vector<glm::mat4>& horn_world = stage.scratch_world;
  horn_world.resize(horn_asset.nodes.size());
  model::compute_world_matrices(horn_asset, horn.pose, seat.horn_correction, horn_world);
  const glm::vec3 mouthpiece = seat.mouthpiece >= 0
                                   ? origin(horn_world[static_cast<std::size_t>(seat.mouthpiece)])
                                   : glm::vec3(0.0f);
  glm::mat4 facing = seat.placement;
  facing[3] = glm::vec4(0, 0, 0, 1);
  // Lips of a 1.75 m player, or the rig's mouth node.
  glm::vec3 lips = origin(seat.placement) + glm::vec3(facing * glm::vec4(0, 1.58f, 0.1f, 0));
  PlacedModel* body = seat.body ? &stage.placed[*seat.body] : nullptr;
  const components::BodyMotion* body_motion = nullptr;
  std::vector<glm::mat4>& body_world = stage.scratch_body_world;
  if (body != nullptr) {
    const model::ModelAsset& body_asset = *stage.models[body->model];
    reset_pose(body_asset, body->pose);
    const auto* mouth = stage.world.try_get<components::Mouth>(seat.performer);
    const auto* breath = stage.world.try_get<components::Breath>(seat.performer);
    body_motion = stage.world.try_get<components::BodyMotion>(seat.performer);
    // With ensemble motion the breathing body comes from it (per-player depth); without, from
    // the Breath component alone.
    pose_body_base(seat.body_nodes, seat.seated && !seat.body_nodes.mapped, body_asset,
                   body_motion != nullptr ? nullptr : breath, body->pose);
    if (body_motion != nullptr && !seat.body_nodes.mapped) {
      pose_body_motion(seat.body_nodes, seat.seated, body_asset, *body_motion, body->pose);
    }
    if (mouth != nullptr) {
      // A phrase that outlasts the air strains the face; with ensemble motion, as the player's
      // expression shapes it (BodyMotion::strain starts from Breath::strain).
      const double strain = body_motion != nullptr ? 0.8 * body_motion->strain
                            : breath != nullptr    ? 0.8 * breath->strain
                                                   : 0.0;
      set_morph(body->pose, seat.body_nodes.morph_tension, std::max(mouth->tension, strain));
      set_morph(body->pose, seat.body_nodes.morph_open, mouth->open);
    }
    body_world.resize(body_asset.nodes.size());
    model::compute_world_matrices(body_asset, body->pose, body->root, body_world);
    if (seat.body_nodes.mouth >= 0) {
      lips = origin(body_world[static_cast<std::size_t>(seat.body_nodes.mouth)]);
    }
  }
  // The instrument hangs from the lips: its mouthpiece at the mouth, pointing where the player
  // faces, the bell a little down. The generated instruments point their bell along -Z (their
  // player at +Z); performers face +Z.
  const float tilt = (seat.trombone ? -0.08f : -0.16f) +
                     (body_motion != nullptr ? body_motion->bell_lift_rad : 0.0f);
  horn.root = glm::translate(glm::mat4(1.0f), lips) * facing *
              glm::rotate(glm::mat4(1.0f), kPi, glm::vec3(0, 1, 0)) *
              glm::rotate(glm::mat4(1.0f), tilt, glm::vec3(1, 0, 0)) *
              glm::translate(glm::mat4(1.0f), -mouthpiece) * seat.horn_correction;
  if (body == nullptr) return;

  // Fingers: the left hand wraps the valve casing or the bell brace, the right hand's fingertips
  // rest on the buttons / hold the slide brace. The default rig flexes its (hanging) fingers
  // about local -Z on the left, +Z on the right (content/generator/README.md).
  if (!seat.body_nodes.mapped) {
    constexpr float kDeg = kPi / 180.0f;
    const float left_curl[3] = {55 * kDeg, 45 * kDeg, 30 * kDeg};
    const float right_curl[3] = {30 * kDeg, 35 * kDeg, 20 * kDeg};
    for (std::size_t side = 0; side < 2; ++side) {
      const float* curl = side == 0 ? left_curl : right_curl;
      const glm::vec3 axis = side == 0 ? glm::vec3(0, 0, -1) : glm::vec3(0, 0, 1);
      for (std::size_t f = 1; f < 5; ++f) {
        for (std::size_t s = 0; s < 3; ++s) {
          turn(body->pose, seat.body_nodes.fingers[side][f][s], curl[s], axis);
        }
      }
      turn(body->pose, seat.body_nodes.fingers[side][0][1], 0.5f * curl[0], axis);
    }
  }

  // Hands on the grips: the hand turned so the rig's grip frame matches the instrument's, the
  // arm solved so the wrist lands where that puts the palm on the grip. The elbows hang down and
  // out to the player's sides (their left is +X when facing +Z).
  const model::ModelAsset& body_asset = *stage.models[body->model];
  const glm::vec3 left = glm::vec3(facing * glm::vec4(1, 0, 0, 0));
  const glm::vec3 back = glm::vec3(facing * glm::vec4(0, 0, -1, 0));
  const glm::vec3 down(0, -1, 0);
  const float body_scale = glm::length(glm::vec3(body->root[0]));
  for (int hand = 0; hand < 2; ++hand) {
    const int grip = hand == 0 ? seat.grip_left : seat.grip_right;
    if (grip < 0) continue;
    const TwoBoneChain& arm = hand == 0 ? seat.body_nodes.arm_left : seat.body_nodes.arm_right;
    const int rig_grip = hand == 0 ? seat.body_nodes.grip_left : seat.body_nodes.grip_right;
    const glm::mat4 grip_world =
        horn.root * glm::inverse(seat.horn_correction) * horn_world[static_cast<std::size_t>(grip)];
    const glm::vec3 grip_position(grip_world[3]);
    const glm::vec3 pole = down + (hand == 0 ? left : -left) * 0.8f + back * 0.3f;
    if (rig_grip < 0 || arm.end < 0) {
      solve_two_bone_ik(body_asset, arm, grip_position, pole, body->root, body->pose, body_world);
      continue;
    }
    const model::NodeTransform& grip_rest =
        body_asset.nodes[static_cast<std::size_t>(rig_grip)].rest;
    const glm::quat hand_rotation =
        glm::normalize(rotation_of(grip_world) * glm::inverse(grip_rest.rotation));
    const glm::vec3 wrist = grip_position - hand_rotation * (body_scale * grip_rest.translation);
    solve_two_bone_ik(body_asset, arm, wrist, pole, body->root, body->pose, body_world);
    const int forearm = body_asset.nodes[static_cast<std::size_t>(arm.end)].parent;
    const glm::quat parent_rotation =
        forearm >= 0 ? rotation_of(body_world[static_cast<std::size_t>(forearm)])
                     : rotation_of(body->root);
    body->pose.local[static_cast<std::size_t>(arm.end)].rotation =
        glm::normalize(glm::inverse(parent_rotation) * hand_rotation);
    model::compute_world_matrices(body_asset, body->pose, body->root, body_world);
  }
}

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

void pose_pianist_body(Stage& stage, PianistSeat& seat, const std::array<glm::vec3, 2>& wrists) {
  PlacedModel& body = stage.placed[*seat.body];
  const model::ModelAsset& asset = *stage.models[body.model];
  reset_pose(asset, body.pose);
  pose_body_base(seat.body_nodes, true, asset, nullptr, body.pose);
  turn(body.pose, seat.body_nodes.chest, 0.12f, {1, 0, 0});  // leaning toward the keys
  turn(body.pose, seat.body_nodes.neck, 0.14f, {1, 0, 0});   // looking down at them
  turn(body.pose, seat.body_nodes.head, 0.14f, {1, 0, 0});
  for (int side : {0, 1}) {
    const int hand = seat.rig_hands[static_cast<std::size_t>(side)];
    if (hand >= 0) body.pose.local[static_cast<std::size_t>(hand)].scale = glm::vec3(0.0f);
  }
  std::vector<glm::mat4>& world = stage.scratch_world;
  world.resize(asset.nodes.size());
  model::compute_world_matrices(asset, body.pose, body.root, world);
  glm::mat4 facing = body.root;
  facing[3] = glm::vec4(0, 0, 0, 1);
  const glm::vec3 left = glm::vec3(facing * glm::vec4(1, 0, 0, 0));
  const glm::vec3 back = glm::vec3(facing * glm::vec4(0, 0, -1, 0));
  const glm::vec3 down(0, -1, 0);
  solve_two_bone_ik(asset, seat.body_nodes.arm_right, wrists[0], down - 0.7f * left + 0.2f * back,
                    body.root, body.pose, world);
  solve_two_bone_ik(asset, seat.body_nodes.arm_left, wrists[1], down + 0.7f * left + 0.2f * back,
                    body.root, body.pose, world);
}

void pose_pianist(Stage& stage, PianistSeat& seat) {
  PlacedModel& piano = stage.placed[seat.piano];
  std::array<glm::vec3, 2> wrists{};
  const model::ModelAsset& piano_asset = *stage.models[piano.model];
  reset_pose(piano_asset, piano.pose);
  for (int side = 0; side < 2; ++side) {
    const auto* hand =
        stage.world.try_get<components::Hand>(seat.hands[static_cast<std::size_t>(side)]);
    PlacedModel& hand_model = stage.placed[seat.hand_models[static_cast<std::size_t>(side)]];
    const model::ModelAsset& hand_asset = *stage.models[hand_model.model];
    reset_pose(hand_asset, hand_model.pose);
    if (hand == nullptr) continue;
    hand_model.root =
        seat.keyboard_to_world *
        glm::translate(glm::mat4(1.0f), keyboard_point(hand->x_mm, hand->y_mm, hand->z_mm));
    wrists[static_cast<std::size_t>(side)] =
        glm::vec3(seat.keyboard_to_world *
                  glm::vec4(keyboard_point(hand->x_mm, hand->y_mm - kWristBehindKnuckleMm,
                                           hand->z_mm + kWristAboveKnuckleMm),
                            1.0f));
    const float mirror = side == 0 ? 1.0f : -1.0f;
    for (std::size_t f = 0; f < 5; ++f) {
      const auto* finger =
          stage.world.try_get<components::Finger>(seat.fingers[static_cast<std::size_t>(side)][f]);
      if (finger == nullptr) continue;
      const auto& bones = seat.finger_bones[static_cast<std::size_t>(side)][f];
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
        hand_model.pose.local[static_cast<std::size_t>(bones[s])].rotation = rotation;
      }
      if (finger->key >= 0 && finger->key < 128) {
        const int node = seat.key_nodes[static_cast<std::size_t>(finger->key)];
        if (node >= 0) {
          turn(piano.pose, node,
               static_cast<float>(finger->press_depth *
                                  seat.key_dip_rad[static_cast<std::size_t>(finger->key)]),
               {1, 0, 0});
        }
      }
    }
  }
  if (seat.body) pose_pianist_body(stage, seat, wrists);
}

}  // namespace

void evaluate_stage(Stage& stage, double t_s) {
  stage.schedule.run(stage.world, {t_s, 0.0});
  for (BrassSeat& seat : stage.brass) pose_brass(stage, seat);
  if (stage.pianist) pose_pianist(stage, *stage.pianist);
}

void collect_instances(const Stage& stage, std::vector<render::ModelInstance>& out) {
  out.clear();
  for (const PlacedModel& placed : stage.placed) {
    out.push_back({placed.model, &placed.pose, placed.root, placed.casts_shadows});
  }
}

render::Camera camera_at(const Stage& stage, double t_s, float aspect) {
  const scene::Camera& camera = stage.scene.camera_at(t_s);
  return render::look_at_camera(to_vec3(camera.position_m), to_vec3(camera.target_m),
                                static_cast<float>(camera.fov_deg), aspect);
}

render::Camera scene_camera(const Stage& stage, std::size_t index, float aspect) {
  const scene::Camera& camera = stage.scene.cameras[index];
  return render::look_at_camera(to_vec3(camera.position_m), to_vec3(camera.target_m),
                                static_cast<float>(camera.fov_deg), aspect);
}

render::Lighting lighting_of(const Stage& stage) {
  const scene::Lights& lights = stage.scene.lights;
  render::Lighting out;
  out.key = {to_vec3(lights.key.direction), to_vec3(lights.key.color),
             static_cast<float>(lights.key.intensity)};
  out.fill = {to_vec3(lights.fill.direction), to_vec3(lights.fill.color),
              static_cast<float>(lights.fill.intensity)};
  out.sky = to_vec3(lights.ambient_sky);
  out.ground = to_vec3(lights.ambient_ground);
  // Shadows cover everyone on stage plus a margin for bodies, stands and instruments.
  glm::vec3 lo(-1.0f, 0.0f, -1.0f);
  glm::vec3 hi(1.0f, 2.0f, 1.0f);
  for (const PlacedModel& placed : stage.placed) {
    if (!placed.casts_shadows) continue;  // the floor itself
    const glm::vec3 p = origin(placed.root);
    lo = glm::min(lo, p - glm::vec3(1.0f, 0.0f, 1.0f));
    hi = glm::max(hi, p + glm::vec3(1.0f, 2.0f, 1.0f));
  }
  out.shadow_center = 0.5f * (lo + hi);
  out.shadow_radius = 0.5f * glm::length(hi - lo);
  return out;
}

}  // namespace tutti::stage
