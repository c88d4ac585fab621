// SPDX-License-Identifier: MIT
#pragma once
// OrbitCamera: the free camera of `tutti play` and the editor. It circles a target point
// (yaw about +Y, pitch above the horizon), zooms along the line of sight and pans the target in
// the view plane, so the point looked at always stays under the same pixel while orbiting.
//
//   OrbitCamera orbit = OrbitCamera::from(scene.cameras[0]);
//   orbit.orbit(dx, dy);       // mouse drag, pixels
//   orbit.zoom(wheel);         // wheel steps (+ = closer)
//   render::Camera c = orbit.camera(aspect);
//
// Pure arithmetic, no state beyond the five numbers below.

#include <glm/glm.hpp>

#include <tutti/render/model_renderer.hpp>
#include <tutti/scene/scene.hpp>

namespace tutti::runtime {

struct OrbitLimits {
  float min_pitch_deg = -85.0f;  // never straight up or down: look_at needs a horizon
  float max_pitch_deg = 85.0f;
  float min_distance_m = 0.2f;
  float max_distance_m = 60.0f;
  float degrees_per_pixel = 0.3f;
  float zoom_per_step = 0.9f;  // distance × this per wheel step towards the target
};

class OrbitCamera {
 public:
  OrbitCamera() = default;
  // Looking from `position` at `target` with a vertical field of view.
  OrbitCamera(const glm::vec3& position, const glm::vec3& target, float fov_y_deg,
              const OrbitLimits& limits = {});
  static OrbitCamera from(const scene::Camera& camera, const OrbitLimits& limits = {});

  // Mouse drag: dx turns about the vertical axis (right = the camera moves right round the
  // target), dy tilts (down = the camera rises). Pitch stays within the limits.
  void orbit(float dx_px, float dy_px);
  // Positive steps move closer (distance × zoom_per_step^steps), clamped.
  void zoom(float wheel_steps);
  // Drags the scene with the mouse: the target moves in the view plane so a point at the
  // target's depth follows the pointer. viewport_height_px > 0.
  void pan(float dx_px, float dy_px, float viewport_height_px);

  render::Camera camera(float aspect) const;

  glm::vec3 target() const { return target_; }
  glm::vec3 position() const;
  float yaw_deg() const { return yaw_deg_; }
  float pitch_deg() const { return pitch_deg_; }
  float distance_m() const { return distance_m_; }
  float fov_y_deg() const { return fov_y_deg_; }

 private:
  glm::vec3 forward() const;  // from the camera towards the target

  OrbitLimits limits_;
  glm::vec3 target_{0.0f, 1.0f, 0.0f};
  float yaw_deg_ = 0.0f;  // 0: the camera on +Z of the target, looking down −Z
  float pitch_deg_ = 0.0f;
  float distance_m_ = 5.0f;
  float fov_y_deg_ = 40.0f;
};

}  // namespace tutti::runtime
