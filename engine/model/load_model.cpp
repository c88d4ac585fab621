// SPDX-License-Identifier: MIT
// tinygltf::Model → ModelAsset: every reference, count and accessor range checked
// (model_asset.hpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include <tutti/core/file_io.hpp>
#include <tutti/model/gltf_accessors.hpp>
#include <tutti/model/gltf_document.hpp>
#include <tutti/model/gltf_images.hpp>
#include <tutti/model/model_asset.hpp>
#include <tutti/model/node_hierarchy.hpp>

namespace tutti::model {
namespace {

using namespace detail;

constexpr std::size_t kMaxVertices = 1'000'000;
constexpr std::size_t kMaxNodes = 65'536;
constexpr std::size_t kMaxJointsPerSkin = 256;
constexpr std::size_t kMaxJointsTotal = 65'536;
constexpr std::size_t kMaxIndices = std::size_t{1} << 24;
constexpr std::size_t kMaxMorphDeltas = std::size_t{1} << 23;

std::string describe(const char* kind, std::size_t index, const std::string& name) {
  std::string text = std::string(kind) + " " + std::to_string(index);
  if (!name.empty()) text = std::string(kind) + " \"" + name + "\"";
  return text;
}

std::string mode_name(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS:
      return "points";
    case TINYGLTF_MODE_LINE:
      return "lines";
    case TINYGLTF_MODE_LINE_LOOP:
      return "line loop";
    case TINYGLTF_MODE_LINE_STRIP:
      return "line strip";
    case TINYGLTF_MODE_TRIANGLE_STRIP:
      return "triangle strip";
    case TINYGLTF_MODE_TRIANGLE_FAN:
      return "triangle fan";
    default:
      return "unknown";
  }
}

// "WHERE: reason", or "WHERE reason" for an accessor error after an attribute name
// ("POSITION accessor 3: ...").
Error prefixed(const std::string& where, const Error& error, const char* separator = ": ") {
  return Error{where + separator + error.message};
}

// The bytes of a base64 `data:` URI; empty when `uri` is not one or is not valid base64.
std::vector<std::uint8_t> data_uri_bytes(const std::string& uri) {
  const std::size_t comma = uri.find(',');
  if (uri.rfind("data:", 0) != 0 || comma == std::string::npos || comma < 7 ||
      uri.compare(comma - 7, 7, ";base64") != 0) {
    return {};
  }
  std::vector<std::uint8_t> out;
  out.reserve((uri.size() - comma) * 3 / 4);
  std::uint32_t bits = 0;
  int count = 0;
  for (std::size_t i = comma + 1; i < uri.size(); ++i) {
    const char c = uri[i];
    int value = -1;
    if (c >= 'A' && c <= 'Z') value = c - 'A';
    if (c >= 'a' && c <= 'z') value = c - 'a' + 26;
    if (c >= '0' && c <= '9') value = c - '0' + 52;
    if (c == '+') value = 62;
    if (c == '/') value = 63;
    if (c == '=') break;
    if (value < 0) return {};
    bits = (bits << 6) | static_cast<std::uint32_t>(value);
    if (++count == 4) {
      out.push_back(static_cast<std::uint8_t>(bits >> 16));
      out.push_back(static_cast<std::uint8_t>(bits >> 8));
      out.push_back(static_cast<std::uint8_t>(bits));
      bits = 0;
      count = 0;
    }
  }
  if (count == 3) {
    out.push_back(static_cast<std::uint8_t>(bits >> 10));
    out.push_back(static_cast<std::uint8_t>(bits >> 2));
  } else if (count == 2) {
    out.push_back(static_cast<std::uint8_t>(bits >> 4));
  }
  return out;
}

// One primitive's vertices before they join the asset's arrays.
struct PrimitiveData {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // empty: computed (flat)
  std::vector<glm::uvec4> joints;  // empty: unskinned
  std::vector<glm::vec4> weights;
  std::vector<glm::vec2> uv0, uv1;  // empty: absent
  std::vector<std::uint32_t> indices;
  std::vector<std::vector<MorphDelta>> targets;
};

// The spec: without normals, flat normals. Every corner becomes its own vertex.
void make_flat(PrimitiveData& data) {
  const std::size_t corners = data.indices.size();
  PrimitiveData flat;
  flat.positions.resize(corners);
  flat.normals.resize(corners);
  if (!data.joints.empty()) {
    flat.joints.resize(corners);
    flat.weights.resize(corners);
  }
  flat.targets.assign(data.targets.size(), std::vector<MorphDelta>(corners));
  if (!data.uv0.empty()) flat.uv0.resize(corners);
  if (!data.uv1.empty()) flat.uv1.resize(corners);
  for (std::size_t c = 0; c < corners; ++c) {
    const std::uint32_t v = data.indices[c];
    flat.positions[c] = data.positions[v];
    if (!data.uv0.empty()) flat.uv0[c] = data.uv0[v];
    if (!data.uv1.empty()) flat.uv1[c] = data.uv1[v];
    if (!data.joints.empty()) {
      flat.joints[c] = data.joints[v];
      flat.weights[c] = data.weights[v];
    }
    for (std::size_t k = 0; k < data.targets.size(); ++k) flat.targets[k][c] = data.targets[k][v];
  }
  for (std::size_t t = 0; t + 2 < corners; t += 3) {
    const glm::vec3 n = glm::cross(flat.positions[t + 1] - flat.positions[t],
                                   flat.positions[t + 2] - flat.positions[t]);
    const float length = glm::length(n);
    const glm::vec3 normal =
        (length > 0.0f && std::isfinite(length)) ? n / length : glm::vec3(0.0f, 1.0f, 0.0f);
    for (std::size_t c = t; c < t + 3; ++c) flat.normals[c] = normal;
  }
  flat.indices.resize(corners);
  for (std::size_t c = 0; c < corners; ++c) flat.indices[c] = static_cast<std::uint32_t>(c);
  data = std::move(flat);
}

// Eight influences per vertex (sets 0 and 1) down to the four largest, into set 0.
void keep_four_largest(std::vector<glm::uvec4>& joints, std::vector<glm::vec4>& weights,
                       const std::vector<glm::uvec4>& joints_1, const std::vector<glm::vec4>& weights_1) {
  for (std::size_t v = 0; v < weights.size(); ++v) {
    std::array<std::pair<float, std::uint32_t>, 8> all{};
    for (int c = 0; c < 4; ++c) {
      const auto k = static_cast<std::size_t>(c);
      all[k] = {std::isfinite(weights[v][c]) ? weights[v][c] : 0.0f, joints[v][c]};
      all[k + 4] = {std::isfinite(weights_1[v][c]) ? weights_1[v][c] : 0.0f, joints_1[v][c]};
    }
    // Ties keep the earlier influence: stable, so the result is deterministic.
    std::stable_sort(all.begin(), all.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    for (int c = 0; c < 4; ++c) {
      weights[v][c] = all[static_cast<std::size_t>(c)].first;
      joints[v][c] = all[static_cast<std::size_t>(c)].second;
    }
  }
}

// Weights clamped to finite non-negative values and scaled to sum 1; all zero → joint 0 alone.
void normalise_weights(std::vector<glm::uvec4>& joints, std::vector<glm::vec4>& weights) {
  for (std::size_t v = 0; v < weights.size(); ++v) {
    glm::vec4& w = weights[v];
    float sum = 0.0f;
    for (int c = 0; c < 4; ++c) {
      if (!std::isfinite(w[c]) || w[c] < 0.0f) w[c] = 0.0f;
      sum += w[c];
    }
    if (sum > 0.0f && std::isfinite(sum)) {
      w /= sum;
    } else {
      w = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
      joints[v] = glm::uvec4(0);
    }
  }
}

class Converter {
 public:
  explicit Converter(const tinygltf::Model& model) : m_(model) {}

  Result<ModelAsset> run() {
    if (m_.nodes.size() > kMaxNodes) {
      return Error{std::to_string(m_.nodes.size()) + " nodes, at most " +
                   std::to_string(kMaxNodes)};
    }
    auto order = order_nodes(m_);
    if (!order) return order.error();
    if (auto s = convert_images(); !s) return s.error();
    if (auto s = convert_textures(); !s) return s.error();
    if (auto s = convert_materials(); !s) return s.error();
    for (std::size_t i = 0; i < m_.meshes.size(); ++i) {
      if (auto s = convert_mesh(i); !s) return s.error();
    }
    if (auto s = convert_skins(*order); !s) return s.error();
    if (auto s = convert_nodes(*order); !s) return s.error();
    if (auto s = check_skinned_nodes(); !s) return s.error();
    if (auto s = find_roots(*order); !s) return s.error();
    read_humanoid_table(*order);
    return std::move(asset_);
  }

 private:
  struct PrimitiveInfo {
    bool skin_attributes = false;
    std::uint32_t max_joint = 0;
  };

  // VRM's humanoid bone table (0.x: extensions.VRM.humanoid.humanBones [{bone, node}]; 1.0:
  // extensions.VRMC_vrm.humanoid.humanBones {bone: {node}}), node indices remapped. Entries
  // that are not a valid node are left out; the recogniser reports what is missing.
  void read_humanoid_table(const NodeOrder& order) {
    const auto add = [&](const std::string& bone, const tinygltf::Value& node) {
      if (!node.IsInt()) return;
      const int file = node.GetNumberAsInt();
      if (file < 0 || static_cast<std::size_t>(file) >= m_.nodes.size()) return;
      asset_.humanoid_table.emplace_back(bone, order.new_index[static_cast<std::size_t>(file)]);
    };
    if (const auto vrm1 = m_.extensions.find("VRMC_vrm"); vrm1 != m_.extensions.end()) {
      const tinygltf::Value& bones = vrm1->second.Get("humanoid").Get("humanBones");
      if (bones.IsObject()) {
        for (const std::string& bone : bones.Keys()) add(bone, bones.Get(bone).Get("node"));
        asset_.humanoid_table_source = "VRM 1.0";
      }
    } else if (const auto vrm0 = m_.extensions.find("VRM"); vrm0 != m_.extensions.end()) {
      const tinygltf::Value& bones = vrm0->second.Get("humanoid").Get("humanBones");
      if (bones.IsArray()) {
        for (std::size_t i = 0; i < bones.ArrayLen(); ++i) {
          const tinygltf::Value& entry = bones.Get(static_cast<int>(i));
          if (entry.Get("bone").IsString()) add(entry.Get("bone").Get<std::string>(), entry.Get("node"));
        }
        asset_.humanoid_table_source = "VRM 0.x";
      }
    }
  }

  // Every image's bytes (tinygltf hands them over undecoded, gltf_document.cpp), decoded when
  // PNG, JPEG or WebP; other formats (KTX2, DDS) stay undecoded and their textures unused.
  Status convert_images() {
    std::size_t budget = kMaxPixelBytesPerModel;
    for (std::size_t i = 0; i < m_.images.size(); ++i) {
      const tinygltf::Image& in = m_.images[i];
      const std::string where = describe("image", i, in.name);
      Image out;
      out.name = in.name;
      out.mime_type = in.mimeType;
      if (in.width == -1) out.encoded = in.image;
      // tinygltf passes over data: URIs of types it does not know (image/webp).
      if (out.encoded.empty()) out.encoded = data_uri_bytes(in.uri);
      if (out.encoded.empty()) {
        return Error{where + ": no data" + (in.uri.empty() ? std::string() : " (" + in.uri + ")")};
      }
      const std::string type = sniff_image_type(out.encoded);
      if (!type.empty()) {
        if (auto s = decode_image(out, budget); !s) return prefixed(where, s.error(), ": ");
        out.mime_type = type;
      }
      asset_.images.push_back(std::move(out));
    }
    return {};
  }

  Status convert_textures() {
    for (std::size_t i = 0; i < m_.textures.size(); ++i) {
      const tinygltf::Texture& in = m_.textures[i];
      const std::string where = describe("texture", i, in.name);
      Texture out;
      int source = in.source;
      // EXT_texture_webp names the WebP image; `source` (if any) is a fallback for other readers.
      if (const auto webp = in.extensions.find("EXT_texture_webp"); webp != in.extensions.end()) {
        const tinygltf::Value& value = webp->second.Get("source");
        if (value.IsInt()) source = value.GetNumberAsInt();
      }
      if (source >= 0) {
        if (static_cast<std::size_t>(source) >= asset_.images.size()) {
          return Error{where + ": image " + std::to_string(source) + " is not in the file"};
        }
        if (!asset_.images[static_cast<std::size_t>(source)].rgba.empty()) out.image = source;
      }
      if (in.sampler >= 0) {
        if (static_cast<std::size_t>(in.sampler) >= m_.samplers.size()) {
          return Error{where + ": sampler " + std::to_string(in.sampler) + " is not in the file"};
        }
        const tinygltf::Sampler& sampler = m_.samplers[static_cast<std::size_t>(in.sampler)];
        out.mag_filter = std::max(sampler.magFilter, 0);
        out.min_filter = std::max(sampler.minFilter, 0);
        out.wrap_s = sampler.wrapS;
        out.wrap_t = sampler.wrapT;
      }
      asset_.textures.push_back(out);
    }
    return {};
  }

  // A material's texture slot: the texture, its UV set (0 or 1) and KHR_texture_transform.
  Status texture_ref(const std::string& where, int index, int texcoord,
                     const tinygltf::ExtensionMap& extensions, double amount, TextureRef& out) {
    if (index < 0) return {};
    if (static_cast<std::size_t>(index) >= asset_.textures.size()) {
      return Error{where + ": texture " + std::to_string(index) + " is not in the file"};
    }
    if (!std::isfinite(amount)) return Error{where + ": scale or strength is not finite"};
    out.amount = static_cast<float>(amount);
    out.texcoord = texcoord;
    if (const auto t = extensions.find("KHR_texture_transform"); t != extensions.end()) {
      const tinygltf::Value& e = t->second;
      const auto number = [](const tinygltf::Value& v, double fallback) {
        return v.IsNumber() && std::isfinite(v.GetNumberAsDouble()) ? v.GetNumberAsDouble()
                                                                      : fallback;
      };
      const auto pair = [&](const char* key, glm::vec2 fallback) {
        const tinygltf::Value& v = e.Get(key);
        if (!v.IsArray() || v.ArrayLen() != 2) return fallback;
        return glm::vec2(static_cast<float>(number(v.Get(0), fallback.x)),
                         static_cast<float>(number(v.Get(1), fallback.y)));
      };
      out.offset = pair("offset", glm::vec2(0.0f));
      out.scale = pair("scale", glm::vec2(1.0f));
      out.rotation = static_cast<float>(number(e.Get("rotation"), 0.0));
      if (e.Get("texCoord").IsInt()) out.texcoord = e.Get("texCoord").GetNumberAsInt();
      out.transformed = true;
    }
    if (out.texcoord < 0 || out.texcoord > 1) {
      return Error{where + ": uses TEXCOORD_" + std::to_string(out.texcoord) +
                   " (tutti reads TEXCOORD_0 and TEXCOORD_1)"};
    }
    // A texture whose image tutti cannot decode (KTX2, DDS) is left out: the factors alone.
    if (asset_.textures[static_cast<std::size_t>(index)].image >= 0) out.texture = index;
    return {};
  }

  Status convert_materials() {
    for (std::size_t i = 0; i < m_.materials.size(); ++i) {
      const tinygltf::Material& in = m_.materials[i];
      Material out;
      out.name = in.name;
      const auto& pbr = in.pbrMetallicRoughness;
      const std::string where = describe("material", i, in.name);
      auto finite = [](double v) { return std::isfinite(v); };
      if (!std::all_of(pbr.baseColorFactor.begin(), pbr.baseColorFactor.end(), finite) ||
          !std::all_of(in.emissiveFactor.begin(), in.emissiveFactor.end(), finite) ||
          !std::isfinite(pbr.metallicFactor) || !std::isfinite(pbr.roughnessFactor)) {
        return Error{where + ": a factor is not a finite number"};
      }
      if (pbr.baseColorFactor.size() == 4) {
        for (int c = 0; c < 4; ++c) {
          out.base_color[c] = static_cast<float>(pbr.baseColorFactor[static_cast<std::size_t>(c)]);
        }
      }
      if (in.emissiveFactor.size() == 3) {
        for (int c = 0; c < 3; ++c) {
          out.emissive[c] = static_cast<float>(in.emissiveFactor[static_cast<std::size_t>(c)]);
        }
      }
      out.metallic = static_cast<float>(pbr.metallicFactor);
      out.roughness = static_cast<float>(pbr.roughnessFactor);
      out.double_sided = in.doubleSided;
      if (in.alphaMode == "MASK") {
        out.alpha_mode = AlphaMode::mask;
      } else if (in.alphaMode == "BLEND") {
        out.alpha_mode = AlphaMode::blend;
      } else if (!in.alphaMode.empty() && in.alphaMode != "OPAQUE") {
        return Error{where + ": alphaMode \"" + in.alphaMode + "\" is not OPAQUE, MASK or BLEND"};
      }
      if (!std::isfinite(in.alphaCutoff) || in.alphaCutoff < 0.0) {
        return Error{where + ": alphaCutoff must be a number >= 0"};
      }
      out.alpha_cutoff = static_cast<float>(in.alphaCutoff);
      struct Slot {
        const char* name;
        int index, texcoord;
        const tinygltf::ExtensionMap* extensions;
        double amount;
        TextureRef* ref;
      };
      const Slot slots[] = {
          {"baseColorTexture", pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
           &pbr.baseColorTexture.extensions, 1.0, &out.base_color_texture},
          {"metallicRoughnessTexture", pbr.metallicRoughnessTexture.index,
           pbr.metallicRoughnessTexture.texCoord, &pbr.metallicRoughnessTexture.extensions, 1.0,
           &out.metallic_roughness_texture},
          {"normalTexture", in.normalTexture.index, in.normalTexture.texCoord,
           &in.normalTexture.extensions, in.normalTexture.scale, &out.normal_texture},
          {"occlusionTexture", in.occlusionTexture.index, in.occlusionTexture.texCoord,
           &in.occlusionTexture.extensions, in.occlusionTexture.strength, &out.occlusion_texture},
          {"emissiveTexture", in.emissiveTexture.index, in.emissiveTexture.texCoord,
           &in.emissiveTexture.extensions, 1.0, &out.emissive_texture},
      };
      for (const Slot& slot : slots) {
        if (auto s = texture_ref(where + ": " + slot.name, slot.index, slot.texcoord,
                                 *slot.extensions, slot.amount, *slot.ref);
            !s) {
          return s.error();
        }
      }
      asset_.materials.push_back(std::move(out));
    }
    return {};
  }

  Status convert_mesh(std::size_t index) {
    const tinygltf::Mesh& in = m_.meshes[index];
    const std::string where = describe("mesh", index, in.name);
    Mesh out;
    out.name = in.name;
    const std::size_t targets = in.primitives.empty() ? 0 : in.primitives[0].targets.size();
    info_.emplace_back();
    for (std::size_t p = 0; p < in.primitives.size(); ++p) {
      const std::string prim_where = where + " primitive " + std::to_string(p);
      if (in.primitives[p].targets.size() != targets) {
        return Error{prim_where + ": " + std::to_string(in.primitives[p].targets.size()) +
                     " morph targets, primitive 0 has " + std::to_string(targets)};
      }
      auto primitive = convert_primitive(in.primitives[p], prim_where);
      if (!primitive) return primitive.error();
      out.primitives.push_back(*primitive);
    }
    if (!in.weights.empty() && in.weights.size() != targets) {
      return Error{where + ": " + std::to_string(in.weights.size()) + " weights for " +
                   std::to_string(targets) + " morph targets"};
    }
    out.default_weights.assign(targets, 0.0f);
    for (std::size_t k = 0; k < in.weights.size(); ++k) {
      if (!std::isfinite(in.weights[k])) return Error{where + ": a weight is not finite"};
      out.default_weights[k] = static_cast<float>(in.weights[k]);
    }
    out.target_names = target_names(in, targets);
    asset_.meshes.push_back(std::move(out));
    return {};
  }

  static std::vector<std::string> target_names(const tinygltf::Mesh& mesh, std::size_t targets) {
    std::vector<std::string> names;
    if (mesh.extras.IsObject() && mesh.extras.Has("targetNames")) {
      const tinygltf::Value& list = mesh.extras.Get("targetNames");
      if (list.IsArray() && list.ArrayLen() == targets) {
        for (std::size_t k = 0; k < targets; ++k) {
          const tinygltf::Value& name = list.Get(static_cast<int>(k));
          if (!name.IsString()) break;
          names.push_back(name.Get<std::string>());
        }
      }
    }
    if (names.size() != targets) {
      names.clear();
      for (std::size_t k = 0; k < targets; ++k) names.push_back("target_" + std::to_string(k));
    }
    return names;
  }

  Result<Primitive> convert_primitive(const tinygltf::Primitive& in, const std::string& where) {
    if (in.mode != -1 && in.mode != TINYGLTF_MODE_TRIANGLES) {
      return Error{where + ": mode " + std::to_string(in.mode) + " (" + mode_name(in.mode) +
                   ") is not supported, only triangles"};
    }
    if (in.material < -1 || in.material >= static_cast<int>(m_.materials.size())) {
      return Error{where + ": material " + std::to_string(in.material) +
                   " does not exist (the file has " + std::to_string(m_.materials.size()) + ")"};
    }
    const std::size_t vertex_budget = kMaxVertices - asset_.vertices.size();
    const std::size_t index_budget = kMaxIndices - asset_.indices.size();
    auto attribute = [&](const char* name) {
      const auto it = in.attributes.find(name);
      return it == in.attributes.end() ? -1 : it->second;
    };

    PrimitiveData data;
    const int position = attribute("POSITION");
    if (position < 0) return Error{where + ": no POSITION attribute"};
    auto positions = read_vec3(m_, position, vertex_budget, Vec3Kind::position);
    if (!positions) return prefixed(where + ": POSITION", positions.error(), " ");
    data.positions = std::move(*positions);
    for (std::size_t v = 0; v < data.positions.size(); ++v) {
      const glm::vec3& p = data.positions[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        return Error{where + ": POSITION " + std::to_string(v) +
                     " has a non-finite number (NaN or infinity)"};
      }
    }
    const std::size_t n = data.positions.size();
    auto same_count = [&](const char* name, std::size_t count) -> Status {
      if (count == n) return {};
      return Error{where + ": " + name + " has " + std::to_string(count) +
                   " elements, POSITION has " + std::to_string(n)};
    };

    if (const int normal = attribute("NORMAL"); normal >= 0) {
      auto normals = read_vec3(m_, normal, n, Vec3Kind::normal);
      if (!normals) return prefixed(where + ": NORMAL", normals.error(), " ");
      if (auto s = same_count("NORMAL", normals->size()); !s) return s.error();
      data.normals = std::move(*normals);
    }

    for (int set = 0; set < 2; ++set) {
      const std::string name = "TEXCOORD_" + std::to_string(set);
      const int texcoord = attribute(name.c_str());
      if (texcoord < 0) continue;
      auto uvs = read_texcoords(m_, texcoord, n);
      if (!uvs) return prefixed(where + ": " + name, uvs.error(), " ");
      if (auto s = same_count(name.c_str(), uvs->size()); !s) return s.error();
      (set == 0 ? data.uv0 : data.uv1) = std::move(*uvs);
    }

    const int joints = attribute("JOINTS_0");
    const int weights = attribute("WEIGHTS_0");
    if ((joints >= 0) != (weights >= 0)) {
      return Error{where +
                   (joints >= 0 ? ": JOINTS_0 without WEIGHTS_0" : ": WEIGHTS_0 without JOINTS_0")};
    }
    if (joints >= 0) {
      auto j = read_joints(m_, joints, n);
      if (!j) return prefixed(where + ": JOINTS_0", j.error(), " ");
      if (auto s = same_count("JOINTS_0", j->size()); !s) return s.error();
      auto w = read_weights(m_, weights, n);
      if (!w) return prefixed(where + ": WEIGHTS_0", w.error(), " ");
      if (auto s = same_count("WEIGHTS_0", w->size()); !s) return s.error();
      data.joints = std::move(*j);
      data.weights = std::move(*w);
      // More than four influences (JOINTS_1 / WEIGHTS_1): the four largest of the eight are kept
      // (normalise_weights then scales them to sum 1).
      const int joints_1 = attribute("JOINTS_1");
      const int weights_1 = attribute("WEIGHTS_1");
      if ((joints_1 >= 0) != (weights_1 >= 0)) {
        return Error{where + (joints_1 >= 0 ? ": JOINTS_1 without WEIGHTS_1"
                                            : ": WEIGHTS_1 without JOINTS_1")};
      }
      if (joints_1 >= 0) {
        auto j1 = read_joints(m_, joints_1, n);
        if (!j1) return prefixed(where + ": JOINTS_1", j1.error(), " ");
        if (auto s = same_count("JOINTS_1", j1->size()); !s) return s.error();
        auto w1 = read_weights(m_, weights_1, n);
        if (!w1) return prefixed(where + ": WEIGHTS_1", w1.error(), " ");
        if (auto s = same_count("WEIGHTS_1", w1->size()); !s) return s.error();
        keep_four_largest(data.joints, data.weights, *j1, *w1);
        ++asset_.primitives_over_four_weights;
      }
    }

    if (in.indices >= 0) {
      auto indices = read_indices(m_, in.indices, index_budget);
      if (!indices) return prefixed(where + ": indices", indices.error(), " ");
      data.indices = std::move(*indices);
      for (const std::uint32_t index : data.indices) {
        if (index >= n) {
          return Error{where + ": index " + std::to_string(index) + " is past the last vertex (" +
                       std::to_string(n) + " vertices)"};
        }
      }
    } else {
      if (n > index_budget)
        return Error{where + ": more than " + std::to_string(kMaxIndices) + " indices in the file"};
      data.indices.resize(n);
      for (std::size_t i = 0; i < n; ++i) data.indices[i] = static_cast<std::uint32_t>(i);
    }
    if (data.indices.size() % 3 != 0) {
      return Error{where + ": " + std::to_string(data.indices.size()) +
                   " indices, not a whole number of triangles"};
    }

    const std::size_t target_count = in.targets.size();
    const std::size_t delta_budget = kMaxMorphDeltas - asset_.morph_deltas.size();
    auto check_delta_budget = [&](std::size_t vertices) -> Status {
      if (target_count > 0 && vertices > delta_budget / target_count) {
        return Error{where + ": more than " + std::to_string(kMaxMorphDeltas) +
                     " morph target deltas in the file"};
      }
      return {};
    };
    if (auto s = check_delta_budget(n); !s) return s.error();
    data.targets.assign(target_count, std::vector<MorphDelta>(n));
    for (std::size_t k = 0; k < target_count; ++k) {
      const std::string target_where = where + " morph target " + std::to_string(k);
      for (const auto& [name, accessor] : in.targets[k]) {
        const bool is_position = name == "POSITION";
        if (!is_position && name != "NORMAL") continue;  // TANGENT etc. are not used
        auto deltas = read_vec3(m_, accessor, n,
                                is_position ? Vec3Kind::morph_position : Vec3Kind::morph_normal);
        if (!deltas) return prefixed(target_where + ": " + name, deltas.error(), " ");
        if (deltas->size() != n) {
          return Error{target_where + ": " + name + " has " + std::to_string(deltas->size()) +
                       " elements, POSITION has " + std::to_string(n)};
        }
        for (std::size_t v = 0; v < n; ++v) {
          (is_position ? data.targets[k][v].position : data.targets[k][v].normal) = (*deltas)[v];
        }
      }
    }

    if (data.normals.empty()) {
      if (data.indices.size() > vertex_budget) {
        return Error{where + ": more than " + std::to_string(kMaxVertices) +
                     " vertices in the file (with flat normals computed)"};
      }
      if (auto s = check_delta_budget(data.indices.size()); !s) return s.error();
      make_flat(data);
    }

    PrimitiveInfo info;
    if (!data.joints.empty()) {
      normalise_weights(data.joints, data.weights);
      info.skin_attributes = true;
      for (const glm::uvec4& j : data.joints) {
        info.max_joint = std::max({info.max_joint, j.x, j.y, j.z, j.w});
      }
    }
    info_.back().push_back(info);

    Primitive out;
    out.first_vertex = static_cast<std::uint32_t>(asset_.vertices.size());
    out.vertex_count = static_cast<std::uint32_t>(data.positions.size());
    out.first_index = static_cast<std::uint32_t>(asset_.indices.size());
    out.index_count = static_cast<std::uint32_t>(data.indices.size());
    out.material = in.material;
    out.first_morph_delta = static_cast<std::uint32_t>(asset_.morph_deltas.size());
    for (std::size_t v = 0; v < data.positions.size(); ++v) {
      Vertex vertex;
      vertex.position = data.positions[v];
      // Quantized normals (KHR_mesh_quantization) come back a little off unit length.
      const glm::vec3 normal = data.normals[v];
      const float length = glm::length(normal);
      vertex.normal = length > 1e-12f && std::isfinite(length) ? normal / length : normal;
      if (!data.joints.empty()) {
        vertex.joints = data.joints[v];
        vertex.weights = data.weights[v];
      }
      if (!data.uv0.empty()) vertex.uv0 = data.uv0[v];
      if (!data.uv1.empty()) vertex.uv1 = data.uv1[v];
      asset_.vertices.push_back(vertex);
    }
    asset_.indices.insert(asset_.indices.end(), data.indices.begin(), data.indices.end());
    for (const auto& target : data.targets) {
      asset_.morph_deltas.insert(asset_.morph_deltas.end(), target.begin(), target.end());
    }
    return out;
  }

  Status convert_skins(const NodeOrder& order) {
    std::size_t total = 0;
    for (std::size_t i = 0; i < m_.skins.size(); ++i) {
      const tinygltf::Skin& in = m_.skins[i];
      const std::string where = describe("skin", i, in.name);
      if (in.joints.size() > kMaxJointsPerSkin) {
        return Error{where + ": " + std::to_string(in.joints.size()) + " joints, at most " +
                     std::to_string(kMaxJointsPerSkin)};
      }
      total += in.joints.size();
      if (total > kMaxJointsTotal) {
        return Error{"more than " + std::to_string(kMaxJointsTotal) + " joints over all skins"};
      }
      Skin out;
      out.name = in.name;
      std::set<int> seen;
      for (const int joint : in.joints) {
        if (joint < 0 || static_cast<std::size_t>(joint) >= m_.nodes.size()) {
          return Error{where + ": joint " + std::to_string(joint) +
                       " is not a node (the file has " + std::to_string(m_.nodes.size()) + ")"};
        }
        if (!seen.insert(joint).second) {
          return Error{where + ": " + describe_node(m_, static_cast<std::size_t>(joint)) +
                       " is listed twice as a joint"};
        }
        out.joints.push_back(order.new_index[static_cast<std::size_t>(joint)]);
      }
      if (in.inverseBindMatrices >= 0) {
        auto matrices = read_mat4s(m_, in.inverseBindMatrices, in.joints.size());
        if (!matrices) return prefixed(where + ": inverseBindMatrices", matrices.error(), " ");
        for (std::size_t j = 0; j < matrices->size(); ++j) {
          const float* values = &(*matrices)[j][0][0];
          if (!std::all_of(values, values + 16, [](float v) { return std::isfinite(v); })) {
            return Error{where + ": inverseBindMatrices: matrix " + std::to_string(j) +
                         " has a non-finite number (NaN or infinity)"};
          }
        }
        out.inverse_bind = std::move(*matrices);
      } else {
        out.inverse_bind.assign(in.joints.size(), glm::mat4(1.0f));
      }
      asset_.skins.push_back(std::move(out));
    }
    return {};
  }

  Status convert_nodes(const NodeOrder& order) {
    asset_.nodes.resize(m_.nodes.size());
    for (std::size_t file = 0; file < m_.nodes.size(); ++file) {
      const tinygltf::Node& in = m_.nodes[file];
      const std::string where = describe_node(m_, file);
      Node& out = asset_.nodes[static_cast<std::size_t>(order.new_index[file])];
      out.name = in.name;
      const int parent = order.parent[file];
      out.parent = parent < 0 ? -1 : order.new_index[static_cast<std::size_t>(parent)];
      for (const int child : in.children) {
        out.children.push_back(order.new_index[static_cast<std::size_t>(child)]);
      }
      auto transform = node_transform(in);
      if (!transform) return prefixed(where, transform.error());
      out.rest = *transform;
      if (in.mesh < -1 || in.mesh >= static_cast<int>(m_.meshes.size())) {
        return Error{where + ": mesh " + std::to_string(in.mesh) +
                     " does not exist (the file has " + std::to_string(m_.meshes.size()) + ")"};
      }
      if (in.skin < -1 || in.skin >= static_cast<int>(m_.skins.size())) {
        return Error{where + ": skin " + std::to_string(in.skin) +
                     " does not exist (the file has " + std::to_string(m_.skins.size()) + ")"};
      }
      out.mesh = in.mesh;
      out.skin = in.skin;
      if (in.extras.IsObject()) {
        for (const std::string& key : in.extras.Keys()) {
          const tinygltf::Value& value = in.extras.Get(key);
          if (value.IsNumber() && std::isfinite(value.GetNumberAsDouble())) {
            out.numbers.emplace_back(key, value.GetNumberAsDouble());
          }
        }
      }
    }
    return {};
  }

  // A skinned node's mesh must carry JOINTS_0/WEIGHTS_0 whose values are joints of its skin.
  Status check_skinned_nodes() {
    for (std::size_t file = 0; file < m_.nodes.size(); ++file) {
      const tinygltf::Node& node = m_.nodes[file];
      if (node.skin < 0 || node.mesh < 0) continue;
      const Skin& skin = asset_.skins[static_cast<std::size_t>(node.skin)];
      const auto mesh = static_cast<std::size_t>(node.mesh);
      for (std::size_t p = 0; p < info_[mesh].size(); ++p) {
        const PrimitiveInfo& info = info_[mesh][p];
        const std::string where =
            describe("mesh", mesh, m_.meshes[mesh].name) + " primitive " + std::to_string(p);
        const std::string skin_name =
            describe("skin", static_cast<std::size_t>(node.skin), skin.name);
        if (!info.skin_attributes) {
          return Error{where + ": no JOINTS_0/WEIGHTS_0, but " + describe_node(m_, file) +
                       " draws it with " + skin_name};
        }
        if (info.max_joint >= skin.joints.size()) {
          return Error{where + ": JOINTS_0 value " + std::to_string(info.max_joint) +
                       " is not a joint of " + skin_name + " (" +
                       std::to_string(skin.joints.size()) + " joints)"};
        }
      }
    }
    return {};
  }

  Status find_roots(const NodeOrder& order) {
    int scene = m_.defaultScene;
    if (scene >= static_cast<int>(m_.scenes.size()) || scene < -1) {
      return Error{"default scene " + std::to_string(scene) + " does not exist (the file has " +
                   std::to_string(m_.scenes.size()) + ")"};
    }
    if (scene < 0 && !m_.scenes.empty()) scene = 0;
    if (scene < 0) {
      for (std::size_t i = 0; i < asset_.nodes.size(); ++i) {
        if (asset_.nodes[i].parent < 0) asset_.roots.push_back(static_cast<int>(i));
      }
      return {};
    }
    const tinygltf::Scene& in = m_.scenes[static_cast<std::size_t>(scene)];
    const std::string where = describe("scene", static_cast<std::size_t>(scene), in.name);
    std::set<int> seen;
    for (const int node : in.nodes) {
      if (node < 0 || static_cast<std::size_t>(node) >= m_.nodes.size()) {
        return Error{where + ": node " + std::to_string(node) + " does not exist (the file has " +
                     std::to_string(m_.nodes.size()) + ")"};
      }
      const auto file = static_cast<std::size_t>(node);
      if (order.parent[file] >= 0) {
        return Error{where + ": " + describe_node(m_, file) + " is a root but has a parent"};
      }
      if (!seen.insert(node).second) {
        return Error{where + ": " + describe_node(m_, file) + " is listed twice"};
      }
      asset_.roots.push_back(order.new_index[file]);
    }
    return {};
  }

  const tinygltf::Model& m_;
  ModelAsset asset_;
  std::vector<std::vector<PrimitiveInfo>> info_;  // per mesh, per primitive
};

Result<ModelAsset> load(std::span<const std::uint8_t> bytes, const std::string& name,
                        const std::optional<std::string>& base_dir) {
  auto document = parse_gltf(bytes, base_dir);
  if (!document) return prefixed(name, document.error());
  auto asset = Converter(*document).run();
  if (!asset) return prefixed(name, asset.error());
  asset->source = name;
  return asset;
}

}  // namespace

Result<ModelAsset> load_model(const std::filesystem::path& path) {
  auto bytes = read_file_bytes(path, kMaxModelFileBytes);
  if (!bytes) return bytes.error();  // already "PATH: reason"
  std::string dir = path.parent_path().string();
  if (dir.empty()) dir = ".";
  return load(*bytes, path.string(), dir);
}

Result<ModelAsset> load_model_from_memory(std::span<const std::uint8_t> bytes,
                                          const std::string& name) {
  return load(bytes, name, std::nullopt);
}

}  // namespace tutti::model
