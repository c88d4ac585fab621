#include "runtime/scene_player.hpp"

#include <algorithm>
#include <cstdio>

namespace tutti::runtime {

Result<std::unique_ptr<ScenePlayer>> ScenePlayer::create(render::VulkanContext& context,
                                                         const render::FrameTarget& target,
                                                         const scene::Scene& scene,
                                                         const ScenePlayerOptions& options) {
  std::unique_ptr<ScenePlayer> player(new ScenePlayer());
  auto stage = stage::build_stage(scene, options.stage);
  if (!stage) return Error{scene.source + ": " + stage.error().message};
  player->stage_ = std::move(*stage);
  stage::Stage& st = *player->stage_;

  const std::vector<const model::ModelAsset*> models = st.model_list();
  render::ModelRendererOptions renderer_options = options.renderer;
  if (renderer_options.shadow_taps == 0) {
    renderer_options.shadow_taps = scene.output.soft_shadows ? 4 : 1;
  }
  auto renderer = render::ModelRenderer::create(context, target, models, renderer_options);
  if (!renderer) return renderer.error();
  player->renderer_ = std::move(*renderer);

  TransportOptions transport_options;
  transport_options.start_s = st.start_s;
  transport_options.end_s = st.end_s;
  transport_options.tempo = options.tempo;
  transport_options.sample_rate = options.sound_options.sample_rate;
  OpenAudio open_audio;
  if (options.sound) {
    const stage::Stage* staged = player->stage_.get();
    const SceneSoundOptions sound_options = options.sound_options;
    open_audio = [staged, sound_options](double tempo) {
      return open_scene_sound(*staged, tempo, sound_options);
    };
  }
  auto transport = Transport::create(transport_options, std::move(open_audio));
  if (!transport) return transport.error();
  player->transport_ = std::move(*transport);

  player->lighting_ = stage::lighting_of(st);
  const scene::Color& bg = scene.output.background;
  player->clear_ = {static_cast<float>(bg.r), static_cast<float>(bg.g), static_cast<float>(bg.b),
                    1.0f};
  player->orbit_ = OrbitCamera::from(scene.camera_at(st.start_s));
  player->show(st.start_s);
  return player;
}

double ScenePlayer::update(double host_s) {
  const double t = transport_->update(host_s);
  show(t);
  return t;
}

void ScenePlayer::show(double t_s) {
  shown_s_ = t_s;
  stage::evaluate_stage(*stage_, t_s);
  stage::collect_instances(*stage_, instances_);
}

render::Camera ScenePlayer::camera(float aspect) const {
  switch (mode_) {
    case CameraMode::scene_camera:
      return stage::scene_camera(*stage_, camera_index_, aspect);
    case CameraMode::free:
      return orbit_.camera(aspect);
    case CameraMode::director:
      break;
  }
  return stage::camera_at(*stage_, shown_s_, aspect);
}

Status ScenePlayer::record(const render::RecordingFrame& frame, render::FrameTarget& target) {
  const VkExtent2D extent = target.extent();
  const float aspect =
      static_cast<float>(extent.width) / static_cast<float>(std::max(1u, extent.height));
  return renderer_->record(frame, target, instances_, camera(aspect), lighting_, clear_);
}

void ScenePlayer::set_director() { mode_ = CameraMode::director; }

Status ScenePlayer::set_scene_camera(std::size_t index) {
  if (index >= stage_->scene.cameras.size()) {
    return Error{stage_->scene.source + ": no camera " + std::to_string(index + 1) + " (it has " +
                 std::to_string(stage_->scene.cameras.size()) + ")"};
  }
  mode_ = CameraMode::scene_camera;
  camera_index_ = index;
  return Status::success();
}

void ScenePlayer::set_free_camera() {
  if (mode_ == CameraMode::free) return;
  const scene::Camera& from = mode_ == CameraMode::scene_camera
                                  ? stage_->scene.cameras[camera_index_]
                                  : stage_->scene.camera_at(shown_s_);
  orbit_ = OrbitCamera::from(from);
  mode_ = CameraMode::free;
}

bool ScenePlayer::apply(const Action& action, double host_s, float viewport_height_px) {
  Transport& t = *transport_;
  switch (action.kind) {
    case ActionKind::none:
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
      camera_text = "director (" + stage_->scene.camera_at(shown_s_).name + ")";
      break;
    case CameraMode::scene_camera:
      camera_text = "camera " + std::to_string(camera_index_ + 1) + " (" +
                    stage_->scene.cameras[camera_index_].name + ")";
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
