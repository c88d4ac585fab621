// SPDX-License-Identifier: MIT
#pragma once
// Draws a stage as its last Stage::run posed it: a model renderer made for the stage's models, the
// scene's lights and background, the caller's camera. `tutti render` (offscreen) and ScenePlayer
// (`tutti play`, the editor; a window) both draw through it.

#include <memory>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/render/frame_target.hpp>
#include <tutti/render/model_renderer.hpp>
#include <tutti/render/vulkan_context.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::runtime {

class StageRenderer {
 public:
  static Result<std::unique_ptr<StageRenderer>> create(render::VulkanContext& context,
                                                       const render::FrameTarget& target,
                                                       const stage::Stage& stage,
                                                       const render::ModelRendererOptions& options);

  // Another stage of the same scene (re-planned after an edit): its lights and background; the
  // model renderer is made again when the stage's models are not the ones it was made for.
  Status use_stage(render::VulkanContext& context, const render::FrameTarget& target,
                   const stage::Stage& stage, bool models_changed);

  // Shadow pass and main pass of `frame`: `stage`'s placed models as `posed` (a sampling
  // context of `stage`: every renderer draws a context's output) last posed them, seen by
  // `camera`.
  Status record(const render::RecordingFrame& frame, render::FrameTarget& target,
                const stage::Stage& stage, const stage::StageContext& posed,
                const render::Camera& camera);

  const render::ModelRenderer& renderer() const { return *renderer_; }

 private:
  StageRenderer() = default;
  Status make_renderer(render::VulkanContext& context, const render::FrameTarget& target,
                       const stage::Stage& stage);

  render::ModelRendererOptions options_;
  std::unique_ptr<render::ModelRenderer> renderer_;
  render::Lighting lighting_;
  render::ClearColor clear_;
  std::vector<render::ModelInstance> instances_;
};

}  // namespace tutti::runtime
