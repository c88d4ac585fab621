#pragma once
// Small helpers for building a glTF 2.0 model in memory: flat-shaded boxes and cylinders, one
// binary buffer, one accessor and buffer view per attribute, materials with a base colour.
//
// Units: metres, glTF axes (+Y up, +Z toward the viewer, right-handed). The builder keeps
// every buffer view 4-byte aligned, writes POSITION min/max (the spec requires them), never
// sets byteStride (tightly packed views are valid for vertex data and required for indices),
// and stamps asset.version "2.0" and asset.generator "tutti". Output is a pure function of the
// calls made, so the same calls give byte-identical files.

#include <tiny_gltf.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tutti::content_generator {

using Vec3 = std::array<float, 3>;    // mesh data
using DVec3 = std::array<double, 3>;  // node transforms

// Triangle list with per-face normals (flat shading), 16-bit indices.
struct MeshData {
  std::vector<float> positions;  // x, y, z per vertex, metres
  std::vector<float> normals;    // unit, per vertex
  std::vector<std::uint16_t> indices;
};

// An axis-aligned box from `min` to `max` (metres), 24 vertices so every face is flat.
void add_box(MeshData& mesh, Vec3 min, Vec3 max);

// A closed cylinder along +Y: bottom centre `base`, `radius`, `height` (metres), `segments` >= 3.
void add_cylinder(MeshData& mesh, Vec3 base, float radius, float height, int segments);

struct Material {
  std::string name;
  std::array<double, 4> base_colour{1.0, 1.0, 1.0, 1.0};  // linear RGBA
  double metallic = 0.0;
  double roughness = 0.5;
};

class ModelBuilder {
 public:
  ModelBuilder();

  int add_material(const Material& material);
  // One primitive (triangles) with POSITION, NORMAL and indices. Returns the mesh index.
  int add_mesh(const std::string& name, const MeshData& data, int material);
  // translation in metres; rotation a unit quaternion (x, y, z, w). mesh -1 = no mesh.
  int add_node(const std::string& name, int mesh = -1, DVec3 translation = {0, 0, 0},
               std::array<double, 4> rotation = {0, 0, 0, 1});
  void add_child(int parent, int child);
  // The default scene's root nodes.
  void add_root(int node);

  // The finished model (call once).
  tinygltf::Model finish();

 private:
  int add_accessor(const void* bytes, std::size_t byte_count, int target, int component_type,
                   int type, std::size_t count);

  tinygltf::Model model_;
  std::vector<unsigned char> bytes_;
};

// Rotation of `radians` about the +X axis as a glTF quaternion (x, y, z, w).
std::array<double, 4> rotation_about_x(double radians);

}  // namespace tutti::content_generator
