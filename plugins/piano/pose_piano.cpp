#include <tutti/piano/pose_piano.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <tutti/components/finger.hpp>
#include <tutti/components/hand.hpp>
#include <tutti/piano/piano_components.hpp>
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
  stage::reset_pose(asset, body.pose);
  stage::pose_body_base(rig.body_nodes, true, asset, nullptr, body.pose);
  stage::turn(body.pose, rig.body_nodes.chest, 0.12f, {1, 0, 0});  // leaning toward the keys
  stage::turn(body.pose, rig.body_nodes.neck, 0.14f, {1, 0, 0});   // looking down at them
  stage::turn(body.pose, rig.body_nodes.head, 0.14f, {1, 0, 0});
  for (int side : {0, 1}) {
    const int hand = rig.rig_hands[static_cast<std::size_t>(side)];
    if (hand >= 0) body.pose.local[static_cast<std::size_t>(hand)].scale = glm::vec3(0.0f);
  }
  std::vector<glm::mat4>& world = rig.scratch_world;
  world.resize(asset.nodes.size());
  model::compute_world_matrices(asset, body.pose, body.root, world);
  glm::mat4 facing = body.root;
  facing[3] = glm::vec4(0, 0, 0, 1);
  const glm::vec3 left = glm::vec3(facing * glm::vec4(1, 0, 0, 0));
  const glm::vec3 back = glm::vec3(facing * glm::vec4(0, 0, -1, 0));
  const glm::vec3 down(0, -1, 0);
  stage::solve_two_bone_ik(asset, rig.body_nodes.arm_right, wrists[0],
                           down - 0.7f * left + 0.2f * back, body.root, body.pose, world);
  stage::solve_two_bone_ik(asset, rig.body_nodes.arm_left, wrists[1],
                           down + 0.7f * left + 0.2f * back, body.root, body.pose, world);
}

void pose_pianist(ecs::World& world, PianoRig& rig) {
  auto* piano = world.try_get<PlacedModel>(rig.piano);
  if (piano == nullptr) return;
  std::array<glm::vec3, 2> wrists{};
  stage::reset_pose(*piano->asset, piano->pose);
  for (int side = 0; side < 2; ++side) {
    const auto* hand = world.try_get<components::Hand>(rig.hands[static_cast<std::size_t>(side)]);
    auto* hand_model =
        world.try_get<PlacedModel>(rig.hand_models[static_cast<std::size_t>(side)]);
    if (hand_model == nullptr) continue;
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
  if (auto* body = world.try_get<PlacedModel>(rig.body)) pose_pianist_body(*body, rig, wrists);
}

}  // namespace

void piano_skeleton_system(ecs::World& world, const ecs::FrameTime&) {
  world.view<PianoRig>().each([&world](PianoRig& rig) { pose_pianist(world, rig); });
}

}  // namespace tutti::piano_family
