// SPDX-License-Identifier: MIT
#pragma once
// The piano family: each of the scene's pianists (plan_pianist.hpp), at a piano of their own, their hands and fingers as entities
// driven by the finger-motion system, and the piano, hand models, bench and performer rig posed
// by piano_skeleton_system (pose_piano.hpp).
//
// Drafting for `tutti scene new`: piano_draft.cpp; its `tutti check-pose` measures:
// check_pose_piano.cpp.
//
// Systems: finger_motion (Phase::evaluate: Hand, Finger from the planned motion), piano_skeleton
// (Phase::pose: keys, hands, the seated pianist).

#include <tutti/piano/piano_scene_section.hpp>
#include <tutti/piano/piano_stops.hpp>
#include <tutti/stage/family_plugin.hpp>

namespace tutti::piano {

class PianoPlugin final : public stage::FamilyPlugin {
 public:
  std::string_view name() const override { return "piano"; }
  const scene::SceneSection& scene_section() const override { return section_; }
  std::string_view draft_plays() const override { return "keyboards"; }
  int draft_seating_order() const override { return 0; }  // the piano at the stage's origin
  Result<std::vector<int>> draft_recognise(const music::Score& score,
                                           std::span<const int> available) const override;
  Result<stage::FamilyDraft> draft(const music::Score& score, std::span<const int> parts,
                                   const stage::DraftPlace& place) const override;
  void check_pose(stage::PoseChecker& checker, ecs::Entity performer) const override;
  void finish_pose_check(stage::PoseChecker& checker) const override;
  void add_systems(ecs::Schedule& schedule) const override;
  std::span<const stage::StopKind* const> stop_kinds() const override {
    return keyboard_stop_kinds();
  }
  std::unique_ptr<stage::StopTracker> track_stops(ecs::World& world) const override {
    return track_keyboard_stops(world);
  }
  Status build(stage::StageBuilder& builder) const override;
  // describe_keyboard_player.cpp
  void describe_player(const stage::Stage& stage, ecs::Entity performer,
                       stage::PlayerView& out) const override;

 private:
  Status build_pianist(stage::StageBuilder& builder, std::size_t index) const;

  PianoSceneSection section_;
};

}  // namespace tutti::piano
