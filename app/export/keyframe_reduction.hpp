// SPDX-License-Identifier: MIT
#pragma once
// Keyframe reduction for baked animation: which of a channel's evenly spaced samples to keep so
// that glTF's LINEAR interpolation between the kept ones (lerp for vectors and weights, slerp for
// rotations) reproduces every dropped sample within a tolerance.
//
// Greedy: from a kept sample, the next kept one is the farthest (at most `max_span` samples
// on) whose straight segment stays within tolerance of every sample in between. The first and
// last samples are always kept. Pure functions of the samples: the same input gives the same
// keys.

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <span>
#include <vector>

namespace tutti::gltf_export {

// What "without visible error" means, per channel. The defaults: 0.05 mm, 0.01 degree, 1e-4 of
// scale and 0.001 of a morph weight; exporting with them moves no joint of the demo scenes by more
// than half a millimetre in world space (tests/export/performance_export_test.cpp).
struct KeyTolerances {
  float translation_m = 5e-5f;
  float rotation_rad = 1.745329e-4f;  // 0.01 degree
  float scale = 1e-4f;
  float weight = 1e-3f;
  std::size_t max_span = 256;  // samples between two kept keys, at most (bounds the cost)
};

// Kept sample indices, ascending, starting with 0 and ending with samples.size() - 1 (just {0}
// for one sample, nothing for none).
std::vector<std::uint32_t> reduce_vec3(std::span<const glm::vec3> samples, float tolerance,
                                       std::size_t max_span);
// `samples` must be unit quaternions in one hemisphere (consecutive dot products >= 0), as glTF
// interpolates them; the error is the angle between the slerp and the sample.
std::vector<std::uint32_t> reduce_rotation(std::span<const glm::quat> samples, float tolerance_rad,
                                           std::size_t max_span);
// `width` weights per sample (one morph target each), sample-major.
std::vector<std::uint32_t> reduce_weights(std::span<const float> samples, std::size_t width,
                                          float tolerance, std::size_t max_span);

// True when every sample is within `tolerance` of the first (the channel need not be animated).
bool constant_vec3(std::span<const glm::vec3> samples, float tolerance);
bool constant_rotation(std::span<const glm::quat> samples, float tolerance_rad);
bool constant_weights(std::span<const float> samples, std::size_t width, float tolerance);

// The angle between two unit quaternions (q and -q are the same rotation).
float rotation_angle(const glm::quat& a, const glm::quat& b);
// glTF's spherical interpolation, as the validator and importers do it.
glm::quat slerp_shortest(const glm::quat& a, const glm::quat& b, float t);

}  // namespace tutti::gltf_export
