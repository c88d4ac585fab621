// SPDX-License-Identifier: MIT
#include <tutti/runtime/stage_renderer.hpp>

#include <tutti/runtime/stage_view.hpp>

namespace tutti::runtime {

Result<std::unique_ptr<StageRenderer>> StageRenderer::create(
    render::VulkanContext& context, const render::FrameTarget& target, const stage::Stage& stage,
    const render::ModelRendererOptions& options) {
  std::unique_ptr<StageRenderer> out(new StageRenderer());
  out->options_ = options;
  if (Status s = out->use_stage(context, target, stage, true); !s) return s.error();
  return out;
}

Status StageRenderer::make_renderer(render::VulkanContext& context,
                                    const render::FrameTarget& target, const stage::Stage& stage) {
  const std::vector<const model::ModelAsset*> models = stage.model_list();
  if (renderer_) vkDeviceWaitIdle(context.device());  // frames in flight still read its buffers
  renderer_.reset();
  auto renderer = render::ModelRenderer::create(context, target, models, options_);
  if (!renderer) return renderer.error();
  renderer_ = std::move(*renderer);
  return Status::success();
}

Status StageRenderer::use_stage(render::VulkanContext& context, const render::FrameTarget& target,
                                const stage::Stage& stage, bool models_changed) {
  if (models_changed || !renderer_) {
    if (Status s = make_renderer(context, target, stage); !s) return s;
  }
  lighting_ = lighting_of(stage);
  clear_ = background_of(stage);
  return Status::success();
}

Status StageRenderer::record(const render::RecordingFrame& frame, render::FrameTarget& target,
                             const stage::Stage& stage, const stage::StageContext& posed,
                             const render::Camera& camera) {
  collect_instances(stage, posed, instances_);
  return renderer_->record(frame, target, instances_, camera, lighting_, clear_);
}

}  // namespace tutti::runtime
