// SPDX-License-Identifier: MIT
#pragma once
// An instrument family as a plugin (Bevy's Plugin): everything about one family in one place.
// A family reads its section of the scene file (scene_section.hpp), adds its systems to the
// schedule's phases and, for a scene, plans its performers, spawns their entities and binds
// their models (StageBuilder), drafts its players for `tutti scene new` (family_draft.hpp) and
// measures their poses for `tutti check-pose` (pose_checker.hpp), and names and finds the stops its
// players reach, which become the host API's events and `sync-report`'s contacts
// (contact_detector.hpp), and describes its players to the editor (player_view.hpp).
// The stage knows families only through this interface; the list of families a program uses is
// a small file of its own (tutti::performance's default_families()).

#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/ecs/schedule.hpp>
#include <tutti/music/score.hpp>
#include <tutti/scene/scene_section.hpp>
#include <tutti/stage/contact_detector.hpp>

namespace tutti::stage {

// family_draft.hpp (it holds JSON values: hosts that never draft need not parse the JSON library).
struct FamilyDraft;
struct DraftPlace;

class PoseChecker;
class Stage;
class StageBuilder;
struct PlayerView;

class FamilyPlugin {
 public:
  virtual ~FamilyPlugin() = default;

  // Seat::family of its performers.
  virtual std::string_view name() const = 0;

  // Its section of the scene file: the top-level keys its players are written under. The
  // loader hands the document to it (scene::LoadOptions::sections).
  virtual const scene::SceneSection& scene_section() const = 0;

  // `tutti scene new` (family_draft.hpp). What the family plays, for the note on parts nobody
  // plays: "violin, viola, cello, double bass".
  virtual std::string_view draft_plays() const = 0;
  // Its place from the audience's left among the families with players (lower = further left).
  virtual int draft_seating_order() const = 0;
  // The parts among `available` (each has notes; no family listed earlier took it) its players
  // would play, in score order.
  virtual Result<std::vector<int>> draft_recognise(const music::Score& score,
                                                   std::span<const int> available) const = 0;
  // Its players for `parts` (what draft_recognise gave, not empty), drafted at `place`.
  virtual Result<FamilyDraft> draft(const music::Score& score, std::span<const int> parts,
                                    const DraftPlace& place) const = 0;

  // Adds the family's systems to their phases. Called once for every stage, whether or not the
  // scene has performers of the family (their systems then find nothing to do).
  virtual void add_systems(ecs::Schedule& schedule) const = 0;

  // `tutti check-pose` (pose_checker.hpp): measures `performer`, one of its performers, in the
  // frame just posed; after the last frame, finish_pose_check adds figures over the whole range.
  // Families without measures of their own take none.
  virtual void check_pose(PoseChecker& checker, ecs::Entity performer) const {
    (void)checker;
    (void)performer;
  }
  virtual void finish_pose_check(PoseChecker& checker) const { (void)checker; }

  // The stops its players reach (contact_detector.hpp): every kind it reports, in a fixed
  // order (the host API lists them by name), and a tracker for one run of the detector over a
  // stage's world (nullptr: nothing of the family's to watch there). Families that report no
  // stops keep both defaults.
  virtual std::span<const StopKind* const> stop_kinds() const { return {}; }
  virtual std::unique_ptr<StopTracker> track_stops(ecs::World& world) const {
    (void)world;
    return nullptr;
  }

  // What the editor shows of `performer`, one of its players, beyond what every player has
  // (player_view.hpp). The default: a player with nothing more.
  virtual void describe_player(const Stage& stage, ecs::Entity performer, PlayerView& out) const {
    (void)stage;
    (void)performer;
    (void)out;
  }

  // Loads the family's content, plans the scene's performers of the family (or shares the plans
  // of builder.previous() whose inputs did not change), spawns their entities and places and
  // binds their models.
  virtual Status build(StageBuilder& builder) const = 0;
};

}  // namespace tutti::stage
