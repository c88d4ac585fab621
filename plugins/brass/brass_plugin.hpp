// SPDX-License-Identifier: MIT
#pragma once
// The brass family: each brass player of the scene (plan_brass_player.hpp) as a performer entity
// driven by the brass-motion system (Mouth, Breath, and the Valve or Slide of their instrument
// entity) and by ensemble variation (BodyMotion), and their instrument, body, chair and stand
// posed by brass_skeleton_system (pose_brass.hpp).
//
// Drafting for `tutti scene new`: brass_draft.cpp; its `tutti check-pose` measures:
// check_pose_brass.cpp.
//
// Systems: brass_motion (Phase::evaluate), ensemble_variation (Phase::express), brass_skeleton
// (Phase::pose).

#include <tutti/brass/brass_scene_section.hpp>
#include <tutti/brass/brass_stops.hpp>
#include <tutti/stage/family_plugin.hpp>

namespace tutti::brass {

class BrassPlugin final : public stage::FamilyPlugin {
 public:
  std::string_view name() const override { return "brass"; }
  const scene::SceneSection& scene_section() const override { return section_; }
  std::string_view draft_plays() const override {
    return "trumpet, horn, trombone, euphonium, tuba";
  }
  int draft_seating_order() const override { return 10; }  // to the keyboards' right
  Result<std::vector<int>> draft_recognise(const music::Score& score,
                                           std::span<const int> available) const override;
  Result<stage::FamilyDraft> draft(const music::Score& score, std::span<const int> parts,
                                   const stage::DraftPlace& place) const override;
  void check_pose(stage::PoseChecker& checker, ecs::Entity performer) const override;
  void add_systems(ecs::Schedule& schedule) const override;
  std::span<const stage::StopKind* const> stop_kinds() const override {
    return brass_stop_kinds();
  }
  std::unique_ptr<stage::StopTracker> track_stops(ecs::World& world) const override {
    return track_brass_stops(world, name());
  }
  Status build(stage::StageBuilder& builder) const override;
  // describe_brass_player.cpp
  void describe_player(const stage::Stage& stage, ecs::Entity performer,
                       stage::PlayerView& out) const override;

 private:
  BrassSceneSection section_;
};

}  // namespace tutti::brass
