// SPDX-License-Identifier: MIT
#pragma once
// A glTF 2.0 binary (.glb) built in memory: the JSON document (nlohmann, keys sorted, so the same
// calls give the same bytes) and one BIN buffer that accessors append to. Every buffer view is
// 4-byte aligned and tightly packed (no byteStride); float accessors can carry min/max (the spec
// requires them for POSITION and animation inputs).

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tutti::gltf_export {

enum class BufferTarget { none = 0, vertices = 34962, indices = 34963 };

class GlbBuilder {
 public:
  GlbBuilder();

  nlohmann::json& document() { return document_; }

  // `type` is the glTF accessor type ("SCALAR", "VEC3", "VEC4", "MAT4"); the value count must be
  // a multiple of its width. Returns the accessor index.
  int add_floats(std::span<const float> values, std::string_view type, BufferTarget target,
                 bool with_min_max);
  int add_indices(std::span<const std::uint32_t> indices);  // u16 when every value fits, else u32
  int add_joints(std::span<const std::uint16_t> joints);    // JOINTS_0: unsigned short VEC4

  // An image's file bytes (PNG, JPEG, WebP) as a buffer view; returns the view's index.
  int add_image_bytes(std::span<const std::uint8_t> bytes);
  // Adds `name` to extensionsUsed (and extensionsRequired when `required`), once.
  void use_extension(const std::string& name, bool required);

  // Appends `value` to document[key] (an array, created when missing) and returns its index.
  int append(const char* key, nlohmann::json value);

  std::size_t binary_size() const { return binary_.size(); }
  // The .glb bytes: header, JSON chunk (space-padded), BIN chunk (zero-padded).
  std::vector<std::uint8_t> finish() const;

 private:
  int add_view(std::span<const std::byte> bytes, BufferTarget target);
  nlohmann::json document_;
  std::vector<std::uint8_t> binary_;
};

}  // namespace tutti::gltf_export
