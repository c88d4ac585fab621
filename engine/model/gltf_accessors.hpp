// SPDX-License-Identifier: MIT
#pragma once
// Reading glTF accessors without trusting the file: every accessor is checked against its buffer
// view and buffer (offsets, stride, count, with no integer overflow) and against the component
// types the attribute allows before one byte is read, and its count against a cap before
// anything is allocated. Integer components marked `normalized` map to [0, 1] (unsigned) or
// [-1, 1] (signed) as the glTF spec says. Sparse accessors are made dense before
// (gltf_extensions.hpp); one still sparse here is refused.
//
// Internal to tutti_model. Errors are reasons without the file name ("accessor 4: ...").

#include <tiny_gltf.h>

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include <tutti/core/result.hpp>

namespace tutti::model::detail {

// An accessor's location after all range checks. `data` is null for an accessor without a
// buffer view (all zeros, as the spec says).
struct AccessorSpan {
  const std::uint8_t* data = nullptr;
  std::size_t count = 0;
  std::size_t stride = 0;  // bytes from one element to the next
  int component_type = 0;
  int components = 0;
  bool normalized = false;
};

// Bytes per component (1, 2 or 4), 0 for an unknown type.
std::size_t component_size(int component_type);
// Components per element (SCALAR 1 ... MAT4 16), 0 for an unknown type.
int component_count(int type);

// Checks accessor `index`: in range, of glTF type `type`, with a component type of `allowed`
// (and `normalized` where `allowed_normalized` says which may be), count <= `max_count`, and the
// whole range inside its buffer view and buffer.
struct AccessorRule {
  int type = 0;
  std::vector<int> allowed;             // component types accepted as they are
  std::vector<int> allowed_normalized;  // component types accepted when normalized
  std::size_t max_count = 0;
};
Result<AccessorSpan> locate_accessor(const tinygltf::Model& model, int index,
                                     const AccessorRule& rule);

// Typed reads (they call locate_accessor with the rule the spec gives for the attribute).
// VEC3 attributes: float, or the integer types KHR_mesh_quantization allows for each (positions
// any byte or short, normalized or not; normals normalized byte or short; morph deltas signed).
enum class Vec3Kind { position, normal, morph_position, morph_normal };
Result<std::vector<glm::vec3>> read_vec3(const tinygltf::Model& model, int index,
                                         std::size_t max_count, Vec3Kind kind);
// TEXCOORD_n: VEC2 of float, normalized unsigned byte / short, or (KHR_mesh_quantization) any
// byte or short, normalized or not.
Result<std::vector<glm::vec2>> read_texcoords(const tinygltf::Model& model, int index,
                                              std::size_t max_count);
// JOINTS_n: VEC4 of unsigned byte or unsigned short.
Result<std::vector<glm::uvec4>> read_joints(const tinygltf::Model& model, int index,
                                            std::size_t max_count);
// WEIGHTS_n: VEC4 of float, or normalized unsigned byte / unsigned short.
Result<std::vector<glm::vec4>> read_weights(const tinygltf::Model& model, int index,
                                            std::size_t max_count);
// Indices: SCALAR of unsigned byte, short or int.
Result<std::vector<std::uint32_t>> read_indices(const tinygltf::Model& model, int index,
                                                std::size_t max_count);
// The first `count` elements of a MAT4 of float accessor (column-major, as glm); the accessor
// must have at least `count` (the spec's rule for inverse bind matrices).
Result<std::vector<glm::mat4>> read_mat4s(const tinygltf::Model& model, int index,
                                          std::size_t count);

}  // namespace tutti::model::detail
