// SPDX-License-Identifier: MIT
#pragma once
// ScenePlayer: a scene performing live — the staged scene (stage::Stage), its renderer for one
// FrameTarget, the transport (sound and clock) and the camera: the scene's shot list
// ("director"), one scene camera, or the free orbit camera. `tutti play` and the editor are
// thin loops around it; a game embeds it the same way (docs/embedding.md).
//
//   auto player = ScenePlayer::create(context, target, scene, options);
//   player->transport().play(now());
//   every frame:
//     player->update(now());                       // or show(t) with your own clock
//     auto frame = target.begin_frame();
//     player->record(*frame, target);              // shadow pass + 3D main pass
//     // extra drawing into the same image here (WindowTarget's overlay pass: ImGui)
//     target.end_frame();

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/render/frame_target.hpp>
#include <tutti/render/model_renderer.hpp>
#include <tutti/render/vulkan_context.hpp>
#include <tutti/runtime/input_bindings.hpp>
#include <tutti/runtime/orbit_camera.hpp>
#include <tutti/runtime/scene_sound.hpp>
#include <tutti/runtime/transport.hpp>
#include <tutti/scene/scene.hpp>
#include <tutti/runtime/stage_renderer.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::runtime {

enum class CameraMode { director, scene_camera, free };

struct ScenePlayerOptions {
  stage::StageOptions stage;
  render::ModelRendererOptions renderer;  // shadow_taps: 0 = the scene's (soft: 4, hard: 1)
  double tempo = 1.0;
  bool sound = true;  // false: silent, the clock runs on the host's time
  SceneSoundOptions sound_options;
};

class ScenePlayer {
 public:
  // Builds the stage (the slow step: planning every performer), the renderer for `target`'s
  // formats and the transport, paused at the scene's start.
  static Result<std::unique_ptr<ScenePlayer>> create(render::VulkanContext& context,
                                                     const render::FrameTarget& target,
                                                     const scene::Scene& scene,
                                                     const ScenePlayerOptions& options = {});
  // Plays a stage planned elsewhere (the editor's session); `options.stage` unused. The player
  // shares it, so it lives until the player has moved on to another (use_stage).
  static Result<std::unique_ptr<ScenePlayer>> create(render::VulkanContext& context,
                                                     const render::FrameTarget& target,
                                                     std::shared_ptr<stage::Stage> stage,
                                                     const ScenePlayerOptions& options = {});
  // Switches to another stage of the same scene (re-planned after an edit), keeping the time,
  // the camera and the transport. `models_changed`: its models are not the ones the renderer
  // was made for (it is made again). The sound is opened again when what is heard changed.
  Status use_stage(render::VulkanContext& context, const render::FrameTarget& target,
                   std::shared_ptr<stage::Stage> stage, bool models_changed, double host_s);

  // The transport's time at host_s, and the stage posed there. Returns the music time.
  double update(double host_s);
  // Poses the stage at music time t_s (your clock; the transport is left alone).
  void show(double t_s);
  // Where it poses the stage and what it draws: a sampling context of its own (the stage's
  // own world is only read, so an editor's session or another thread may use the stage too).
  // Made again with each stage (use_stage). Write into its world what should change what is
  // shown (the live player's motion).
  stage::StageContext& posed() { return *posed_; }
  const stage::StageContext& posed() const { return *posed_; }
  double shown_time() const { return shown_s_; }

  // Shadow pass and main pass (begin_main_pass .. end_main_pass) of `frame` with the current
  // camera, the scene's lighting and background. Aspect from target.extent().
  Status record(const render::RecordingFrame& frame, render::FrameTarget& target);

  // Key / mouse actions (input_bindings.hpp). Returns false for ActionKind::quit.
  bool apply(const Action& action, double host_s, float viewport_height_px);

  void set_director();
  Status set_scene_camera(std::size_t index);
  // The orbit camera starts where the shown camera is.
  void set_free_camera();
  CameraMode camera_mode() const { return mode_; }
  std::size_t camera_index() const { return camera_index_; }
  render::Camera camera(float aspect) const;
  OrbitCamera& orbit_camera() { return orbit_; }

  Transport& transport() { return *transport_; }
  const Transport& transport() const { return *transport_; }
  stage::Stage& stage() { return *stage_; }
  const stage::Stage& stage() const { return *stage_; }
  const render::ModelRenderer& renderer() const { return stage_renderer_->renderer(); }

  // "12.3 / 95.0 s  playing  camera 2 (wide)  tempo 0.75  loop 10.0-20.0" for a title bar.
  std::string status_line() const;

 private:
  ScenePlayer() = default;

  Status init(render::VulkanContext& context, const render::FrameTarget& target,
              const ScenePlayerOptions& options);

  std::shared_ptr<stage::Stage> owned_stage_;  // what stage_ points into, kept alive
  stage::Stage* stage_ = nullptr;
  std::optional<stage::StageContext> posed_;  // made from *stage_
  std::unique_ptr<StageRenderer> stage_renderer_;
  std::unique_ptr<Transport> transport_;
  CameraMode mode_ = CameraMode::director;
  std::size_t camera_index_ = 0;
  OrbitCamera orbit_;
  double shown_s_ = 0.0;
};

}  // namespace tutti::runtime
