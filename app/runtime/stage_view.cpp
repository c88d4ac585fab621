// SPDX-License-Identifier: MIT
#include <tutti/runtime/stage_view.hpp>

namespace tutti::runtime {
namespace {

glm::vec3 to_vec3(const scene::Vec3& v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}
glm::vec3 to_vec3(const scene::Color& c) {
  return {static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b)};
}

render::Camera camera_from(const scene::Camera& camera, float aspect) {
  return render::look_at_camera(to_vec3(camera.position_m), to_vec3(camera.target_m),
                                static_cast<float>(camera.fov_deg), aspect);
}

}  // namespace

namespace {

template <typename Placed>
void collect_placed(std::size_t count, const Placed& placed_model,
                    std::vector<render::ModelInstance>& out) {
  out.clear();
  for (std::size_t i = 0; i < count; ++i) {
    const stage::PlacedModel& placed = placed_model(i);
    out.push_back({placed.model, &placed.pose, placed.root, placed.casts_shadows});
  }
}

}  // namespace

void collect_instances(const stage::Stage& stage, std::vector<render::ModelInstance>& out) {
  collect_placed(
      stage.instances().size(),
      [&](std::size_t i) -> const stage::PlacedModel& { return stage.placed(i); }, out);
}

void collect_instances(const stage::Stage& stage, const stage::StageContext& context,
                       std::vector<render::ModelInstance>& out) {
  collect_placed(
      stage.instances().size(),
      [&](std::size_t i) -> const stage::PlacedModel& { return context.placed(i); }, out);
}

render::Camera camera_at(const stage::Stage& stage, double t_s, float aspect) {
  return camera_from(stage.scene().camera_at(t_s), aspect);
}

render::Camera scene_camera(const stage::Stage& stage, std::size_t index, float aspect) {
  return camera_from(stage.scene().cameras[index], aspect);
}

render::Lighting lighting_of(const stage::Stage& stage) {
  const scene::Lights& lights = stage.scene().lights;
  render::Lighting out;
  out.key = {to_vec3(lights.key.direction), to_vec3(lights.key.color),
             static_cast<float>(lights.key.intensity)};
  out.fill = {to_vec3(lights.fill.direction), to_vec3(lights.fill.color),
              static_cast<float>(lights.fill.intensity)};
  out.sky = to_vec3(lights.ambient_sky);
  out.ground = to_vec3(lights.ambient_ground);
  // Shadows cover everyone on stage plus a margin for bodies, stands and instruments.
  glm::vec3 lo(-1.0f, 0.0f, -1.0f);
  glm::vec3 hi(1.0f, 2.0f, 1.0f);
  for (std::size_t i = 0; i < stage.instances().size(); ++i) {
    const stage::PlacedModel& placed = stage.placed(i);
    if (!placed.casts_shadows) continue;  // the floor itself
    const glm::vec3 p(placed.root[3]);
    lo = glm::min(lo, p - glm::vec3(1.0f, 0.0f, 1.0f));
    hi = glm::max(hi, p + glm::vec3(1.0f, 2.0f, 1.0f));
  }
  out.shadow_center = 0.5f * (lo + hi);
  out.shadow_radius = 0.5f * glm::length(hi - lo);
  return out;
}

render::ClearColor background_of(const stage::Stage& stage) {
  const scene::Color& bg = stage.scene().output.background;
  return {static_cast<float>(bg.r), static_cast<float>(bg.g), static_cast<float>(bg.b), 1.0f};
}

}  // namespace tutti::runtime
