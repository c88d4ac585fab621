// SPDX-License-Identifier: MIT
#include <tutti/model/gltf_draco.hpp>

#include <draco/compression/decode.h>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <tutti/model/gltf_accessors.hpp>
#include <tutti/model/gltf_document.hpp>

namespace tutti::model::detail {
namespace {

constexpr const char* kDraco = "KHR_draco_mesh_compression";

int add_view(tinygltf::Model& model, std::vector<unsigned char> data) {
  tinygltf::Buffer buffer;
  buffer.data = std::move(data);
  model.buffers.push_back(std::move(buffer));
  tinygltf::BufferView view;
  view.buffer = static_cast<int>(model.buffers.size() - 1);
  view.byteLength = model.buffers.back().data.size();
  model.bufferViews.push_back(view);
  return static_cast<int>(model.bufferViews.size() - 1);
}

template <typename T>
std::vector<unsigned char> bytes_of(const std::vector<T>& values) {
  std::vector<unsigned char> out(values.size() * sizeof(T));
  if (!out.empty()) std::memcpy(out.data(), values.data(), out.size());
  return out;
}

Status decode_one(tinygltf::Model& model, tinygltf::Primitive& primitive, const std::string& where) {
  const tinygltf::Value& e = primitive.extensions.at(kDraco);
  if (!e.IsObject() || !e.Has("bufferView") || !e.Get("bufferView").IsInt() ||
      !e.Has("attributes") || !e.Get("attributes").IsObject()) {
    return Error{where + ": " + kDraco + " needs a bufferView and attributes"};
  }
  const int view_index = e.Get("bufferView").GetNumberAsInt();
  if (view_index < 0 || static_cast<std::size_t>(view_index) >= model.bufferViews.size()) {
    return Error{where + ": " + kDraco + " buffer view " + std::to_string(view_index) +
                 " does not exist"};
  }
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(view_index)];
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
    return Error{where + ": " + kDraco + " buffer " + std::to_string(view.buffer) + " does not exist"};
  }
  const std::vector<unsigned char>& buffer = model.buffers[static_cast<std::size_t>(view.buffer)].data;
  if (view.byteLength > buffer.size() || view.byteOffset > buffer.size() - view.byteLength) {
    return Error{where + ": " + kDraco + " data runs past the end of buffer " +
                 std::to_string(view.buffer)};
  }
  draco::DecoderBuffer compressed;
  compressed.Init(reinterpret_cast<const char*>(buffer.data() + view.byteOffset), view.byteLength);
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&compressed);
  if (!decoded.ok()) {
    return Error{where + ": " + kDraco + " data does not decode (" +
                 decoded.status().error_msg_string() + ")"};
  }
  const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
  const std::size_t points = mesh->num_points();
  const std::size_t corners = static_cast<std::size_t>(mesh->num_faces()) * 3;
  if (points > kMaxDecodedCount || corners > kMaxDecodedCount) {
    return Error{where + ": " + kDraco + ": " + std::to_string(points) + " points and " +
                 std::to_string(corners) + " indices are over the limit"};
  }
  // Indices.
  if (primitive.indices >= 0) {
    if (static_cast<std::size_t>(primitive.indices) >= model.accessors.size()) {
      return Error{where + ": indices accessor " + std::to_string(primitive.indices) +
                   " does not exist"};
    }
    tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(primitive.indices)];
    if (accessor.count != corners) {
      return Error{where + ": " + kDraco + " decodes " + std::to_string(corners) +
                   " indices, the accessor says " + std::to_string(accessor.count)};
    }
    std::vector<std::uint32_t> indices(corners);
    for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f) {
      const auto& face = mesh->face(f);
      for (int c = 0; c < 3; ++c) {
        indices[f.value() * 3 + static_cast<std::size_t>(c)] = face[c].value();
      }
    }
    accessor.bufferView = add_view(model, bytes_of(indices));
    accessor.byteOffset = 0;
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    accessor.sparse.isSparse = false;
  }
  // Attributes, each in the component type its accessor declares (draco converts, normalising
  // where the attribute is normalised).
  const tinygltf::Value& attributes = e.Get("attributes");
  for (const std::string& name : attributes.Keys()) {
    const tinygltf::Value& id = attributes.Get(name);
    const auto it = primitive.attributes.find(name);
    if (!id.IsInt() || it == primitive.attributes.end() || it->second < 0 ||
        static_cast<std::size_t>(it->second) >= model.accessors.size()) {
      return Error{where + ": " + kDraco + " attribute " + name + " has no accessor"};
    }
    const draco::PointAttribute* attribute =
        mesh->GetAttributeByUniqueId(static_cast<std::uint32_t>(id.GetNumberAsInt()));
    if (attribute == nullptr) {
      return Error{where + ": " + kDraco + " attribute " + name + " (id " +
                   std::to_string(id.GetNumberAsInt()) + ") is not in the compressed data"};
    }
    tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(it->second)];
    const int components = component_count(accessor.type);
    if (accessor.count != points || components == 0 || components > 16 ||
        attribute->num_components() != components) {
      return Error{where + ": " + kDraco + " attribute " + name + " decodes " +
                   std::to_string(points) + " x " + std::to_string(attribute->num_components()) +
                   ", the accessor says " + std::to_string(accessor.count) + " x " +
                   std::to_string(components)};
    }
    const auto n = static_cast<std::size_t>(components);
    const bool joints = accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                        accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    if (joints && !accessor.normalized) {
      std::vector<std::uint16_t> values(points * n);
      for (draco::PointIndex p(0); p < mesh->num_points(); ++p) {
        if (!attribute->ConvertValue<std::uint16_t>(attribute->mapped_index(p),
                                                    static_cast<std::int8_t>(components),
                                                    values.data() + p.value() * n)) {
          return Error{where + ": " + kDraco + " attribute " + name + " does not convert"};
        }
      }
      accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
      accessor.bufferView = add_view(model, bytes_of(values));
    } else {
      std::vector<float> values(points * n);
      for (draco::PointIndex p(0); p < mesh->num_points(); ++p) {
        if (!attribute->ConvertValue<float>(attribute->mapped_index(p),
                                            static_cast<std::int8_t>(components),
                                            values.data() + p.value() * n)) {
          return Error{where + ": " + kDraco + " attribute " + name + " does not convert"};
        }
      }
      accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
      accessor.normalized = false;
      accessor.bufferView = add_view(model, bytes_of(values));
    }
    accessor.byteOffset = 0;
    accessor.sparse.isSparse = false;
  }
  primitive.extensions.erase(kDraco);
  return {};
}

}  // namespace

Status decode_draco_primitives(tinygltf::Model& model) {
  for (std::size_t m = 0; m < model.meshes.size(); ++m) {
    for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
      tinygltf::Primitive& primitive = model.meshes[m].primitives[p];
      if (primitive.extensions.count(kDraco) == 0) continue;
      const std::string where = "mesh " + std::to_string(m) + " primitive " + std::to_string(p);
      if (auto ok = decode_one(model, primitive, where); !ok) return ok;
    }
  }
  return {};
}

}  // namespace tutti::model::detail
