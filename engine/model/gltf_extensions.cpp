// SPDX-License-Identifier: MIT
#include <tutti/model/gltf_extensions.hpp>

#include <meshoptimizer.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>

#include <tutti/model/gltf_accessors.hpp>
#include <tutti/model/gltf_document.hpp>
#include <tutti/model/gltf_draco.hpp>

namespace tutti::model::detail {
namespace {

using json = nlohmann::json;

constexpr const char* kMeshopt = "EXT_meshopt_compression";
// What a decoded view or a dense accessor may grow to (the file cap).
constexpr std::size_t kMaxDecodedBytes = kMaxModelFileBytes;

// Extensions whose data tutti decodes.
const std::set<std::string> kDecoded = {"KHR_mesh_quantization", kMeshopt,
                                         "KHR_draco_mesh_compression"};
// Appearance only: the geometry is whole without them.
bool appearance_only(const std::string& name) {
  return name.rfind("KHR_materials_", 0) == 0 || name == "KHR_texture_transform" ||
         name == "EXT_texture_webp" || name == "KHR_texture_basisu" ||
         name == "MSFT_texture_dds" || name == "KHR_lights_punctual" ||
         name == "EXT_lights_image_based" || name == "KHR_xmp_json_ld" ||
         name == "KHR_materials_variants";
}

void append_u32(std::vector<std::uint8_t>& out, std::uint32_t value) {
  std::uint8_t raw[4];
  std::memcpy(raw, &value, 4);
  out.insert(out.end(), raw, raw + 4);
}

// A non-negative integer member of `object`, or an error naming it.
Result<std::size_t> size_member(const json& object, const char* key, const std::string& where,
                                std::optional<std::size_t> fallback = std::nullopt) {
  if (!object.contains(key)) {
    if (fallback) return *fallback;
    return Error{where + ": " + key + " missing"};
  }
  const json& v = object.at(key);
  if (!v.is_number_unsigned() && !(v.is_number_integer() && v.get<std::int64_t>() >= 0)) {
    return Error{where + ": " + key + " must be a non-negative integer"};
  }
  const auto value = v.get<std::uint64_t>();
  if (value > std::numeric_limits<std::uint32_t>::max()) {
    return Error{where + ": " + key + " " + std::to_string(value) + " is too large"};
  }
  return static_cast<std::size_t>(value);
}

Result<std::string> string_member(const json& object, const char* key, const std::string& where,
                                  const char* fallback) {
  if (!object.contains(key)) {
    if (fallback != nullptr) return std::string(fallback);
    return Error{where + ": " + key + " missing"};
  }
  if (!object.at(key).is_string()) return Error{where + ": " + key + " must be a string"};
  return object.at(key).get<std::string>();
}

Status check_required(const json& doc) {
  if (!doc.contains("extensionsRequired")) return {};
  const json& required = doc.at("extensionsRequired");
  if (!required.is_array()) return Error{"extensionsRequired is not an array"};
  for (const json& name : required) {
    if (!name.is_string()) return Error{"extensionsRequired holds a non-string"};
    const std::string extension = name.get<std::string>();
    if (kDecoded.count(extension) != 0 || appearance_only(extension)) continue;
    return Error{"requires the glTF extension " + extension + ", which tutti does not read"};
  }
  return {};
}

// Points every meshopt view at its compressed bytes; gives fallback buffers a stand-in.
Status rewrite_meshopt(json& doc, std::vector<MeshoptView>& views) {
  if (doc.contains("bufferViews") && doc.at("bufferViews").is_array()) {
    json& all = doc.at("bufferViews");
    for (std::size_t i = 0; i < all.size(); ++i) {
      json& view = all[i];
      if (!view.is_object() || !view.contains("extensions") || !view.at("extensions").is_object() ||
          !view.at("extensions").contains(kMeshopt)) {
        continue;
      }
      const json& e = view.at("extensions").at(kMeshopt);
      const std::string where = "buffer view " + std::to_string(i) + " " + kMeshopt;
      if (!e.is_object()) return Error{where + ": not an object"};
      auto buffer = size_member(e, "buffer", where);
      if (!buffer) return buffer.error();
      auto offset = size_member(e, "byteOffset", where, 0);
      if (!offset) return offset.error();
      auto length = size_member(e, "byteLength", where);
      if (!length) return length.error();
      auto stride = size_member(e, "byteStride", where);
      if (!stride) return stride.error();
      auto count = size_member(e, "count", where);
      if (!count) return count.error();
      auto mode = string_member(e, "mode", where, nullptr);
      if (!mode) return mode.error();
      auto filter = string_member(e, "filter", where, "NONE");
      if (!filter) return filter.error();
      views.push_back({i, *count, *stride, *mode, *filter});
      view["buffer"] = *buffer;
      view["byteOffset"] = *offset;
      view["byteLength"] = *length;
      view.erase("byteStride");  // the compressed bytes have none; restored after decoding
    }
  }
  if (doc.contains("buffers") && doc.at("buffers").is_array()) {
    for (json& buffer : doc.at("buffers")) {
      if (!buffer.is_object() || !buffer.contains("extensions") ||
          !buffer.at("extensions").is_object() || !buffer.at("extensions").contains(kMeshopt)) {
        continue;
      }
      const json& e = buffer.at("extensions").at(kMeshopt);
      if (e.is_object() && e.contains("fallback") && e.at("fallback") == true) {
        buffer["uri"] = "data:application/octet-stream;base64,AAAA";
        buffer["byteLength"] = 3;
      }
    }
  }
  return {};
}

// tinygltf (built without Draco) wants a buffer view on every accessor a primitive uses; the
// accessors a Draco primitive decodes into have none. They are pointed at the compressed view
// until decode_draco_primitives gives them their decoded data.
void point_draco_accessors(json& doc) {
  if (!doc.contains("meshes") || !doc.at("meshes").is_array() || !doc.contains("accessors") ||
      !doc.at("accessors").is_array()) {
    return;
  }
  json& accessors = doc.at("accessors");
  const auto point = [&](const json& index, const json& view) {
    if (!index.is_number_unsigned() || index.get<std::size_t>() >= accessors.size()) return;
    json& accessor = accessors[index.get<std::size_t>()];
    if (accessor.is_object() && !accessor.contains("bufferView")) accessor["bufferView"] = view;
  };
  for (const json& mesh : doc.at("meshes")) {
    if (!mesh.is_object() || !mesh.contains("primitives") || !mesh.at("primitives").is_array()) {
      continue;
    }
    for (const json& primitive : mesh.at("primitives")) {
      if (!primitive.is_object() || !primitive.contains("extensions") ||
          !primitive.at("extensions").is_object() ||
          !primitive.at("extensions").contains("KHR_draco_mesh_compression")) {
        continue;
      }
      const json& e = primitive.at("extensions").at("KHR_draco_mesh_compression");
      if (!e.is_object() || !e.contains("bufferView") || !e.contains("attributes") ||
          !e.at("attributes").is_object()) {
        continue;  // decode_draco_primitives names the problem
      }
      if (primitive.contains("indices")) point(primitive.at("indices"), e.at("bufferView"));
      if (!primitive.contains("attributes") || !primitive.at("attributes").is_object()) continue;
      for (const auto& [name, id] : e.at("attributes").items()) {
        if (primitive.at("attributes").contains(name)) {
          point(primitive.at("attributes").at(name), e.at("bufferView"));
        }
      }
    }
  }
}

std::vector<std::uint8_t> rebuild_glb(std::span<const std::uint8_t> bytes, const std::string& text) {
  std::string json_chunk = text;
  while (json_chunk.size() % 4 != 0) json_chunk += ' ';
  const std::size_t old_json = read_u32(bytes, 12);
  const std::size_t length = std::min<std::size_t>(read_u32(bytes, 8), bytes.size());
  const std::size_t rest_from = std::min(length, 20 + old_json);
  std::vector<std::uint8_t> out;
  out.reserve(20 + json_chunk.size() + (length - rest_from));
  append_u32(out, 0x46546C67);
  append_u32(out, 2);
  append_u32(out, static_cast<std::uint32_t>(20 + json_chunk.size() + (length - rest_from)));
  append_u32(out, static_cast<std::uint32_t>(json_chunk.size()));
  append_u32(out, 0x4E4F534A);
  out.insert(out.end(), json_chunk.begin(), json_chunk.end());
  out.insert(out.end(), bytes.begin() + static_cast<std::ptrdiff_t>(rest_from),
             bytes.begin() + static_cast<std::ptrdiff_t>(length));
  return out;
}

int add_buffer(tinygltf::Model& model, std::vector<unsigned char> data) {
  tinygltf::Buffer buffer;
  buffer.data = std::move(data);
  model.buffers.push_back(std::move(buffer));
  return static_cast<int>(model.buffers.size() - 1);
}

Status decode_meshopt(tinygltf::Model& model, const MeshoptView& job) {
  const std::string where = "buffer view " + std::to_string(job.view) + " " + kMeshopt;
  if (job.view >= model.bufferViews.size()) return Error{where + ": no such buffer view"};
  tinygltf::BufferView& view = model.bufferViews[job.view];
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
    return Error{where + ": buffer " + std::to_string(view.buffer) + " does not exist"};
  }
  const std::vector<unsigned char>& source = model.buffers[static_cast<std::size_t>(view.buffer)].data;
  if (view.byteLength > source.size() || view.byteOffset > source.size() - view.byteLength) {
    return Error{where + ": compressed bytes " + std::to_string(view.byteOffset) + " + " +
                 std::to_string(view.byteLength) + " run past the end of buffer " +
                 std::to_string(view.buffer) + " (" + std::to_string(source.size()) + " bytes)"};
  }
  const bool attributes = job.mode == "ATTRIBUTES";
  const bool triangles = job.mode == "TRIANGLES";
  const bool indices = job.mode == "INDICES";
  if (!attributes && !triangles && !indices) return Error{where + ": unknown mode " + job.mode};
  if (attributes && (job.stride == 0 || job.stride % 4 != 0 || job.stride > 256)) {
    return Error{where + ": byteStride " + std::to_string(job.stride) +
                 " (attributes need a multiple of 4 up to 256)"};
  }
  if (!attributes && job.stride != 2 && job.stride != 4) {
    return Error{where + ": byteStride " + std::to_string(job.stride) + " (indices are 2 or 4)"};
  }
  if (triangles && job.count % 3 != 0) {
    return Error{where + ": " + std::to_string(job.count) + " triangle indices, not a multiple of 3"};
  }
  if (job.count > kMaxDecodedCount || job.count * job.stride > kMaxDecodedBytes) {
    return Error{where + ": " + std::to_string(job.count) + " elements of " +
                 std::to_string(job.stride) + " bytes are over the limit"};
  }
  const unsigned char* compressed = source.data() + view.byteOffset;
  std::vector<unsigned char> decoded(job.count * job.stride);
  int status = 0;
  if (attributes) {
    status = meshopt_decodeVertexBuffer(decoded.data(), job.count, job.stride, compressed,
                                        view.byteLength);
  } else if (triangles) {
    status = meshopt_decodeIndexBuffer(decoded.data(), job.count, job.stride, compressed,
                                       view.byteLength);
  } else {
    status = meshopt_decodeIndexSequence(decoded.data(), job.count, job.stride, compressed,
                                         view.byteLength);
  }
  if (status != 0) {
    return Error{where + ": the compressed data does not decode (meshoptimizer error " +
                 std::to_string(status) + ")"};
  }
  if (job.filter != "NONE") {
    if (!attributes) return Error{where + ": filter " + job.filter + " on indices"};
    if (job.filter == "OCTAHEDRAL" && (job.stride == 4 || job.stride == 8)) {
      meshopt_decodeFilterOct(decoded.data(), job.count, job.stride);
    } else if (job.filter == "QUATERNION" && job.stride == 8) {
      meshopt_decodeFilterQuat(decoded.data(), job.count, job.stride);
    } else if (job.filter == "EXPONENTIAL") {
      meshopt_decodeFilterExp(decoded.data(), job.count, job.stride);
    } else {
      return Error{where + ": filter " + job.filter + " with byteStride " +
                   std::to_string(job.stride) + " is not defined"};
    }
  }
  view.byteLength = decoded.size();
  view.buffer = add_buffer(model, std::move(decoded));
  view.byteOffset = 0;
  view.byteStride = attributes ? job.stride : 0;
  return {};
}

// A sparse accessor written out dense: the base view's elements (or zeros), then the sparse
// values at their indices.
Status densify(tinygltf::Model& model, std::size_t index) {
  tinygltf::Accessor& accessor = model.accessors[index];
  const std::string where = "accessor " + std::to_string(index) + " (sparse)";
  const std::size_t element =
      component_size(accessor.componentType) * static_cast<std::size_t>(component_count(accessor.type));
  if (element == 0) return Error{where + ": unknown type or component type"};
  if (accessor.count > kMaxDecodedCount || accessor.count * element > kMaxDecodedBytes) {
    return Error{where + ": count " + std::to_string(accessor.count) + " is over the limit"};
  }
  if (accessor.sparse.count < 0 || static_cast<std::size_t>(accessor.sparse.count) > accessor.count) {
    return Error{where + ": " + std::to_string(accessor.sparse.count) +
                 " sparse values for " + std::to_string(accessor.count) + " elements"};
  }
  const auto sparse_count = static_cast<std::size_t>(accessor.sparse.count);
  const AccessorRule any_of_its_type{accessor.type,
                                     {accessor.componentType},
                                     {accessor.componentType},
                                     kMaxDecodedCount};
  std::vector<unsigned char> dense(accessor.count * element, 0);
  // The base: the accessor as it is, without its sparse part.
  const auto saved_sparse = accessor.sparse;
  accessor.sparse.isSparse = false;
  auto base = locate_accessor(model, static_cast<int>(index), any_of_its_type);
  accessor.sparse = saved_sparse;
  if (!base) return Error{where + ": " + base.error().message};
  if (base->data != nullptr) {
    for (std::size_t i = 0; i < base->count; ++i) {
      std::memcpy(dense.data() + i * element, base->data + i * base->stride, element);
    }
  }
  // The indices and values, through the same range checks as any accessor.
  tinygltf::Accessor indices_accessor;
  indices_accessor.bufferView = accessor.sparse.indices.bufferView;
  indices_accessor.byteOffset = static_cast<std::size_t>(std::max(0, accessor.sparse.indices.byteOffset));
  indices_accessor.componentType = accessor.sparse.indices.componentType;
  indices_accessor.count = sparse_count;
  indices_accessor.type = TINYGLTF_TYPE_SCALAR;
  tinygltf::Accessor values_accessor;
  values_accessor.bufferView = accessor.sparse.values.bufferView;
  values_accessor.byteOffset = static_cast<std::size_t>(std::max(0, accessor.sparse.values.byteOffset));
  values_accessor.componentType = accessor.componentType;
  values_accessor.normalized = accessor.normalized;
  values_accessor.count = sparse_count;
  values_accessor.type = accessor.type;
  if (indices_accessor.bufferView < 0 || values_accessor.bufferView < 0) {
    return Error{where + ": sparse indices and values need buffer views"};
  }
  model.accessors.push_back(indices_accessor);
  model.accessors.push_back(values_accessor);
  const int values_index = static_cast<int>(model.accessors.size() - 1);
  auto sparse_indices = read_indices(model, values_index - 1, sparse_count);
  auto values = locate_accessor(model, values_index, any_of_its_type);
  model.accessors.resize(model.accessors.size() - 2);
  if (!sparse_indices) return Error{where + ": indices: " + sparse_indices.error().message};
  if (!values) return Error{where + ": values: " + values.error().message};
  for (std::size_t k = 0; k < sparse_count; ++k) {
    const std::uint32_t at = (*sparse_indices)[k];
    if (at >= accessor.count) {
      return Error{where + ": sparse index " + std::to_string(at) + " is past its " +
                   std::to_string(accessor.count) + " elements"};
    }
    std::memcpy(dense.data() + static_cast<std::size_t>(at) * element,
                values->data + k * values->stride, element);
  }
  tinygltf::BufferView view;
  view.byteLength = dense.size();
  view.buffer = add_buffer(model, std::move(dense));
  model.bufferViews.push_back(view);
  tinygltf::Accessor& out = model.accessors[index];
  out.bufferView = static_cast<int>(model.bufferViews.size() - 1);
  out.byteOffset = 0;
  out.sparse.isSparse = false;
  return {};
}

}  // namespace

Result<PreparedDocument> prepare_extensions(std::span<const std::uint8_t> bytes, bool binary,
                                            std::span<const std::uint8_t> json_text) {
  PreparedDocument prepared;
  const std::string_view text(reinterpret_cast<const char*>(json_text.data()), json_text.size());
  // Most files use none of this: only those that name an extension are parsed here.
  const bool meshopt = text.find(kMeshopt) != std::string_view::npos;
  const bool draco = text.find("KHR_draco_mesh_compression") != std::string_view::npos;
  if (text.find("extensionsRequired") == std::string_view::npos && !meshopt && !draco) {
    return prepared;
  }
  json doc;
  try {
    doc = json::parse(text);
  } catch (const std::exception&) {
    return prepared;  // tinygltf gives the parse error
  }
  if (!doc.is_object()) return prepared;
  if (auto ok = check_required(doc); !ok) return ok.error();
  if (!meshopt && !draco) return prepared;
  if (meshopt) {
    if (auto ok = rewrite_meshopt(doc, prepared.meshopt); !ok) return ok.error();
  }
  if (draco) point_draco_accessors(doc);
  const std::string rewritten = doc.dump();
  prepared.rewritten = true;
  if (binary) {
    prepared.bytes = rebuild_glb(bytes, rewritten);
  } else {
    prepared.bytes.assign(rewritten.begin(), rewritten.end());
  }
  return prepared;
}

Status resolve_extensions(tinygltf::Model& model, const PreparedDocument& prepared) {
  for (const MeshoptView& job : prepared.meshopt) {
    if (auto ok = decode_meshopt(model, job); !ok) return ok;
  }
  if (auto ok = decode_draco_primitives(model); !ok) return ok;
  const std::size_t accessors = model.accessors.size();
  for (std::size_t i = 0; i < accessors; ++i) {
    if (!model.accessors[i].sparse.isSparse) continue;
    if (auto ok = densify(model, i); !ok) return ok;
  }
  return {};
}

}  // namespace tutti::model::detail
