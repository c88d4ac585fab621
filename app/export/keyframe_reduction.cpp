// SPDX-License-Identifier: MIT
#include <tutti/export/keyframe_reduction.hpp>

#include <algorithm>
#include <cmath>

namespace tutti::gltf_export {
namespace {

// `fits(a, b)`: the segment from kept sample a to candidate b stays within tolerance of every
// sample strictly between them.
template <typename Fits>
std::vector<std::uint32_t> reduce(std::size_t count, std::size_t max_span, Fits fits) {
  std::vector<std::uint32_t> keys;
  if (count == 0) return keys;
  keys.push_back(0);
  const std::size_t span = std::max<std::size_t>(max_span, 1);
  std::size_t from = 0;
  while (from + 1 < count) {
    std::size_t to = from + 1;
    while (to + 1 < count && to + 1 - from <= span && fits(from, to + 1)) ++to;
    keys.push_back(static_cast<std::uint32_t>(to));
    from = to;
  }
  return keys;
}

float fraction(std::size_t from, std::size_t to, std::size_t k) {
  return static_cast<float>(k - from) / static_cast<float>(to - from);
}

}  // namespace

float rotation_angle(const glm::quat& a, const glm::quat& b) {
  // |a - b| = 2 sin(angle / 4) for unit quaternions: exact for small angles, where 2 acos(a . b)
  // in float cannot tell anything under about 0.04 degrees apart.
  const glm::dvec4 da(a.x, a.y, a.z, a.w);
  glm::dvec4 db(b.x, b.y, b.z, b.w);
  if (glm::dot(da, db) < 0.0) db = -db;
  const double chord = std::min(2.0, glm::length(da - db));
  return static_cast<float>(4.0 * std::asin(chord / 2.0));
}

glm::quat slerp_shortest(const glm::quat& a, const glm::quat& b, float t) {
  float d = glm::dot(a, b);
  glm::quat target = b;
  if (d < 0.0f) {
    target = -b;
    d = -d;
  }
  if (d > 0.9995f) return glm::normalize(a * (1.0f - t) + target * t);
  const float theta = std::acos(d);
  const float s = std::sin(theta);
  return glm::normalize(a * (std::sin((1.0f - t) * theta) / s) +
                        target * (std::sin(t * theta) / s));
}

std::vector<std::uint32_t> reduce_vec3(std::span<const glm::vec3> samples, float tolerance,
                                       std::size_t max_span) {
  return reduce(samples.size(), max_span, [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from + 1; k < to; ++k) {
      const glm::vec3 line = glm::mix(samples[from], samples[to], fraction(from, to, k));
      if (glm::length(line - samples[k]) > tolerance) return false;
    }
    return true;
  });
}

std::vector<std::uint32_t> reduce_rotation(std::span<const glm::quat> samples, float tolerance_rad,
                                           std::size_t max_span) {
  return reduce(samples.size(), max_span, [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from + 1; k < to; ++k) {
      const glm::quat arc = slerp_shortest(samples[from], samples[to], fraction(from, to, k));
      if (rotation_angle(arc, samples[k]) > tolerance_rad) return false;
    }
    return true;
  });
}

std::vector<std::uint32_t> reduce_weights(std::span<const float> samples, std::size_t width,
                                          float tolerance, std::size_t max_span) {
  if (width == 0) return {};
  const std::size_t count = samples.size() / width;
  return reduce(count, max_span, [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from + 1; k < to; ++k) {
      const float t = fraction(from, to, k);
      for (std::size_t w = 0; w < width; ++w) {
        const float a = samples[from * width + w];
        const float b = samples[to * width + w];
        if (std::fabs(a + (b - a) * t - samples[k * width + w]) > tolerance) return false;
      }
    }
    return true;
  });
}

bool constant_vec3(std::span<const glm::vec3> samples, float tolerance) {
  return std::all_of(samples.begin(), samples.end(), [&](const glm::vec3& s) {
    return glm::length(s - samples.front()) <= tolerance;
  });
}

bool constant_rotation(std::span<const glm::quat> samples, float tolerance_rad) {
  return std::all_of(samples.begin(), samples.end(), [&](const glm::quat& s) {
    return rotation_angle(s, samples.front()) <= tolerance_rad;
  });
}

bool constant_weights(std::span<const float> samples, std::size_t width, float tolerance) {
  for (std::size_t i = width; i < samples.size(); ++i) {
    if (std::fabs(samples[i] - samples[i % width]) > tolerance) return false;
  }
  return true;
}

}  // namespace tutti::gltf_export
