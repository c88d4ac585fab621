// SPDX-License-Identifier: MIT
#include <tutti/export/glb_builder.hpp>

#include <algorithm>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

namespace tutti::gltf_export {
namespace {

std::size_t type_width(std::string_view type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4") return 4;
  if (type == "MAT4") return 16;
  return 0;
}

constexpr int kFloat = 5126;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;

void put_u32(std::vector<std::uint8_t>& out, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}

}  // namespace

GlbBuilder::GlbBuilder() : document_(nlohmann::json::object()) {}

int GlbBuilder::append(const char* key, nlohmann::json value) {
  nlohmann::json& array = document_[key];
  if (!array.is_array()) array = nlohmann::json::array();
  array.push_back(std::move(value));
  return static_cast<int>(array.size() - 1);
}

int GlbBuilder::add_view(std::span<const std::byte> bytes, BufferTarget target) {
  while (binary_.size() % 4 != 0) binary_.push_back(0);
  nlohmann::json view = {
      {"buffer", 0}, {"byteOffset", binary_.size()}, {"byteLength", bytes.size()}};
  if (target != BufferTarget::none) view["target"] = static_cast<int>(target);
  const auto* begin = reinterpret_cast<const std::uint8_t*>(bytes.data());
  binary_.insert(binary_.end(), begin, begin + bytes.size());
  return append("bufferViews", std::move(view));
}

int GlbBuilder::add_image_bytes(std::span<const std::uint8_t> bytes) {
  return add_view(std::as_bytes(bytes), BufferTarget::none);
}

void GlbBuilder::use_extension(const std::string& name, bool required) {
  for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
    if (key[10] == 'R' && !required) continue;
    nlohmann::json& list = document_[key];
    if (!list.is_array()) list = nlohmann::json::array();
    if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
  }
}

int GlbBuilder::add_floats(std::span<const float> values, std::string_view type,
                           BufferTarget target, bool with_min_max) {
  const std::size_t width = type_width(type);
  const std::size_t count = width == 0 ? 0 : values.size() / width;
  nlohmann::json accessor = {{"bufferView", add_view(std::as_bytes(values), target)},
                             {"componentType", kFloat},
                             {"count", count},
                             {"type", std::string(type)}};
  if (with_min_max && count > 0) {
    std::vector<float> lo(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(width));
    std::vector<float> hi = lo;
    for (std::size_t i = 0; i < values.size(); ++i) {
      lo[i % width] = std::min(lo[i % width], values[i]);
      hi[i % width] = std::max(hi[i % width], values[i]);
    }
    accessor["min"] = lo;
    accessor["max"] = hi;
  }
  return append("accessors", std::move(accessor));
}

int GlbBuilder::add_indices(std::span<const std::uint32_t> indices) {
  const bool small = std::all_of(indices.begin(), indices.end(), [](std::uint32_t i) {
    return i <= std::numeric_limits<std::uint16_t>::max() - 1;  // 65535 is primitive restart
  });
  int view = 0;
  if (small) {
    std::vector<std::uint16_t> narrow(indices.begin(), indices.end());
    view = add_view(std::as_bytes(std::span<const std::uint16_t>(narrow)), BufferTarget::indices);
  } else {
    view = add_view(std::as_bytes(indices), BufferTarget::indices);
  }
  return append("accessors", {{"bufferView", view},
                              {"componentType", small ? kUnsignedShort : kUnsignedInt},
                              {"count", indices.size()},
                              {"type", "SCALAR"}});
}

int GlbBuilder::add_joints(std::span<const std::uint16_t> joints) {
  const int view = add_view(std::as_bytes(joints), BufferTarget::vertices);
  return append("accessors", {{"bufferView", view},
                              {"componentType", kUnsignedShort},
                              {"count", joints.size() / 4},
                              {"type", "VEC4"}});
}

std::vector<std::uint8_t> GlbBuilder::finish() const {
  nlohmann::json document = document_;
  std::vector<std::uint8_t> binary = binary_;
  while (binary.size() % 4 != 0) binary.push_back(0);
  if (!binary.empty()) document["buffers"] = {{{"byteLength", binary.size()}}};
  std::string json = document.dump();
  while (json.size() % 4 != 0) json.push_back(' ');

  std::vector<std::uint8_t> out;
  const std::size_t total = 12 + 8 + json.size() + (binary.empty() ? 0 : 8 + binary.size());
  out.reserve(total);
  put_u32(out, 0x46546C67u);  // "glTF"
  put_u32(out, 2);
  put_u32(out, static_cast<std::uint32_t>(total));
  put_u32(out, static_cast<std::uint32_t>(json.size()));
  put_u32(out, 0x4E4F534Au);  // "JSON"
  out.insert(out.end(), json.begin(), json.end());
  if (!binary.empty()) {
    put_u32(out, static_cast<std::uint32_t>(binary.size()));
    put_u32(out, 0x004E4942u);  // "BIN\0"
    out.insert(out.end(), binary.begin(), binary.end());
  }
  return out;
}

}  // namespace tutti::gltf_export
