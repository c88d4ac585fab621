#include "generator/gltf_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace tutti::content_generator {
namespace {

void push_vertex(MeshData& mesh, Vec3 position, Vec3 normal) {
  mesh.positions.insert(mesh.positions.end(), position.begin(), position.end());
  mesh.normals.insert(mesh.normals.end(), normal.begin(), normal.end());
}

std::uint16_t vertex_count(const MeshData& mesh) {
  const std::size_t count = mesh.positions.size() / 3;
  if (count > std::numeric_limits<std::uint16_t>::max() - 64) {
    throw std::length_error("mesh too large for 16-bit indices");  // a generator bug
  }
  return static_cast<std::uint16_t>(count);
}

// A quad a-b-c-d, counter-clockwise seen from the side `normal` points to.
void push_quad(MeshData& mesh, Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 normal) {
  const std::uint16_t first = vertex_count(mesh);
  for (const Vec3& v : {a, b, c, d}) push_vertex(mesh, v, normal);
  for (const int i : {0, 1, 2, 0, 2, 3}) {
    mesh.indices.push_back(static_cast<std::uint16_t>(first + i));
  }
}

}  // namespace

void add_box(MeshData& mesh, Vec3 min, Vec3 max) {
  const auto [x0, y0, z0] = min;
  const auto [x1, y1, z1] = max;
  push_quad(mesh, {x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x1, y0, z1}, {1, 0, 0});   // +X
  push_quad(mesh, {x0, y0, z1}, {x0, y1, z1}, {x0, y1, z0}, {x0, y0, z0}, {-1, 0, 0});  // -X
  push_quad(mesh, {x0, y1, z1}, {x1, y1, z1}, {x1, y1, z0}, {x0, y1, z0}, {0, 1, 0});   // +Y
  push_quad(mesh, {x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1}, {0, -1, 0});  // -Y
  push_quad(mesh, {x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}, {0, 0, 1});   // +Z
  push_quad(mesh, {x1, y0, z0}, {x0, y0, z0}, {x0, y1, z0}, {x1, y1, z0}, {0, 0, -1});  // -Z
}

void add_cylinder(MeshData& mesh, Vec3 base, float radius, float height, int segments) {
  // Plain copies, not structured bindings: lambdas may not capture those before C++20's fix
  // (clang 14).
  const float cx = base[0];
  const float cy = base[1];
  const float cz = base[2];
  const float top = cy + height;
  auto point = [&](int i, float y) {
    const double angle = 2.0 * std::numbers::pi * i / segments;
    return Vec3{cx + radius * static_cast<float>(std::cos(angle)), y,
                cz - radius * static_cast<float>(std::sin(angle))};
  };
  for (int i = 0; i < segments; ++i) {
    const double mid = 2.0 * std::numbers::pi * (i + 0.5) / segments;
    const Vec3 normal{static_cast<float>(std::cos(mid)), 0.0f, -static_cast<float>(std::sin(mid))};
    push_quad(mesh, point(i, cy), point(i + 1, cy), point(i + 1, top), point(i, top), normal);
  }
  for (const bool upper : {false, true}) {
    const std::uint16_t centre = vertex_count(mesh);
    push_vertex(mesh, {cx, upper ? top : cy, cz}, {0, upper ? 1.0f : -1.0f, 0});
    for (int i = 0; i <= segments; ++i) {
      push_vertex(mesh, point(i, upper ? top : cy), {0, upper ? 1.0f : -1.0f, 0});
    }
    for (int i = 0; i < segments; ++i) {
      const auto a = static_cast<std::uint16_t>(centre + 1 + i);
      const auto b = static_cast<std::uint16_t>(centre + 2 + i);
      // Points run counter-clockwise seen from above (+Y).
      if (upper) {
        mesh.indices.insert(mesh.indices.end(), {centre, a, b});
      } else {
        mesh.indices.insert(mesh.indices.end(), {centre, b, a});
      }
    }
  }
}

std::array<double, 4> rotation_about_x(double radians) {
  return {std::sin(radians / 2.0), 0.0, 0.0, std::cos(radians / 2.0)};
}

ModelBuilder::ModelBuilder() {
  model_.asset.version = "2.0";
  model_.asset.generator = "tutti";
  model_.scenes.emplace_back();
  model_.defaultScene = 0;
}

int ModelBuilder::add_material(const Material& material) {
  tinygltf::Material out;
  out.name = material.name;
  out.pbrMetallicRoughness.baseColorFactor.assign(material.base_colour.begin(),
                                                  material.base_colour.end());
  out.pbrMetallicRoughness.metallicFactor = material.metallic;
  out.pbrMetallicRoughness.roughnessFactor = material.roughness;
  model_.materials.push_back(std::move(out));
  return static_cast<int>(model_.materials.size()) - 1;
}

int ModelBuilder::add_accessor(const void* bytes, std::size_t byte_count, int target,
                               int component_type, int type, std::size_t count) {
  // Every view starts 4-byte aligned (the largest component is a 4-byte float).
  bytes_.resize((bytes_.size() + 3) / 4 * 4, 0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = bytes_.size();
  view.byteLength = byte_count;
  view.target = target;
  const auto* first = static_cast<const unsigned char*>(bytes);
  bytes_.insert(bytes_.end(), first, first + byte_count);
  model_.bufferViews.push_back(view);

  tinygltf::Accessor accessor;
  accessor.bufferView = static_cast<int>(model_.bufferViews.size()) - 1;
  accessor.byteOffset = 0;
  accessor.componentType = component_type;
  accessor.type = type;
  accessor.count = count;
  model_.accessors.push_back(accessor);
  return static_cast<int>(model_.accessors.size()) - 1;
}

int ModelBuilder::add_mesh(const std::string& name, const MeshData& data, int material) {
  const std::size_t vertices = data.positions.size() / 3;
  const int position = add_accessor(data.positions.data(), data.positions.size() * sizeof(float),
                                    TINYGLTF_TARGET_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                    TINYGLTF_TYPE_VEC3, vertices);
  std::vector<double> min(3, std::numeric_limits<double>::infinity());
  std::vector<double> max(3, -std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < data.positions.size(); ++i) {
    min[i % 3] = std::min(min[i % 3], static_cast<double>(data.positions[i]));
    max[i % 3] = std::max(max[i % 3], static_cast<double>(data.positions[i]));
  }
  model_.accessors[static_cast<std::size_t>(position)].minValues = min;
  model_.accessors[static_cast<std::size_t>(position)].maxValues = max;
  const int normal = add_accessor(data.normals.data(), data.normals.size() * sizeof(float),
                                  TINYGLTF_TARGET_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                  TINYGLTF_TYPE_VEC3, vertices);
  const int indices =
      add_accessor(data.indices.data(), data.indices.size() * sizeof(std::uint16_t),
                   TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                   TINYGLTF_TYPE_SCALAR, data.indices.size());

  tinygltf::Primitive primitive;
  primitive.attributes["POSITION"] = position;
  primitive.attributes["NORMAL"] = normal;
  primitive.indices = indices;
  primitive.material = material;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  tinygltf::Mesh mesh;
  mesh.name = name;
  mesh.primitives.push_back(std::move(primitive));
  model_.meshes.push_back(std::move(mesh));
  return static_cast<int>(model_.meshes.size()) - 1;
}

int ModelBuilder::add_node(const std::string& name, int mesh, DVec3 translation,
                           std::array<double, 4> rotation) {
  tinygltf::Node node;
  node.name = name;
  node.mesh = mesh;
  if (translation != DVec3{0, 0, 0}) {
    node.translation = {translation[0], translation[1], translation[2]};
  }
  if (rotation != std::array<double, 4>{0, 0, 0, 1}) {
    node.rotation.assign(rotation.begin(), rotation.end());
  }
  model_.nodes.push_back(std::move(node));
  return static_cast<int>(model_.nodes.size()) - 1;
}

void ModelBuilder::add_child(int parent, int child) {
  model_.nodes[static_cast<std::size_t>(parent)].children.push_back(child);
}

void ModelBuilder::add_root(int node) { model_.scenes[0].nodes.push_back(node); }

tinygltf::Model ModelBuilder::finish() {
  bytes_.resize((bytes_.size() + 3) / 4 * 4, 0);
  tinygltf::Buffer buffer;
  buffer.data = std::move(bytes_);
  model_.buffers = {std::move(buffer)};
  return std::move(model_);
}

}  // namespace tutti::content_generator
