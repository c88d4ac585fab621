// SPDX-License-Identifier: MIT
#include <tutti/model/gltf_accessors.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

namespace tutti::model::detail {
namespace {

constexpr std::size_t kMaxStride = 252;  // glTF: byteStride 4..252

std::string type_name(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
      return "VEC2";
    case TINYGLTF_TYPE_VEC3:
      return "VEC3";
    case TINYGLTF_TYPE_VEC4:
      return "VEC4";
    case TINYGLTF_TYPE_MAT2:
      return "MAT2";
    case TINYGLTF_TYPE_MAT3:
      return "MAT3";
    case TINYGLTF_TYPE_MAT4:
      return "MAT4";
    default:
      return "unknown (" + std::to_string(type) + ")";
  }
}

std::string component_name(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return "byte";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return "unsigned byte";
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return "short";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return "unsigned short";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return "unsigned int";
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return "float";
    default:
      return "unknown component type " + std::to_string(component_type);
  }
}

bool contains(const std::vector<int>& list, int value) {
  return std::find(list.begin(), list.end(), value) != list.end();
}

float float_component(const std::uint8_t* p, int component_type, bool normalized) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float f = 0;
      std::memcpy(&f, p, 4);
      return f;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return normalized ? static_cast<float>(p[0]) / 255.0f : static_cast<float>(p[0]);
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      std::int8_t v = 0;
      std::memcpy(&v, p, 1);
      return normalized ? std::max(static_cast<float>(v) / 127.0f, -1.0f) : static_cast<float>(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      std::uint16_t v = 0;
      std::memcpy(&v, p, 2);
      return normalized ? static_cast<float>(v) / 65535.0f : static_cast<float>(v);
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      std::int16_t v = 0;
      std::memcpy(&v, p, 2);
      return normalized ? std::max(static_cast<float>(v) / 32767.0f, -1.0f) : static_cast<float>(v);
    }
    default:
      return 0.0f;  // excluded by locate_accessor's rule
  }
}

std::uint32_t uint_component(const std::uint8_t* p, int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return p[0];
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      std::uint16_t v = 0;
      std::memcpy(&v, p, 2);
      return v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      std::uint32_t v = 0;
      std::memcpy(&v, p, 4);
      return v;
    }
    default:
      return 0;  // excluded by locate_accessor's rule
  }
}

// Calls f(i, element bytes) for every element; an accessor without a buffer view reads zeros.
template <typename F>
void for_each_element(const AccessorSpan& span, F&& f) {
  static constexpr std::array<std::uint8_t, 64> kZeros{};  // the largest element: MAT4 of float
  for (std::size_t i = 0; i < span.count; ++i) {
    f(i, span.data ? span.data + i * span.stride : kZeros.data());
  }
}

}  // namespace

std::size_t component_size(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

int component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    case TINYGLTF_TYPE_MAT2:
      return 4;
    case TINYGLTF_TYPE_MAT3:
      return 9;
    case TINYGLTF_TYPE_MAT4:
      return 16;
    default:
      return 0;
  }
}

Result<AccessorSpan> locate_accessor(const tinygltf::Model& model, int index,
                                     const AccessorRule& rule) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) {
    return Error{"accessor " + std::to_string(index) + " does not exist (the file has " +
                 std::to_string(model.accessors.size()) + ")"};
  }
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
  const std::string what = "accessor " + std::to_string(index);
  if (accessor.sparse.isSparse) return Error{what + ": sparse accessors are not supported"};
  if (accessor.type != rule.type) {
    return Error{what + ": type " + type_name(accessor.type) + ", expected " +
                 type_name(rule.type)};
  }
  const int ct = accessor.componentType;
  const bool accepted =
      accessor.normalized ? contains(rule.allowed_normalized, ct) : contains(rule.allowed, ct);
  if (!accepted) {
    return Error{what + ": component type " + component_name(ct) +
                 (accessor.normalized ? " (normalized)" : "") + " is not allowed here"};
  }
  if (accessor.count > rule.max_count) {
    return Error{what + ": count " + std::to_string(accessor.count) + " is over the limit of " +
                 std::to_string(rule.max_count)};
  }

  AccessorSpan span;
  span.count = accessor.count;
  span.component_type = ct;
  span.components = component_count(accessor.type);
  span.normalized = accessor.normalized;
  const std::size_t element = component_size(ct) * static_cast<std::size_t>(span.components);
  span.stride = element;
  if (accessor.bufferView < 0) return span;  // all zeros

  const auto view_index = static_cast<std::size_t>(accessor.bufferView);
  if (view_index >= model.bufferViews.size()) {
    return Error{what + ": buffer view " + std::to_string(accessor.bufferView) +
                 " does not exist (the file has " + std::to_string(model.bufferViews.size()) + ")"};
  }
  const tinygltf::BufferView& view = model.bufferViews[view_index];
  const std::string view_what = "buffer view " + std::to_string(view_index);
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
    return Error{view_what + ": buffer " + std::to_string(view.buffer) +
                 " does not exist (the file has " + std::to_string(model.buffers.size()) + ")"};
  }
  const std::vector<unsigned char>& buffer =
      model.buffers[static_cast<std::size_t>(view.buffer)].data;
  if (view.byteLength > buffer.size() || view.byteOffset > buffer.size() - view.byteLength) {
    return Error{view_what + ": bytes " + std::to_string(view.byteOffset) + " + " +
                 std::to_string(view.byteLength) + " run past the end of buffer " +
                 std::to_string(view.buffer) + " (" + std::to_string(buffer.size()) + " bytes)"};
  }
  if (view.byteStride != 0) {
    if (view.byteStride < element || view.byteStride > kMaxStride) {
      return Error{view_what + ": byteStride " + std::to_string(view.byteStride) +
                   " does not fit " + what + " (elements of " + std::to_string(element) +
                   " bytes, at most " + std::to_string(kMaxStride) + ")"};
    }
    span.stride = view.byteStride;
  }
  if (accessor.byteOffset > view.byteLength) {
    return Error{what + ": byteOffset " + std::to_string(accessor.byteOffset) +
                 " is past the end of " + view_what + " (" + std::to_string(view.byteLength) +
                 " bytes)"};
  }
  const std::size_t available = view.byteLength - accessor.byteOffset;
  // The last element must end inside the view: (count - 1) * stride + element <= available,
  // written so that nothing overflows.
  if (span.count > 0 &&
      (element > available || span.count - 1 > (available - element) / span.stride)) {
    return Error{what + ": " + std::to_string(span.count) + " elements of " +
                 std::to_string(element) + " bytes (stride " + std::to_string(span.stride) +
                 ") from byte " + std::to_string(accessor.byteOffset) + " run past the end of " +
                 view_what + " (" + std::to_string(view.byteLength) + " bytes)"};
  }
  span.data = buffer.data() + view.byteOffset + accessor.byteOffset;
  return span;
}

Result<std::vector<glm::vec3>> read_vec3(const tinygltf::Model& model, int index,
                                         std::size_t max_count, Vec3Kind kind) {
  constexpr int kByte = TINYGLTF_COMPONENT_TYPE_BYTE;
  constexpr int kUByte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  constexpr int kShort = TINYGLTF_COMPONENT_TYPE_SHORT;
  constexpr int kUShort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
  AccessorRule rule{TINYGLTF_TYPE_VEC3, {kFloat}, {}, max_count};
  // KHR_mesh_quantization's table.
  switch (kind) {
    case Vec3Kind::position:
      rule.allowed = {kFloat, kByte, kUByte, kShort, kUShort};
      rule.allowed_normalized = {kByte, kUByte, kShort, kUShort};
      break;
    case Vec3Kind::normal:
      rule.allowed_normalized = {kByte, kShort};
      break;
    case Vec3Kind::morph_position:
      rule.allowed = {kFloat, kByte, kShort};
      rule.allowed_normalized = {kByte, kShort};
      break;
    case Vec3Kind::morph_normal:
      rule.allowed_normalized = {kByte, kShort};
      break;
  }
  auto span = locate_accessor(model, index, rule);
  if (!span) return span.error();
  const std::size_t size = component_size(span->component_type);
  std::vector<glm::vec3> out(span->count);
  for_each_element(*span, [&](std::size_t i, const std::uint8_t* p) {
    for (int c = 0; c < 3; ++c) {
      out[i][c] = float_component(p + size * static_cast<std::size_t>(c), span->component_type,
                                  span->normalized);
    }
  });
  return out;
}

Result<std::vector<glm::uvec4>> read_joints(const tinygltf::Model& model, int index,
                                            std::size_t max_count) {
  auto span = locate_accessor(
      model, index,
      {TINYGLTF_TYPE_VEC4,
       {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
       {},
       max_count});
  if (!span) return span.error();
  const std::size_t size = component_size(span->component_type);
  std::vector<glm::uvec4> out(span->count);
  for_each_element(*span, [&](std::size_t i, const std::uint8_t* p) {
    for (int c = 0; c < 4; ++c) {
      out[i][c] = uint_component(p + size * static_cast<std::size_t>(c), span->component_type);
    }
  });
  return out;
}

Result<std::vector<glm::vec2>> read_texcoords(const tinygltf::Model& model, int index,
                                              std::size_t max_count) {
  const std::vector<int> integers{TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                  TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};
  std::vector<int> plain = integers;
  plain.push_back(TINYGLTF_COMPONENT_TYPE_FLOAT);
  auto span = locate_accessor(model, index, {TINYGLTF_TYPE_VEC2, plain, integers, max_count});
  if (!span) return span.error();
  const std::size_t size = component_size(span->component_type);
  std::vector<glm::vec2> out(span->count);
  bool finite = true;
  for_each_element(*span, [&](std::size_t i, const std::uint8_t* p) {
    for (int c = 0; c < 2; ++c) {
      out[i][c] = float_component(p + size * static_cast<std::size_t>(c), span->component_type,
                                  span->normalized);
      finite = finite && std::isfinite(out[i][c]);
    }
  });
  if (!finite) return Error{"accessor " + std::to_string(index) + ": a non-finite number"};
  return out;
}

Result<std::vector<glm::vec4>> read_weights(const tinygltf::Model& model, int index,
                                            std::size_t max_count) {
  auto span = locate_accessor(
      model, index,
      {TINYGLTF_TYPE_VEC4,
       {TINYGLTF_COMPONENT_TYPE_FLOAT},
       {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
       max_count});
  if (!span) return span.error();
  const std::size_t size = component_size(span->component_type);
  std::vector<glm::vec4> out(span->count);
  for_each_element(*span, [&](std::size_t i, const std::uint8_t* p) {
    for (int c = 0; c < 4; ++c) {
      out[i][c] = float_component(p + size * static_cast<std::size_t>(c), span->component_type,
                                  span->normalized);
    }
  });
  return out;
}

Result<std::vector<std::uint32_t>> read_indices(const tinygltf::Model& model, int index,
                                                std::size_t max_count) {
  auto span = locate_accessor(
      model, index,
      {TINYGLTF_TYPE_SCALAR,
       {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
        TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
       {},
       max_count});
  if (!span) return span.error();
  std::vector<std::uint32_t> out(span->count);
  for_each_element(*span, [&](std::size_t i, const std::uint8_t* p) {
    out[i] = uint_component(p, span->component_type);
  });
  return out;
}

Result<std::vector<glm::mat4>> read_mat4s(const tinygltf::Model& model, int index,
                                          std::size_t count) {
  auto span = locate_accessor(model, index,
                              {TINYGLTF_TYPE_MAT4,
                               {TINYGLTF_COMPONENT_TYPE_FLOAT},
                               {},
                               std::numeric_limits<std::size_t>::max()});
  if (!span) return span.error();
  if (span->count < count) {
    return Error{"accessor " + std::to_string(index) + ": " + std::to_string(span->count) +
                 " matrices, " + std::to_string(count) + " needed"};
  }
  span->count = count;
  std::vector<glm::mat4> out(span->count);
  for_each_element(*span, [&](std::size_t i, const std::uint8_t* p) {
    for (int col = 0; col < 4; ++col) {
      for (int row = 0; row < 4; ++row) {
        out[i][col][row] = float_component(p + 4 * static_cast<std::size_t>(col * 4 + row),
                                           span->component_type, false);
      }
    }
  });
  return out;
}

}  // namespace tutti::model::detail
