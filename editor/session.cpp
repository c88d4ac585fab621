#include <tutti/editor/session.hpp>

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

double Session::breath_boundary(std::size_t performer, double t) const {
  // The first playable note of theirs starting at or after t (the notes are in time order).
  const ecs::Entity player = stage_->find_performer("brass", performer);
  if (player.is_null()) return t;
  for (const TimelineLane& lane : timeline_.lanes) {
    if (lane.pianist || lane.performer != performer) continue;
    for (const TimelineNote& note : lane.notes) {
      if (note.playable && note.start_s >= t - 1e-9) return note.start_s;
    }
  }
  return t;
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
