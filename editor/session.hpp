// SPDX-License-Identifier: MIT
#pragma once
// The editor's model: the open Document and the Stage planned from it. Every edit re-plans the
// stage (the models are shared with the previous stage, so a renderer stays valid) before it is
// accepted: an edit the planners refuse (a pin naming no note) changes nothing and returns their
// message. UI-free; the panels, the --script runner and the tests all drive it.

#include <cstdint>
#include <filesystem>
#include <memory>

#include <tutti/core/result.hpp>
#include <tutti/editor/document.hpp>
#include <tutti/editor/scene_edits.hpp>
#include <tutti/editor/timeline.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::editor {

class Session {
 public:
  static Result<std::unique_ptr<Session>> open(const std::filesystem::path& scene,
                                               const stage::StageOptions& options = {});

  const Document& document() const { return document_; }
  Document& document() { return document_; }
  stage::Stage& stage() { return *stage_; }
  const stage::Stage& stage() const { return *stage_; }
  // The same stage, shared: a player keeps the one it shows alive while the session re-plans.
  std::shared_ptr<stage::Stage> shared_stage() const { return stage_; }
  const Timeline& timeline() const { return timeline_; }

  // `coalesce`: merge with the previous edit of the same thing (one undo step per slider drag).
  Status apply(Result<Edit> edit, bool coalesce = false);
  Status undo();
  Status redo();
  // Document::recover_autosave, re-planned.
  Status recover_autosave();
  // Counts re-plans; the stage object is replaced on each (re-read any pointers into it).
  std::uint64_t stage_revision() const { return stage_revision_; }
  // The stage's models are not the ones of the stage before the last re-plan (a renderer made
  // for model_list() must be made again). False while the cast is unchanged.
  bool models_changed() const { return models_changed_; }
  double last_replan_ms() const { return last_replan_ms_; }
  // The breath boundary a time names for a player who breathes: the onset of the first playable
  // note at or after t (t itself after the last note). Marks are stored there, so a mark and the
  // breath it makes share one time.
  double breath_boundary(const PlayerRef& player, double t) const;
  // The player's breath at `t`: the one whose inhaling (from its preparation to its note) holds
  // t, or whose note starts within 0.1 s of it, the nearest; an error naming the breaths there
  // are when none is.
  Result<TimelineBreath> breath_near(const PlayerRef& player, double t) const;

 private:
  Session(Document document, stage::StageOptions options)
      : document_(std::move(document)), options_(std::move(options)) {}
  Status replan(const scene::Scene& scene);  // plans into next_
  void adopt();                              // next_ becomes the stage

  Document document_;
  stage::StageOptions options_;
  std::shared_ptr<stage::Stage> stage_;
  std::unique_ptr<stage::Stage> next_;
  Timeline timeline_;
  std::uint64_t stage_revision_ = 0;
  bool models_changed_ = false;
  double last_replan_ms_ = 0.0;
};

}  // namespace tutti::editor
