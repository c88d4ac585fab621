// SPDX-License-Identifier: MIT
#pragma once
// Builds small glTF files in memory for the model tests: the JSON is a plain nlohmann::json the
// test may edit (to make it hostile), the binary data one buffer. Output as .gltf text (the
// buffer a base64 data: URI, or an external file) or as .glb bytes.

#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include <tutti/model/model_asset.hpp>

namespace tutti::test {

inline constexpr int kByte = 5120;
inline constexpr int kUnsignedByte = 5121;
inline constexpr int kShort = 5122;
inline constexpr int kUnsignedShort = 5123;
inline constexpr int kUnsignedInt = 5125;
inline constexpr int kFloat = 5126;

inline std::string base64(const std::vector<std::uint8_t>& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const std::uint32_t v =
        (std::uint32_t{bytes[i]} << 16) | (std::uint32_t{bytes[i + 1]} << 8) | bytes[i + 2];
    for (int s = 18; s >= 0; s -= 6) out += digits[(v >> s) & 63];
  }
  if (i + 1 == bytes.size()) {
    const std::uint32_t v = std::uint32_t{bytes[i]} << 16;
    out += digits[(v >> 18) & 63];
    out += digits[(v >> 12) & 63];
    out += "==";
  } else if (i + 2 == bytes.size()) {
    const std::uint32_t v = (std::uint32_t{bytes[i]} << 16) | (std::uint32_t{bytes[i + 1]} << 8);
    out += digits[(v >> 18) & 63];
    out += digits[(v >> 12) & 63];
    out += digits[(v >> 6) & 63];
    out += '=';
  }
  return out;
}

class GltfBuilder {
 public:
  nlohmann::json json;
  std::vector<std::uint8_t> bin;

  GltfBuilder() { json["asset"] = {{"version", "2.0"}, {"generator", "tutti model tests"}}; }

  // Appends raw bytes (4-byte aligned) as a new buffer view; returns its index.
  int add_view(const void* data, std::size_t size, std::size_t stride = 0) {
    while (bin.size() % 4 != 0) bin.push_back(0);
    const std::size_t offset = bin.size();
    bin.resize(offset + size);
    if (size > 0) std::memcpy(bin.data() + offset, data, size);
    nlohmann::json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}};
    if (stride != 0) view["byteStride"] = stride;
    json["bufferViews"].push_back(view);
    return static_cast<int>(json["bufferViews"].size()) - 1;
  }

  int add_accessor(int view, int component_type, const std::string& type, std::size_t count,
                   std::size_t offset = 0, bool normalized = false) {
    nlohmann::json a = {
        {"bufferView", view}, {"componentType", component_type}, {"type", type}, {"count", count}};
    if (offset != 0) a["byteOffset"] = offset;
    if (normalized) a["normalized"] = true;
    json["accessors"].push_back(a);
    return static_cast<int>(json["accessors"].size()) - 1;
  }

  // A tightly packed accessor over `values`; count = bytes / element size.
  template <typename T>
  int add_data(const std::vector<T>& values, int component_type, const std::string& type,
               bool normalized = false) {
    const std::size_t bytes = values.size() * sizeof(T);
    const int view = add_view(values.data(), bytes);
    return add_accessor(view, component_type, type, bytes / element_size(component_type, type), 0,
                        normalized);
  }

  int add_vec3s(const std::vector<glm::vec3>& values) {
    std::vector<float> flat;
    for (const glm::vec3& v : values) flat.insert(flat.end(), {v.x, v.y, v.z});
    return add_data(flat, kFloat, "VEC3");
  }

  int add_node(const nlohmann::json& node) {
    json["nodes"].push_back(node);
    return static_cast<int>(json["nodes"].size()) - 1;
  }
  int add_mesh(const nlohmann::json& mesh) {
    json["meshes"].push_back(mesh);
    return static_cast<int>(json["meshes"].size()) - 1;
  }
  void set_scene(const std::vector<int>& roots) {
    json["scenes"] = nlohmann::json::array({{{"nodes", roots}}});
    json["scene"] = 0;
  }

  // .gltf with the buffer as a data: URI (or `external_uri` when given).
  std::string gltf_text(const std::string& external_uri = "") const {
    nlohmann::json doc = json;
    if (bin.empty() && external_uri.empty()) return doc.dump();
    doc["buffers"] = nlohmann::json::array(
        {{{"byteLength", bin.size()},
          {"uri", external_uri.empty() ? "data:application/octet-stream;base64," + base64(bin)
                                       : external_uri}}});
    return doc.dump();
  }
  std::vector<std::uint8_t> gltf_bytes() const {
    const std::string text = gltf_text();
    return {text.begin(), text.end()};
  }

  std::vector<std::uint8_t> glb() const {
    nlohmann::json doc = json;
    if (!bin.empty()) doc["buffers"] = nlohmann::json::array({{{"byteLength", bin.size()}}});
    std::string text = doc.dump();
    while (text.size() % 4 != 0) text += ' ';
    std::vector<std::uint8_t> data = bin;
    while (data.size() % 4 != 0) data.push_back(0);
    std::vector<std::uint8_t> out;
    auto u32 = [&](std::uint32_t v) {
      for (int s = 0; s < 32; s += 8) out.push_back(static_cast<std::uint8_t>(v >> s));
    };
    const std::size_t total = 12 + 8 + text.size() + (data.empty() ? 0 : 8 + data.size());
    u32(0x46546C67);
    u32(2);
    u32(static_cast<std::uint32_t>(total));
    u32(static_cast<std::uint32_t>(text.size()));
    u32(0x4E4F534A);
    out.insert(out.end(), text.begin(), text.end());
    if (!data.empty()) {
      u32(static_cast<std::uint32_t>(data.size()));
      u32(0x004E4942);
      out.insert(out.end(), data.begin(), data.end());
    }
    return out;
  }

  static std::size_t element_size(int component_type, const std::string& type) {
    const std::size_t component = (component_type == kByte || component_type == kUnsignedByte) ? 1
                                  : (component_type == kShort || component_type == kUnsignedShort)
                                      ? 2
                                      : 4;
    const std::size_t count = type == "SCALAR" ? 1
                              : type == "VEC2" ? 2
                              : type == "VEC3" ? 3
                              : type == "VEC4" ? 4
                              : type == "MAT4" ? 16
                                               : 1;
    return component * count;
  }
};

// A triangle mesh with POSITION (and NORMAL when asked) and u16 indices; returns the mesh index.
inline int add_triangle_mesh(GltfBuilder& b, const std::string& name,
                             const std::vector<glm::vec3>& positions,
                             const std::vector<std::uint16_t>& indices, bool normals = true) {
  nlohmann::json attributes = {{"POSITION", b.add_vec3s(positions)}};
  if (normals) {
    attributes["NORMAL"] = b.add_vec3s(std::vector<glm::vec3>(positions.size(), {0, 0, 1}));
  }
  nlohmann::json primitive = {{"attributes", attributes}};
  if (!indices.empty()) primitive["indices"] = b.add_data(indices, kUnsignedShort, "SCALAR");
  return b.add_mesh({{"name", name}, {"primitives", nlohmann::json::array({primitive})}});
}

inline Result<model::ModelAsset> load_bytes(const std::vector<std::uint8_t>& bytes,
                                            const std::string& name) {
  return model::load_model_from_memory(bytes, name);
}

}  // namespace tutti::test

namespace tutti::test {

// A 1 m wide, 2 m tall strip along +Y skinned to two joints: "root_joint" at the origin and its
// child "tip_joint" 1 m up. Rows y = 0 / 1 / 2 are weighted 1:0 / 0.5:0.5 / 0:1. The mesh node
// "strip" has its own translation (5, 0, 0), which skinning ignores.
inline GltfBuilder two_bone_strip() {
  GltfBuilder b;
  const std::vector<glm::vec3> positions = {{-0.5f, 0, 0}, {0.5f, 0, 0},  {-0.5f, 1, 0},
                                            {0.5f, 1, 0},  {-0.5f, 2, 0}, {0.5f, 2, 0}};
  const std::vector<std::uint8_t> joints = {0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0,
                                            0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
  const std::vector<float> weights = {1,    0,    0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0,
                                      0.5f, 0.5f, 0, 0, 1, 0, 0, 0, 1,    0,    0, 0};
  const std::vector<std::uint16_t> indices = {0, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4};
  nlohmann::json attributes = {{"POSITION", b.add_vec3s(positions)},
                               {"NORMAL", b.add_vec3s(std::vector<glm::vec3>(6, {0, 0, 1}))},
                               {"JOINTS_0", b.add_data(joints, kUnsignedByte, "VEC4")},
                               {"WEIGHTS_0", b.add_data(weights, kFloat, "VEC4")}};
  b.add_mesh({{"name", "strip"},
              {"primitives", nlohmann::json::array(
                                 {{{"attributes", attributes},
                                   {"indices", b.add_data(indices, kUnsignedShort, "SCALAR")}}})}});
  std::vector<float> ibm(32, 0.0f);
  for (int i = 0; i < 4; ++i)
    ibm[static_cast<std::size_t>(i * 5)] = ibm[16 + static_cast<std::size_t>(i * 5)] = 1;
  ibm[16 + 13] = -1.0f;  // translate(0, -1, 0): the inverse of tip_joint's bind pose
  b.json["skins"] =
      nlohmann::json::array({{{"name", "strip_skin"},
                              {"joints", {0, 1}},
                              {"inverseBindMatrices", b.add_data(ibm, kFloat, "MAT4")}}});
  b.add_node({{"name", "root_joint"}, {"children", {1}}});
  b.add_node({{"name", "tip_joint"}, {"translation", {0, 1, 0}}});
  b.add_node({{"name", "strip"}, {"mesh", 0}, {"skin", 0}, {"translation", {5, 0, 0}}});
  b.set_scene({0, 2});
  return b;
}

}  // namespace tutti::test
