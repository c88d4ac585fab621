// SPDX-License-Identifier: MIT
#pragma once
// Hands other than tutti's hand models playing where those play: a user's character's own hands
// (through its stand-in, stage/body_retarget.hpp) or a user's hand models. tutti's hand models
// are still posed by the fingering and the finger motion (not drawn); these hands then go where
// they play: flat over the keys, the wrist where a rounded curl puts the fingertips near the hand
// models', every finger bent onto its fingertip goal — the goal set so the hand's own pad (the
// rounded cap along its own last bone) meets the hand model's pad. The pressing fingers the hand
// cannot reach (a thumb shorter than tutti's, a narrower span) move the wrist toward their goals;
// a span still too wide brings the fingertip in along the key's top, not through it.

#include <array>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <tutti/ecs/world.hpp>
#include <tutti/model/model_asset.hpp>
#include <tutti/piano/piano_components.hpp>
#include <tutti/stage/fingertip_reach.hpp>
#include <tutti/stage/performer_rig.hpp>

namespace tutti::piano {

// Puts a hand's wrist (its hand node's origin) at `wrist`, turned to `rotation`: an arm's IK, or
// a free hand's root. Leaves `world` the pose's world matrices; returns how far the wrist stayed
// from `wrist` (an arm too short).
class WristPlacer {
 public:
  virtual ~WristPlacer() = default;
  virtual float place(const glm::vec3& wrist, const glm::quat& rotation,
                      std::vector<glm::mat4>& world) = 0;
  // The world matrices of the pose as it now is (the fingers bent), the wrist left where it is.
  virtual void refresh(std::vector<glm::mat4>& world) const = 0;
};

// The wrist on a seated body's arm (two-bone IK, elbow down, out and a little back).
class ArmPlacer : public WristPlacer {
 public:
  ArmPlacer(const model::ModelAsset& asset, model::ModelPose& pose, const glm::mat4& root,
            const stage::TwoBoneChain& arm, int side)
      : asset_(asset), pose_(pose), root_(root), arm_(arm), side_(side) {}
  float place(const glm::vec3& wrist, const glm::quat& rotation,
              std::vector<glm::mat4>& world) override;
  void refresh(std::vector<glm::mat4>& world) const override;

 private:
  const model::ModelAsset& asset_;
  model::ModelPose& pose_;
  const glm::mat4& root_;
  const stage::TwoBoneChain& arm_;
  int side_;
};

// A hand model on its own: its forearm (or the hand, without one) is a root, set so the hand sits
// at the wrist with the forearm straight behind it.
class FreeHandPlacer : public WristPlacer {
 public:
  FreeHandPlacer(const model::ModelAsset& asset, model::ModelPose& pose, const glm::mat4& root,
                 int hand)
      : asset_(asset), pose_(pose), root_(root), hand_(hand) {}
  float place(const glm::vec3& wrist, const glm::quat& rotation,
              std::vector<glm::mat4>& world) override;
  void refresh(std::vector<glm::mat4>& world) const override;

 private:
  const model::ModelAsset& asset_;
  model::ModelPose& pose_;
  const glm::mat4& root_;
  int hand_;
};

// Elbow poles for a seated pianist: down, out to the side and a little back.
glm::vec3 pianist_elbow_pole(const glm::mat4& root, int side);

// Where the piano's hand `side` (0 right, 1 left) of `hands` (with `nodes`) goes to play as its
// hand model (rig.hand_targets) plays now, and its wrist for a rounded curl.
struct HandGoal {
  stage::FingertipTargets tips;
  std::array<glm::vec3, 5> pads{};
  std::array<bool, 5> has_pad{};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 wrist{0.0f};
  bool valid = false;
};
HandGoal hand_goal(const model::ModelAsset& hands, const stage::BodyNodes& nodes, PianoRig& rig,
                   int side);

// Places hand `side` of `asset` (its pose, `nodes`) on `goal` through `placer`, tries the wrist
// again where the pressing fingers miss (the best of eight stays). `world` ends as the pose's world
// matrices. Returns how far the wrist stayed from where the hand needed it.
float place_hand(const ecs::World& ecs_world, const model::ModelAsset& asset,
                 model::ModelPose& pose, const stage::BodyNodes& nodes, PianoRig& rig, int side,
                 HandGoal& goal, WristPlacer& placer, std::vector<glm::mat4>& world);

// A user's character with its own hands (its stand-in `body`): seated, leaning toward the keys,
// each hand placed; a player whose arms fall short of the keys from tutti's bench leans further in
// from the spine (up to 25 degrees more), then toward the far hand.
void pose_pianist_with_own_hands(const ecs::World& ecs_world, stage::PlacedModel& body,
                                 PianoRig& rig);

// A user's hand models (their stand-in `hands`): each hand placed freely where tutti's hand
// model plays; returns the wrists (right, left) for the body's arms.
std::array<glm::vec3, 2> pose_user_hands(const ecs::World& ecs_world, stage::PlacedModel& hands,
                                         PianoRig& rig);

// The seated pianist's trunk and head (both bodies).
void pose_seated_pianist(const stage::BodyNodes& nodes, const model::ModelAsset& asset,
                         model::ModelPose& pose);

}  // namespace tutti::piano
