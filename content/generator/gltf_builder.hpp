// SPDX-License-Identifier: MIT
#pragma once
// Small helpers for building a glTF 2.0 model in memory: flat-shaded boxes and cylinders,
// smooth tubes (swept circles, surfaces of revolution, capsules, spheres), one binary buffer, one
// accessor and buffer view per attribute, materials with a base colour; skins (JOINTS_0 /
// WEIGHTS_0, inverse bind matrices from the nodes' rest transforms) and morph targets.
//
// Units: metres, glTF axes (+Y up, +Z toward the viewer, right-handed). The builder keeps
// every buffer view 4-byte aligned, writes POSITION min/max (the spec requires them), never
// sets byteStride (tightly packed views are valid for vertex data and required for indices),
// and stamps asset.version "2.0" and asset.generator "tutti". Output is a pure function of the
// calls made, so the same calls give byte-identical files. Skinned meshes: JOINTS_0 is unsigned
// short VEC4 (not normalised), WEIGHTS_0 float VEC4 summing to 1, inverseBindMatrices MAT4 float
// with one matrix per joint; a node that draws a skinned mesh must be a scene root without a
// transform (glTF ignores it anyway). Morph targets carry POSITION (with min/max) and NORMAL
// deltas, their names in mesh.extras.targetNames, default weights 0.

#include <tiny_gltf.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

namespace tutti::content_generator {

using Vec3 = std::array<float, 3>;    // mesh data
using DVec3 = std::array<double, 3>;  // node transforms
using Quat = std::array<double, 4>;   // unit quaternion x, y, z, w

inline constexpr double kPi = std::numbers::pi;
// Millimetres (the dimensions' unit) to metres (glTF's), as mesh data.
inline float m(double mm) { return static_cast<float>(mm / 1000.0); }

// Vector arithmetic on mesh data (float) and on transforms (double).
inline Vec3 sub(Vec3 a, Vec3 b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 add(Vec3 a, Vec3 b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 scaled(Vec3 a, float s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline float dot(Vec3 a, Vec3 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline DVec3 add(DVec3 a, DVec3 b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline DVec3 scaled(DVec3 a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline double dot(DVec3 a, DVec3 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline DVec3 cross(DVec3 a, DVec3 b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
using Mat4 = std::array<double, 16>;  // column-major 4x4, like glTF

// Vertex deltas of one morph target (same vertex count as the base mesh).
struct MorphTarget {
  std::string name;
  std::vector<float> positions;  // dx, dy, dz per vertex, metres
  std::vector<float> normals;    // normal deltas per vertex
};

// Triangle list with per-vertex normals (flat or smooth), 16-bit indices; optional skin weights
// (4 joints and 4 weights per vertex, all vertices or none) and morph targets.
struct MeshData {
  std::vector<float> positions;  // x, y, z per vertex, metres
  std::vector<float> normals;    // unit, per vertex
  std::vector<std::uint16_t> indices;
  std::vector<std::uint16_t> joints;  // 4 per vertex: indices into the skin's joint list
  std::vector<float> weights;         // 4 per vertex, summing to 1
  std::vector<MorphTarget> targets;

  std::size_t vertex_count() const { return positions.size() / 3; }
};

// Gives every vertex from `first_vertex` on the joint `joint` with weight 1.
void weight_vertices(MeshData& mesh, std::size_t first_vertex, std::uint16_t joint);
// Gives every vertex from `first_vertex` on joints a and b, weight of b = blend(vertex) in [0, 1].
template <typename Blend>
void weight_vertices_blend(MeshData& mesh, std::size_t first_vertex, std::uint16_t a,
                           std::uint16_t b, Blend blend) {
  for (std::size_t v = first_vertex; v < mesh.vertex_count(); ++v) {
    const float w = static_cast<float>(
        blend(Vec3{mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]}));
    mesh.joints.insert(mesh.joints.end(), {a, b, 0, 0});
    mesh.weights.insert(mesh.weights.end(), {1.0f - w, w, 0.0f, 0.0f});
  }
}
// Transforms the positions and normals of the vertices from `first_vertex` on by a rigid
// matrix (rotation and translation; normals are rotated).
void transform_vertices(MeshData& mesh, std::size_t first_vertex, const Mat4& matrix);

// An axis-aligned box from `min` to `max` (metres), 24 vertices so every face is flat.
void add_box(MeshData& mesh, Vec3 min, Vec3 max);

// A closed cylinder along +Y: bottom centre `base`, `radius`, `height` (metres), `segments` >= 3.
void add_cylinder(MeshData& mesh, Vec3 base, float radius, float height, int segments);

// A smooth tube along the polyline `centres` (>= 2 points, metres) with radius `radii[i]` at
// each (> 0), rings of `segments` vertices, normals from the surface's slope. Ends: open, a flat
// disc, or a hemisphere of the end's radius. `inward`: the surface faces the axis (the inside of
// a bell). Covers surfaces of revolution (straight centres), bent pipes and capsules.
struct Tube {
  enum class End { open, flat, rounded };
  std::vector<Vec3> centres;
  std::vector<float> radii;
  int segments = 16;
  End start = End::flat;
  End end = End::flat;
  bool inward = false;
};
void add_tube(MeshData& mesh, const Tube& tube);
// A capsule from `a` to `b` (rounded ends) with radius ra at a and rb at b.
void add_capsule(MeshData& mesh, Vec3 a, Vec3 b, float ra, float rb, int segments = 12);
// A sphere (a capsule of zero length along Y), `segments` around.
void add_sphere(MeshData& mesh, Vec3 centre, float radius, int segments = 16);
// A flattened sphere: the unit sphere scaled by `radii` along X, Y and Z about `centre`.
void add_ellipsoid(MeshData& mesh, Vec3 centre, Vec3 radii, int segments = 16);
// Points along a circular arc from `from` around `centre` by `radians` about `axis` (unit,
// right-handed), `steps` + 1 points including both ends.
std::vector<Vec3> arc_points(Vec3 centre, Vec3 from, Vec3 axis, double radians, int steps);

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
  void set_scale(int node, DVec3 scale);
  void set_extras(int node, tinygltf::Value extras);
  // The node's transform relative to the scene (its parents' transforms applied).
  Mat4 world_matrix(int node) const;
  // A skin over `joints` (node indices; JOINTS_0 indexes this list) whose inverse bind matrices
  // are the inverses of the joints' current world matrices (the rest pose). Returns its index.
  int add_skin(const std::string& name, const std::vector<int>& joints, int skeleton_root);
  // Makes `node` draw its mesh with `skin` (the node should be a scene root without transform).
  void set_skin(int node, int skin);

  // The finished model (call once).
  tinygltf::Model finish();

 private:
  int add_accessor(const void* bytes, std::size_t byte_count, int target, int component_type,
                   int type, std::size_t count);

  int add_vec3_accessor(const std::vector<float>& values, bool with_bounds);

  tinygltf::Model model_;
  std::vector<unsigned char> bytes_;
  std::vector<int> parent_;  // per node, -1 = none
};

// Rotation of `radians` about the +X axis as a glTF quaternion (x, y, z, w).
std::array<double, 4> rotation_about_x(double radians);
// Rotation of `radians` about a unit `axis`.
Quat rotation_about(DVec3 axis, double radians);
// The Hamilton product a * b: the rotation b first, then a.
Quat quat_multiply(const Quat& a, const Quat& b);
// Translation, rotation, scale as a matrix (T * R * S, glTF's order).
Mat4 compose(DVec3 translation, const Quat& rotation, DVec3 scale = {1, 1, 1});
Mat4 multiply(const Mat4& a, const Mat4& b);
// Inverse of an affine matrix (last row 0 0 0 1) with an invertible 3x3 part.
Mat4 affine_inverse(const Mat4& m);
DVec3 transform_point(const Mat4& m, DVec3 p);

}  // namespace tutti::content_generator
