// SPDX-License-Identifier: MIT
#include <tutti/editor/session.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <chrono>

#include <tutti/performance/families.hpp>

namespace tutti::editor {

Result<std::unique_ptr<Session>> Session::open(const std::filesystem::path& scene,
                                               const stage::StageOptions& options) {
  auto document = Document::open(scene);
  if (!document) return document.error();
  std::unique_ptr<Session> session(new Session(std::move(*document), options));
  if (Status s = session->replan(session->document_.scene()); !s) return s.error();
  session->adopt();
  session->models_changed_ = true;
  return session;
}

Status Session::replan(const scene::Scene& scene) {
  const auto start = std::chrono::steady_clock::now();
  stage::StageOptions options = options_;
  options.reuse_models = stage_.get();
  auto stage = performance::build_stage(scene, options);
  if (!stage) return stage.error();
  next_ = std::move(*stage);
  last_replan_ms_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return Status::success();
}

void Session::adopt() {
  models_changed_ = !stage_ || stage_->models() != next_->models();
  stage_ = std::move(next_);
  timeline_ = build_timeline(*stage_);
  ++stage_revision_;
}

Status Session::apply(Result<Edit> edit, bool coalesce) {
  if (!edit) return edit.error();
  const auto check = [this](const scene::Scene& scene) { return replan(scene); };
  if (Status s = document_.apply(std::move(*edit), coalesce, check); !s) return s;
  adopt();
  return Status::success();
}

Status Session::undo() {
  if (Status s = document_.undo([this](const scene::Scene& scene) { return replan(scene); }); !s) {
    return s;
  }
  adopt();
  return Status::success();
}

Status Session::redo() {
  if (Status s = document_.redo([this](const scene::Scene& scene) { return replan(scene); }); !s) {
    return s;
  }
  adopt();
  return Status::success();
}

double Session::breath_boundary(const PlayerRef& player, double t) const {
  // The first playable note of theirs starting at or after t (the notes are in time order).
  for (const TimelineLane& lane : timeline_.lanes) {
    if (!lane.breathes || lane.player != player.pointer) continue;
    for (const TimelineNote& note : lane.notes) {
      // Times are written to the millisecond: a note up to half of one before t is t's.
      if (note.playable && note.start_s >= t - 0.0005) return note.start_s;
    }
  }
  return t;
}

Result<TimelineBreath> Session::breath_near(const PlayerRef& player, double t) const {
  for (const TimelineLane& lane : timeline_.lanes) {
    if (!lane.breathes || lane.player != player.pointer) continue;
    const TimelineBreath* best = nullptr;
    for (const TimelineBreath& breath : lane.breaths) {
      const bool near = std::abs(breath.boundary_s - t) <= 0.1 ||
                        (t >= breath.prepare_s - 1e-9 && t <= breath.end_s + 1e-9);
      if (near && (best == nullptr || std::abs(breath.boundary_s - t) < std::abs(best->boundary_s - t))) {
        best = &breath;
      }
    }
    if (best != nullptr) return *best;
    std::vector<const TimelineBreath*> nearest;
    for (const TimelineBreath& breath : lane.breaths) nearest.push_back(&breath);
    std::sort(nearest.begin(), nearest.end(), [&](const TimelineBreath* a, const TimelineBreath* b) {
      return std::abs(a->boundary_s - t) < std::abs(b->boundary_s - t);
    });
    if (nearest.size() > 4) nearest.resize(4);
    std::sort(nearest.begin(), nearest.end(), [](const TimelineBreath* a, const TimelineBreath* b) {
      return a->boundary_s < b->boundary_s;
    });
    std::string list;
    for (const TimelineBreath* breath : nearest) {
      char text[32];
      std::snprintf(text, sizeof text, "%.3f", breath->boundary_s);
      list += (list.empty() ? "" : ", ") + std::string(text);
    }
    char at[32];
    std::snprintf(at, sizeof at, "%.3f", t);
    return Error{"no breath of \"" + lane.name + "\" at " + at + " s" +
                 (list.empty() ? std::string(" (it has none)") : " (nearest at " + list + " s)")};
  }
  return Error{"\"" + (player.name.empty() ? player.pointer : player.name) +
               "\" has no breaths (its family plans none)"};
}

Status Session::recover_autosave() {
  if (Status s =
          document_.recover_autosave([this](const scene::Scene& scene) { return replan(scene); });
      !s) {
    return s;
  }
  adopt();
  return Status::success();
}

}  // namespace tutti::editor
