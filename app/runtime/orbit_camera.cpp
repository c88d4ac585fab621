// SPDX-License-Identifier: MIT
#include <tutti/runtime/orbit_camera.hpp>

#include <algorithm>
#include <cmath>

namespace tutti::runtime {

OrbitCamera::OrbitCamera(const glm::vec3& position, const glm::vec3& target, float fov_y_deg,
                         const OrbitLimits& limits)
    : limits_(limits), target_(target), fov_y_deg_(fov_y_deg) {
  const glm::vec3 offset = position - target;  // target → camera
  const float length = glm::length(offset);
  distance_m_ = std::clamp(length, limits_.min_distance_m, limits_.max_distance_m);
  if (length > 0.0f) {
    const float horizontal = std::sqrt(offset.x * offset.x + offset.z * offset.z);
    yaw_deg_ = glm::degrees(std::atan2(offset.x, offset.z));
    pitch_deg_ = glm::degrees(std::atan2(offset.y, horizontal));
  }
  pitch_deg_ = std::clamp(pitch_deg_, limits_.min_pitch_deg, limits_.max_pitch_deg);
}

OrbitCamera OrbitCamera::from(const scene::Camera& camera, const OrbitLimits& limits) {
  const auto v = [](const scene::Vec3& p) {
    return glm::vec3(static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z));
  };
  return OrbitCamera(v(camera.position_m), v(camera.target_m), static_cast<float>(camera.fov_deg),
                     limits);
}

glm::vec3 OrbitCamera::position() const {
  const float yaw = glm::radians(yaw_deg_);
  const float pitch = glm::radians(pitch_deg_);
  const glm::vec3 offset(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                         std::cos(pitch) * std::cos(yaw));
  return target_ + distance_m_ * offset;
}

glm::vec3 OrbitCamera::forward() const { return glm::normalize(target_ - position()); }

void OrbitCamera::orbit(float dx_px, float dy_px) {
  yaw_deg_ = std::remainder(yaw_deg_ - dx_px * limits_.degrees_per_pixel, 360.0f);
  pitch_deg_ = std::clamp(pitch_deg_ + dy_px * limits_.degrees_per_pixel, limits_.min_pitch_deg,
                          limits_.max_pitch_deg);
}

void OrbitCamera::zoom(float wheel_steps) {
  distance_m_ = std::clamp(distance_m_ * std::pow(limits_.zoom_per_step, wheel_steps),
                           limits_.min_distance_m, limits_.max_distance_m);
}

void OrbitCamera::pan(float dx_px, float dy_px, float viewport_height_px) {
  if (!(viewport_height_px > 0.0f)) return;
  // Metres per pixel at the target's depth.
  const float metres_per_px =
      2.0f * distance_m_ * std::tan(glm::radians(fov_y_deg_) * 0.5f) / viewport_height_px;
  const glm::vec3 f = forward();
  const glm::vec3 right = glm::normalize(glm::cross(f, glm::vec3(0.0f, 1.0f, 0.0f)));
  const glm::vec3 up = glm::cross(right, f);
  // Window y grows downwards; dragging right moves the scene right, so the target moves left.
  target_ += metres_per_px * (-dx_px * right + dy_px * up);
}

render::Camera OrbitCamera::camera(float aspect) const {
  return render::look_at_camera(position(), target_, fov_y_deg_, aspect);
}

}  // namespace tutti::runtime
