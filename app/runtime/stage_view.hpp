// SPDX-License-Identifier: MIT
#pragma once
// A stage as the renderer sees it: its placed models as render instances (pointing into the
// PlacedModel components, as the last Stage::run posed them, or as a sampling context's last run
// did), the shot list's or a scene camera, and the scene's lights with a shadow volume fitted
// around everything placed.

#include <cstddef>
#include <vector>

#include <tutti/render/model_renderer.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::runtime {

void collect_instances(const stage::Stage& stage, std::vector<render::ModelInstance>& out);
// The same as `context` posed them (Stage::run(context, ...)).
void collect_instances(const stage::Stage& stage, const stage::StageContext& context,
                       std::vector<render::ModelInstance>& out);
// The shot list's camera at t_s.
render::Camera camera_at(const stage::Stage& stage, double t_s, float aspect);
// The scene's camera number `camera` (Scene::cameras), whatever the shot list says.
render::Camera scene_camera(const stage::Stage& stage, std::size_t camera, float aspect);
render::Lighting lighting_of(const stage::Stage& stage);
render::ClearColor background_of(const stage::Stage& stage);

}  // namespace tutti::runtime
