// SPDX-License-Identifier: MIT
#include <tutti/runtime/scene_player.hpp>

#include <algorithm>
#include <cstdio>

#include <tutti/performance/families.hpp>
#include <tutti/runtime/stage_view.hpp>

namespace tutti::runtime {

Result<std::unique_ptr<ScenePlayer>> ScenePlayer::create(render::VulkanContext& context,
                                                         const render::FrameTarget& target,
                                                         const scene::Scene& scene,
                                                         const ScenePlayerOptions& options) {
  std::unique_ptr<ScenePlayer> player(new ScenePlayer());
  auto stage = performance::build_stage(scene, options.stage);
  if (!stage) return Error{scene.source + ": " + stage.error().message};
  player->owned_stage_ = std::move(*stage);
  player->stage_ = player->owned_stage_.get();
  if (Status s = player->init(context, target, options); !s) return s.error();
  return player;
}

Result<std::unique_ptr<ScenePlayer>> ScenePlayer::create(render::VulkanContext& context,
                                                         const render::FrameTarget& target,
                                                         std::shared_ptr<stage::Stage> stage,
                                                         const ScenePlayerOptions& options) {
  std::unique_ptr<ScenePlayer> player(new ScenePlayer());
  player->stage_ = stage.get();
  player->owned_stage_ = std::move(stage);
  if (Status s = player->init(context, target, options); !s) return s.error();
  return player;
}

Status ScenePlayer::init(render::VulkanContext& context, const render::FrameTarget& target,
                         const ScenePlayerOptions& options) {
  stage::Stage& st = *stage_;
  posed_.emplace(st.make_context());
  const scene::Scene& scene = st.scene();
  render::ModelRendererOptions renderer_options = options.renderer;
  if (renderer_options.shadow_taps == 0) {
    renderer_options.shadow_taps = scene.output.soft_shadows ? 4 : 1;
  }
  auto stage_renderer = StageRenderer::create(context, target, st, renderer_options);
  if (!stage_renderer) return stage_renderer.error();
  stage_renderer_ = std::move(*stage_renderer);

  TransportOptions transport_options;
  transport_options.start_s = st.start_s();
  transport_options.end_s = st.end_s();
  transport_options.tempo = options.tempo;
  transport_options.sample_rate = options.sound_options.sample_rate;
  OpenAudio open_audio;
  if (options.sound) {
    // The stage playing when the sound is opened (use_stage may switch it).
    const SceneSoundOptions sound_options = options.sound_options;
    open_audio = [this, sound_options](double tempo) {
      return open_scene_sound(*stage_, tempo, sound_options);
    };
  }
  auto transport = Transport::create(transport_options, std::move(open_audio));
  if (!transport) return transport.error();
  transport_ = std::move(*transport);

  orbit_ = OrbitCamera::from(scene.camera_at(st.start_s()));
  show(st.start_s());
  return Status::success();
}

namespace {

// The notes heard, as (onset, offset, key) of every score: what the sound is made from.
bool same_sound(const stage::Stage& a, const stage::Stage& b) {
  const std::vector<music::Score> heard_a = a.heard_scores();
  const std::vector<music::Score> heard_b = b.heard_scores();
  if (heard_a.size() != heard_b.size()) return false;
  for (std::size_t s = 0; s < heard_a.size(); ++s) {
    const auto& x = heard_a[s].notes;
    const auto& y = heard_b[s].notes;
    if (x.size() != y.size()) return false;
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (x[i].onset_s != y[i].onset_s || x[i].offset_s != y[i].offset_s ||
          x[i].pitch != y[i].pitch || x[i].velocity != y[i].velocity) {
        return false;
      }
    }
  }
  return true;
}

}  // namespace

Status ScenePlayer::use_stage(render::VulkanContext& context, const render::FrameTarget& target,
                              std::shared_ptr<stage::Stage> next, bool models_changed,
                              double host_s) {
  stage::Stage& stage = *next;
  const bool sound_changed = !same_sound(*stage_, stage);
  stage_ = &stage;
  posed_.emplace(stage.make_context());
  owned_stage_ = std::move(next);  // the previous stage may go now
  if (Status s = stage_renderer_->use_stage(context, target, stage, models_changed); !s) return s;
  if (camera_index_ >= stage.scene().cameras.size()) mode_ = CameraMode::director;
  if (sound_changed) {
    if (Status s = transport_->reopen_sound(host_s); !s) return s;
  }
  show(shown_s_);
  return Status::success();
}

double ScenePlayer::update(double host_s) {
  transport_->update(host_s);
  // The frame's time is the transport's audio clock, given to the frame as its argument.
  shown_s_ = transport_->clock().time();
  stage_->run(*posed_, {shown_s_, 0.0});
  return shown_s_;
}

void ScenePlayer::show(double t_s) {
  shown_s_ = t_s;
  stage_->run(*posed_, {t_s, 0.0});
}

render::Camera ScenePlayer::camera(float aspect) const {
  switch (mode_) {
    case CameraMode::scene_camera:
      return scene_camera(*stage_, camera_index_, aspect);
    case CameraMode::free:
      return orbit_.camera(aspect);
    case CameraMode::director:
      break;
  }
  return camera_at(*stage_, shown_s_, aspect);
}

Status ScenePlayer::record(const render::RecordingFrame& frame, render::FrameTarget& target) {
  const VkExtent2D extent = target.extent();
  const float aspect =
      static_cast<float>(extent.width) / static_cast<float>(std::max(1u, extent.height));
  return stage_renderer_->record(frame, target, *stage_, *posed_, camera(aspect));
}

void ScenePlayer::set_director() { mode_ = CameraMode::director; }

Status ScenePlayer::set_scene_camera(std::size_t index) {
  if (index >= stage_->scene().cameras.size()) {
    return Error{stage_->scene().source + ": no camera " + std::to_string(index + 1) + " (it has " +
                 std::to_string(stage_->scene().cameras.size()) + ")"};
  }
  mode_ = CameraMode::scene_camera;
  camera_index_ = index;
  return Status::success();
}

void ScenePlayer::set_free_camera() {
  if (mode_ == CameraMode::free) return;
  const scene::Camera& from = mode_ == CameraMode::scene_camera
                                  ? stage_->scene().cameras[camera_index_]
                                  : stage_->scene().camera_at(shown_s_);
  orbit_ = OrbitCamera::from(from);
  mode_ = CameraMode::free;
}

bool ScenePlayer::apply(const Action& action, double host_s, float viewport_height_px) {
  Transport& t = *transport_;
  switch (action.kind) {
    case ActionKind::none:
    case ActionKind::toggle_stats:  // drawn by the host (tutti play, the editor)
      break;
    case ActionKind::toggle_play:
      t.toggle(host_s);
      break;
    case ActionKind::seek_by:
      t.seek(host_s, t.time() + action.amount);
      break;
    case ActionKind::seek_to_start:
      t.seek(host_s, t.start_s());
      break;
    case ActionKind::director:
      set_director();
      break;
    case ActionKind::scene_camera:
      (void)set_scene_camera(static_cast<std::size_t>(action.index));  // no such camera: ignored
      break;
    case ActionKind::free_camera:
      set_free_camera();
      break;
    case ActionKind::loop_start:
      t.set_loop_start(host_s, t.time());
      break;
    case ActionKind::loop_end:
      t.set_loop_end(host_s, t.time());
      break;
    case ActionKind::loop_clear:
      t.clear_loop();
      break;
    case ActionKind::tempo_down:
    case ActionKind::tempo_up:
      // A failure to reopen the sound keeps the old tempo playing.
      (void)t.set_tempo(host_s,
                        step_tempo(t.tempo(), action.kind == ActionKind::tempo_up ? 1 : -1));
      break;
    case ActionKind::quit:
      return false;
    case ActionKind::orbit:
      set_free_camera();
      orbit_.orbit(action.dx, action.dy);
      break;
    case ActionKind::pan:
      set_free_camera();
      orbit_.pan(action.dx, action.dy, viewport_height_px);
      break;
    case ActionKind::zoom:
      set_free_camera();
      orbit_.zoom(static_cast<float>(action.amount));
      break;
  }
  return true;
}

std::string ScenePlayer::status_line() const {
  const Transport& t = *transport_;
  std::string camera_text;
  switch (mode_) {
    case CameraMode::director:
      camera_text = "director (" + stage_->scene().camera_at(shown_s_).name + ")";
      break;
    case CameraMode::scene_camera:
      camera_text = "camera " + std::to_string(camera_index_ + 1) + " (" +
                    stage_->scene().cameras[camera_index_].name + ")";
      break;
    case CameraMode::free:
      camera_text = "free camera";
      break;
  }
  char line[256];
  std::snprintf(line, sizeof line, "%.1f / %.1f s  %s  %s  tempo %.2f", shown_s_, t.end_s(),
                t.playing() ? "playing" : "paused", camera_text.c_str(), t.tempo());
  std::string text = line;
  if (const std::optional<LoopRange> loop = t.loop()) {
    std::snprintf(line, sizeof line, "  loop %.1f-%.1f", loop->from_s, loop->to_s);
    text += line;
  }
  return text;
}

}  // namespace tutti::runtime
