#include <tutti/piano/pose_piano.hpp>

#include <cmath>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include <tutti/components/finger.hpp>
#include <tutti/components/hand.hpp>
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

void pose_seated_pianist(const stage::BodyNodes& nodes, const model::ModelAsset& asset,
                         model::ModelPose& pose) {
  stage::reset_pose(asset, pose);
  stage::pose_body_base(nodes, true, asset, nullptr, pose);
  stage::turn(pose, nodes.chest, 0.12f, {1, 0, 0});  // leaning toward the keys
  stage::turn(pose, nodes.neck, 0.14f, {1, 0, 0});   // looking down at them
  stage::turn(pose, nodes.head, 0.14f, {1, 0, 0});
}

// Elbow poles: down, out to the side and a little back.
glm::vec3 elbow_pole(const glm::mat4& root, int side) {
  glm::mat4 facing = root;
  facing[3] = glm::vec4(0, 0, 0, 1);
  const glm::vec3 left = glm::vec3(facing * glm::vec4(1, 0, 0, 0));
  const glm::vec3 back = glm::vec3(facing * glm::vec4(0, 0, -1, 0));
  return glm::vec3(0, -1, 0) + (side == 0 ? -0.7f : 0.7f) * left + 0.2f * back;
}

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
  stage::solve_two_bone_ik(asset, rig.body_nodes.arm_right, wrists[0], elbow_pole(body.root, 0),
                           body.root, body.pose, world);
  stage::solve_two_bone_ik(asset, rig.body_nodes.arm_left, wrists[1], elbow_pole(body.root, 1),
                           body.root, body.pose, world);
}

constexpr const char* kFingerNames[5] = {"thumb", "index", "middle", "ring", "little"};

// Where a user's hand should be to play like the hand model: each fingertip's goal, the hand
// model's pad centres (the rounded caps that rest on the keys), the hand's turn and its wrist.
struct OwnHand {
  stage::FingertipTargets tips;
  std::array<glm::vec3, 5> pads{};
  std::array<bool, 5> has_pad{};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 wrist{0.0f};
  bool valid = false;
};

// A nominal curl for placing the wrist: a pianist's rounded hand.
stage::FingerCurls pianist_curls() {
  stage::FingerCurls curls;
  curls.finger = {glm::radians(20.0f), glm::radians(45.0f), glm::radians(20.0f)};
  curls.thumb = glm::radians(15.0f);
  return curls;
}

// The piano's hand `side` (0 right, 1 left) as its hand model plays now. The hand lies flat over
// the keys, the metacarpals 10 degrees down toward them, the index toward the thumb's side (the
// bass for the right hand).
OwnHand own_hand_goal(const model::ModelAsset& body, PianoRig& rig, int side) {
  OwnHand out;
  const auto s = static_cast<std::size_t>(side);
  const PlacedModel& model = rig.hand_targets[s];
  if (model.asset == nullptr) return out;
  std::vector<glm::mat4>& world = rig.scratch_target_world;
  world.resize(model.asset->nodes.size());
  model::compute_world_matrices(*model.asset, model.pose, model.root, world);
  const std::string suffix = side == 0 ? "_r" : "_l";
  for (std::size_t f = 0; f < 5; ++f) {
    const int tip = model.asset->find_node(std::string(kFingerNames[f]) + "_tip" + suffix);
    if (tip < 0) continue;
    out.tips.world[f] = glm::vec3(world[static_cast<std::size_t>(tip)][3]);
    out.tips.has[f] = true;
    const int dip = model.asset->find_node(std::string(kFingerNames[f]) + "_3" + suffix);
    if (dip < 0) continue;
    const glm::vec3 last_bone = out.tips.world[f] - glm::vec3(world[static_cast<std::size_t>(dip)][3]);
    if (glm::length(last_bone) < 1e-6f) continue;
    out.pads[f] = out.tips.world[f] - stage::kFingertipPadRadiusM[f] * glm::normalize(last_bone);
    out.has_pad[f] = true;
  }
  const glm::vec3 treble = glm::normalize(glm::vec3(rig.keyboard_to_world * glm::vec4(1, 0, 0, 0)));
  const glm::vec3 into = glm::normalize(glm::vec3(rig.keyboard_to_world * glm::vec4(0, 0, -1, 0)));
  const glm::vec3 up = glm::normalize(glm::cross(treble, into));
  const float tilt = glm::radians(10.0f);
  const glm::vec3 y = -(std::cos(tilt) * into - std::sin(tilt) * up);
  const glm::vec3 index_side = side == 0 ? -treble : treble;
  const glm::vec3 z = glm::normalize(index_side - glm::dot(index_side, y) * y);
  out.rotation = glm::normalize(glm::quat_cast(glm::mat3(glm::cross(y, z), y, z)));
  const int body_side = side == 0 ? 1 : 0;  // the piano's right hand is the rig's _r (side 1)
  out.wrist = stage::fingertip_wrist(body, rig.body_nodes, body_side, pianist_curls(), out.tips,
                                     out.rotation, 1.0f);
  out.valid = true;
  return out;
}

// Places hand `side` of the stand-in `body` on `goal`: the arm reaches the wrist, the hand turns,
// the fingers bend onto their goals as far as their joints allow. Each fingertip's goal is then
// set again so that its own pad's centre (along its own last bone, as bent) meets the hand
// model's, and the pressing fingers left off (a user's thumb shorter than the hand model's) move
// the wrist toward their goals; the best of eight tries stays. Returns how
// far the wrist stayed from where the hand needed it (the arm too short).
float place_own_hand(const ecs::World& ecs_world, PlacedModel& body, PianoRig& rig, int side,
                     OwnHand& goal) {
  const model::ModelAsset& asset = *body.asset;
  std::vector<glm::mat4>& world = rig.scratch_world;
  const auto s = static_cast<std::size_t>(side);
  const int body_side = side == 0 ? 1 : 0;
  const auto b = static_cast<std::size_t>(body_side);
  const stage::TwoBoneChain& arm = body_side == 0 ? rig.body_nodes.arm_left : rig.body_nodes.arm_right;
  if (!goal.valid || arm.end < 0) return 0.0f;
  const stage::FingerCurls curls = pianist_curls();
  glm::vec3 wrist = goal.wrist;
  glm::vec3 best_wrist = wrist;
  float best = 1e9f;
  float wrist_short = 0.0f;
  constexpr int kTries = 8;
  for (int attempt = 0; attempt <= kTries; ++attempt) {
    const bool last = attempt == kTries;
    if (last) wrist = best_wrist;
    stage::solve_two_bone_ik(asset, arm, wrist, elbow_pole(body.root, side), body.root, body.pose,
                             world);
    const int forearm = asset.nodes[static_cast<std::size_t>(arm.end)].parent;
    const glm::quat parent_rotation = forearm >= 0
                                          ? stage::rotation_of(world[static_cast<std::size_t>(forearm)])
                                          : stage::rotation_of(body.root);
    body.pose.local[static_cast<std::size_t>(arm.end)].rotation =
        glm::normalize(glm::inverse(parent_rotation) * goal.rotation);
    model::compute_world_matrices(asset, body.pose, body.root, world);
    const float short_now = glm::distance(glm::vec3(world[static_cast<std::size_t>(arm.end)][3]), wrist);
    if (!last) wrist_short = short_now;
    if (!last && attempt > 0 && short_now > 0.002f) {
      // The arm does not reach where the fingers want the wrist: the best reached place stays
      // (the caller leans in and tries again).
      attempt = kTries - 1;
      continue;
    }
    if (last) {
      // A pressing fingertip whose goal is still beyond its straight finger (a span wider than
      // the hand's) comes in along the key's top, not down through it: its height over the key
      // stays.
      for (std::size_t f = 0; f < 5; ++f) {
        const auto* finger = ecs_world.try_get<components::Finger>(rig.fingers[s][f]);
        const auto& bones = rig.body_nodes.fingers[b][f];
        const int tip = rig.body_nodes.fingertips[b][f];
        if (finger == nullptr || finger->press_depth <= 0.0 || !goal.tips.has[f] || tip < 0 ||
            bones[0] < 0 || bones[1] < 0 || bones[2] < 0) {
          continue;
        }
        float straight = 0.0f;
        for (const int node : {bones[1], bones[2], tip}) {
          straight += glm::length(asset.nodes[static_cast<std::size_t>(node)].rest.translation);
        }
        const glm::vec3 mcp = glm::vec3(world[static_cast<std::size_t>(bones[0])][3]);
        const glm::vec3 d = goal.tips.world[f] - mcp;
        if (glm::length(d) <= straight + 0.001f) continue;
        const float reach = 0.995f * straight;
        // The pressed key's top tilts toward the player: its normal, the keyboard's up turned
        // as the key is (about the keyboard's x, stage::turn in pose_pianist).
        glm::vec3 up(0.0f, 1.0f, 0.0f);
        if (finger->key >= 0 && finger->key < 128) {
          const float dip = static_cast<float>(finger->press_depth *
                                               rig.key_dip_rad[static_cast<std::size_t>(finger->key)]);
          up = glm::normalize(glm::mat3(rig.keyboard_to_world) *
                              (glm::angleAxis(dip, glm::vec3(1, 0, 0)) * glm::vec3(0, 1, 0)));
        }
        const float height = glm::dot(d, up);
        const glm::vec3 across = d - height * up;
        const float room = std::sqrt(std::max(0.0f, reach * reach - height * height));
        if (glm::length(across) < 1e-6f) continue;
        goal.tips.world[f] = mcp + height * up + room * glm::normalize(across);
      }
    }
    stage::pose_fingers(asset, rig.body_nodes, body_side, curls, &goal.tips, world, body.pose);
    if (last) break;
    model::compute_world_matrices(asset, body.pose, body.root, world);
    glm::vec3 worst(0.0f), mean_miss(0.0f);
    int pressing = 0;
    for (std::size_t f = 0; f < 5; ++f) {
      const int tip = rig.body_nodes.fingertips[b][f];
      const int dip = rig.body_nodes.fingers[b][f][2];
      if (tip < 0 || !goal.tips.has[f]) continue;
      const glm::vec3 at = glm::vec3(world[static_cast<std::size_t>(tip)][3]);
      const auto* finger = ecs_world.try_get<components::Finger>(rig.fingers[s][f]);
      // Only the fingers on keys move the hand: the others hover where they can.
      if (finger != nullptr && finger->press_depth > 0.0) {
        const glm::vec3 miss = goal.tips.world[f] - at;
        if (glm::length(miss) > glm::length(worst)) worst = miss;
        mean_miss += miss;
        ++pressing;
      }
      if (dip < 0 || !goal.has_pad[f]) continue;
      const glm::vec3 last_bone = at - glm::vec3(world[static_cast<std::size_t>(dip)][3]);
      if (glm::length(last_bone) < 1e-6f) continue;
      goal.tips.world[f] = goal.pads[f] + stage::kFingertipPadRadiusM[f] * glm::normalize(last_bone);
    }
    if (glm::length(worst) < best) {
      best = glm::length(worst);
      best_wrist = wrist;
    }
    // One finger off: the wrist goes all the way; several: by their mean, so a span wider than
    // the hand's is shared between its ends.
    wrist += pressing > 1 ? mean_miss / static_cast<float>(pressing) : worst;
  }
  return wrist_short;
}

// A user's character plays with its own hands (through its stand-in, `body`): each placed where
// the hand model plays (place_own_hand). A player whose arms fall short of the keys from tutti's
// bench leans further in from the spine, as far as the reach needs (up to 25 degrees more).
void pose_pianist_own_hands(const ecs::World& ecs_world, PlacedModel& body, PianoRig& rig) {
  const model::ModelAsset& asset = *body.asset;
  pose_seated_pianist(rig.body_nodes, asset, body.pose);
  std::vector<glm::mat4>& world = rig.scratch_world;
  world.resize(asset.nodes.size());
  model::compute_world_matrices(asset, body.pose, body.root, world);
  std::array<OwnHand, 2> goals{own_hand_goal(asset, rig, 0), own_hand_goal(asset, rig, 1)};
  constexpr float kMaxLean = 0.44f, kMaxSideLean = 0.25f;
  constexpr int kLeanPasses = 6;
  float leaned = 0.0f, side_leaned = 0.0f;
  for (int pass = 0; pass <= kLeanPasses; ++pass) {
    std::array<float, 2> short_of{};  // right, left hand
    for (int side = 0; side < 2; ++side) {
      short_of[static_cast<std::size_t>(side)] =
          place_own_hand(ecs_world, body, rig, side, goals[static_cast<std::size_t>(side)]);
    }
    const float worst = std::max(short_of[0], short_of[1]);
    const int spine = rig.body_nodes.spine;
    const int shoulder = rig.body_nodes.arm_right.upper;
    if (worst <= 0.002f || pass == kLeanPasses || spine < 0 || shoulder < 0) break;
    model::compute_world_matrices(asset, body.pose, body.root, world);
    const float lever = glm::distance(glm::vec3(world[static_cast<std::size_t>(spine)][3]),
                                      glm::vec3(world[static_cast<std::size_t>(shoulder)][3]));
    if (lever < 0.05f) break;
    if (leaned < kMaxLean) {
      const float lean = std::min(kMaxLean - leaned, 1.2f * worst / lever);
      leaned += lean;
      stage::turn(body.pose, spine, lean, {1, 0, 0});
      stage::turn(body.pose, rig.body_nodes.neck, -0.5f * lean, {1, 0, 0});  // eyes on the keys
    } else {
      // Leaning in is not enough: toward the far hand's side (the player's left is +X; a turn
      // about +Z by a negative angle leans that way).
      const float toward_left = short_of[1] > short_of[0] ? 1.0f : -1.0f;
      const float lean = std::min(kMaxSideLean - side_leaned, 1.2f * worst / lever);
      if (lean <= 1e-4f) break;
      side_leaned += lean;
      stage::turn(body.pose, spine, -toward_left * lean, {0, 0, 1});
      stage::turn(body.pose, rig.body_nodes.neck, 0.5f * toward_left * lean, {0, 0, 1});
    }
    model::compute_world_matrices(asset, body.pose, body.root, world);
  }
}

void pose_pianist(ecs::World& world, PianoRig& rig) {
  auto* piano = world.try_get<PlacedModel>(rig.piano);
  if (piano == nullptr) return;
  std::array<glm::vec3, 2> wrists{};
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
        const int node = rig.key_nodes[static_cast<std::size_t>(finger->key)];
        if (node >= 0) {
          stage::turn(piano->pose, node,
                      static_cast<float>(finger->press_depth *
                                         rig.key_dip_rad[static_cast<std::size_t>(finger->key)]),
                      {1, 0, 0});
        }
      }
    }
  }

  auto* body = world.try_get<PlacedModel>(rig.body);
  if (body == nullptr) return;
  if (!rig.body_retarget) {
    pose_pianist_body(*body, rig, wrists);
    return;
  }
  pose_pianist_own_hands(world, rig.body_retarget->proxy, rig);
  stage::apply_body_retarget(*rig.body_retarget, *body);
}

}  // namespace

void piano_skeleton_system(ecs::World& world, const ecs::FrameTime&) {
  world.view<PianoRig>().each([&world](PianoRig& rig) { pose_pianist(world, rig); });
}

}  // namespace tutti::piano_family
