// SPDX-License-Identifier: MIT
#include <tutti/generator/gltf_builder.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
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

Vec3 normalised(Vec3 a) {
  const float length = std::sqrt(dot(a, a));
  return length > 0.0f ? scaled(a, 1.0f / length) : a;
}

// One ring of a tube: centre, frame (t along the tube, u x v = t), radius, and the normal as
// nr * radial + nt * t.
struct Ring {
  Vec3 centre;
  Vec3 t, u, v;
  float radius;
  float nr, nt;
};

// Rings joined by quads; optional fans to a pole (or flat centre) before the first and after
// the last ring. Counter-clockwise seen from outside (from the axis when `inward`).
struct Pole {
  bool present = false;
  Vec3 point{};
  Vec3 normal{};
};

void emit_rings(MeshData& mesh, const std::vector<Ring>& rings, int segments, const Pole& first,
                const Pole& last, bool inward) {
  const float flip = inward ? -1.0f : 1.0f;
  const std::uint16_t base = vertex_count(mesh);
  for (const Ring& ring : rings) {
    for (int k = 0; k < segments; ++k) {
      const double angle = 2.0 * std::numbers::pi * k / segments;
      const Vec3 radial = add(scaled(ring.u, static_cast<float>(std::cos(angle))),
                              scaled(ring.v, static_cast<float>(std::sin(angle))));
      push_vertex(mesh, add(ring.centre, scaled(radial, ring.radius)),
                  scaled(normalised(add(scaled(radial, ring.nr), scaled(ring.t, ring.nt))), flip));
    }
  }
  vertex_count(mesh);  // range check
  auto index = [&](std::size_t ring, int k) {
    return static_cast<std::uint16_t>(base + ring * static_cast<std::size_t>(segments) +
                                      static_cast<std::size_t>(k % segments));
  };
  auto triangle = [&](std::uint16_t a, std::uint16_t b, std::uint16_t c) {
    if (inward) {
      mesh.indices.insert(mesh.indices.end(), {a, c, b});
    } else {
      mesh.indices.insert(mesh.indices.end(), {a, b, c});
    }
  };
  for (std::size_t i = 0; i + 1 < rings.size(); ++i) {
    for (int k = 0; k < segments; ++k) {
      triangle(index(i, k), index(i, k + 1), index(i + 1, k + 1));
      triangle(index(i, k), index(i + 1, k + 1), index(i + 1, k));
    }
  }
  for (const bool at_start : {true, false}) {
    const Pole& pole = at_start ? first : last;
    if (!pole.present) continue;
    const std::size_t ring = at_start ? 0 : rings.size() - 1;
    const std::uint16_t centre = vertex_count(mesh);
    push_vertex(mesh, pole.point, scaled(pole.normal, flip));
    for (int k = 0; k < segments; ++k) {
      if (at_start) {
        triangle(centre, index(ring, k + 1), index(ring, k));
      } else {
        triangle(centre, index(ring, k), index(ring, k + 1));
      }
    }
  }
}

// A flat disc closing a tube end: a copy of the ring with the end's normal, and a centre.
void emit_flat_cap(MeshData& mesh, const Ring& ring, int segments, bool at_start, bool inward) {
  Ring flat = ring;
  flat.nr = 0.0f;
  flat.nt = at_start ? -1.0f : 1.0f;
  const Pole centre{true, ring.centre, scaled(ring.t, flat.nt)};
  emit_rings(mesh, {flat}, segments, at_start ? centre : Pole{}, at_start ? Pole{} : centre,
             inward);
}

constexpr int kHemisphereRings = 4;

}  // namespace

void weight_vertices(MeshData& mesh, std::size_t first_vertex, std::uint16_t joint) {
  for (std::size_t v = first_vertex; v < mesh.vertex_count(); ++v) {
    mesh.joints.insert(mesh.joints.end(), {joint, 0, 0, 0});
    mesh.weights.insert(mesh.weights.end(), {1.0f, 0.0f, 0.0f, 0.0f});
  }
}

void transform_vertices(MeshData& mesh, std::size_t first_vertex, const Mat4& matrix) {
  for (std::size_t v = first_vertex; v < mesh.vertex_count(); ++v) {
    float* p = &mesh.positions[3 * v];
    float* n = &mesh.normals[3 * v];
    const DVec3 point{p[0], p[1], p[2]};
    const DVec3 normal{n[0], n[1], n[2]};
    for (std::size_t r = 0; r < 3; ++r) {
      p[r] = static_cast<float>(matrix[r] * point[0] + matrix[4 + r] * point[1] +
                                matrix[8 + r] * point[2] + matrix[12 + r]);
      n[r] = static_cast<float>(matrix[r] * normal[0] + matrix[4 + r] * normal[1] +
                                matrix[8 + r] * normal[2]);
    }
    const Vec3 unit = normalised({n[0], n[1], n[2]});
    std::copy(unit.begin(), unit.end(), n);
  }
}

void add_tube(MeshData& mesh, const Tube& tube) {
  const std::size_t count = tube.centres.size();
  if (count < 2 || tube.radii.size() != count || tube.segments < 3) {
    throw std::invalid_argument("add_tube: need >= 2 centres, one radius each");  // a bug
  }
  std::vector<Ring> body(count);
  std::vector<float> arc(count, 0.0f);
  for (std::size_t i = 1; i < count; ++i) {
    const Vec3 d = sub(tube.centres[i], tube.centres[i - 1]);
    arc[i] = arc[i - 1] + std::sqrt(dot(d, d));
  }
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t lo = i == 0 ? 0 : i - 1;
    const std::size_t hi = i + 1 == count ? i : i + 1;
    Ring& ring = body[i];
    ring.centre = tube.centres[i];
    ring.radius = tube.radii[i];
    ring.t = normalised(sub(tube.centres[hi], tube.centres[lo]));
    if (i == 0) {
      const Vec3 t = ring.t;
      const Vec3 helper = std::abs(t[1]) < 0.9f ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
      ring.u = normalised(cross(helper, t));
    } else {  // parallel transport: the previous u without its component along t
      const Vec3 previous = body[i - 1].u;
      ring.u = normalised(sub(previous, scaled(ring.t, dot(previous, ring.t))));
    }
    ring.v = cross(ring.t, ring.u);
    const float slope = (tube.radii[hi] - tube.radii[lo]) / std::max(arc[hi] - arc[lo], 1e-9f);
    const float norm = 1.0f / std::sqrt(1.0f + slope * slope);
    ring.nr = norm;
    ring.nt = -slope * norm;
  }
  std::vector<Ring> rings;
  Pole first;
  Pole last;
  auto hemisphere = [&](const Ring& end_ring, float sign, bool reverse) {
    std::vector<Ring> cap;
    for (int j = 1; j < kHemisphereRings; ++j) {
      const double psi = std::numbers::pi / 2 * j / kHemisphereRings;
      Ring ring = end_ring;
      ring.centre = add(end_ring.centre, scaled(end_ring.t, sign * end_ring.radius *
                                                                static_cast<float>(std::sin(psi))));
      ring.radius = end_ring.radius * static_cast<float>(std::cos(psi));
      ring.nr = static_cast<float>(std::cos(psi));
      ring.nt = sign * static_cast<float>(std::sin(psi));
      cap.push_back(ring);
    }
    if (reverse) std::reverse(cap.begin(), cap.end());
    return cap;
  };
  if (tube.start == Tube::End::rounded) {
    rings = hemisphere(body.front(), -1.0f, true);
    first = {true, add(body.front().centre, scaled(body.front().t, -body.front().radius)),
             scaled(body.front().t, -1.0f)};
  }
  rings.insert(rings.end(), body.begin(), body.end());
  if (tube.end == Tube::End::rounded) {
    const std::vector<Ring> cap = hemisphere(body.back(), 1.0f, false);
    rings.insert(rings.end(), cap.begin(), cap.end());
    last = {true, add(body.back().centre, scaled(body.back().t, body.back().radius)),
            body.back().t};
  }
  emit_rings(mesh, rings, tube.segments, first, last, tube.inward);
  if (tube.start == Tube::End::flat)
    emit_flat_cap(mesh, body.front(), tube.segments, true, tube.inward);
  if (tube.end == Tube::End::flat)
    emit_flat_cap(mesh, body.back(), tube.segments, false, tube.inward);
}

void add_capsule(MeshData& mesh, Vec3 a, Vec3 b, float ra, float rb, int segments) {
  Tube tube;
  tube.centres = {a, add(a, scaled(sub(b, a), 0.5f)), b};
  tube.radii = {ra, 0.5f * (ra + rb), rb};
  tube.segments = segments;
  tube.start = Tube::End::rounded;
  tube.end = Tube::End::rounded;
  add_tube(mesh, tube);
}

void add_ellipsoid(MeshData& mesh, Vec3 centre, Vec3 radii, int segments) {
  const std::size_t first = mesh.vertex_count();
  const int latitudes = std::max(4, segments / 2);
  std::vector<Ring> rings;
  for (int j = 1; j < latitudes; ++j) {
    const double phi = std::numbers::pi * j / latitudes;  // from the -Y pole
    Ring ring;
    ring.t = {0, 1, 0};
    ring.u = {1, 0, 0};
    ring.v = {0, 0, -1};
    ring.centre = {0, -static_cast<float>(std::cos(phi)), 0};
    ring.radius = static_cast<float>(std::sin(phi));
    ring.nr = ring.radius;
    ring.nt = -static_cast<float>(std::cos(phi));
    rings.push_back(ring);
  }
  emit_rings(mesh, rings, segments, {true, {0, -1, 0}, {0, -1, 0}}, {true, {0, 1, 0}, {0, 1, 0}},
             false);
  for (std::size_t v = first; v < mesh.vertex_count(); ++v) {
    for (std::size_t a = 0; a < 3; ++a) {
      mesh.positions[3 * v + a] = centre[a] + radii[a] * mesh.positions[3 * v + a];
      mesh.normals[3 * v + a] /= radii[a];
    }
    const Vec3 unit =
        normalised({mesh.normals[3 * v], mesh.normals[3 * v + 1], mesh.normals[3 * v + 2]});
    std::copy(unit.begin(), unit.end(), mesh.normals.begin() + static_cast<std::ptrdiff_t>(3 * v));
  }
}

void add_sphere(MeshData& mesh, Vec3 centre, float radius, int segments) {
  add_ellipsoid(mesh, centre, {radius, radius, radius}, segments);
}

std::vector<Vec3> arc_points(Vec3 centre, Vec3 from, Vec3 axis, double radians, int steps) {
  std::vector<Vec3> points;
  const Vec3 r = sub(from, centre);
  for (int i = 0; i <= steps; ++i) {
    const double angle = radians * i / steps;
    const float c = static_cast<float>(std::cos(angle));
    const float s = static_cast<float>(std::sin(angle));
    // Rodrigues: r cos + (axis x r) sin + axis (axis . r)(1 - cos).
    const Vec3 rotated =
        add(add(scaled(r, c), scaled(cross(axis, r), s)), scaled(axis, dot(axis, r) * (1.0f - c)));
    points.push_back(add(centre, rotated));
  }
  return points;
}

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

Quat rotation_about(DVec3 axis, double radians) {
  const double s = std::sin(radians / 2.0);
  return {axis[0] * s, axis[1] * s, axis[2] * s, std::cos(radians / 2.0)};
}

Quat quat_multiply(const Quat& a, const Quat& b) {
  return {a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1],
          a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
          a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3],
          a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2]};
}

Mat4 compose(DVec3 translation, const Quat& rotation, DVec3 scale) {
  const auto [x, y, z, w] = rotation;
  const std::array<double, 9> r{
      1 - 2 * (y * y + z * z), 2 * (x * y + z * w),     2 * (x * z - y * w),
      2 * (x * y - z * w),     1 - 2 * (x * x + z * z), 2 * (y * z + x * w),
      2 * (x * z + y * w),     2 * (y * z - x * w),     1 - 2 * (x * x + y * y)};
  Mat4 m{};
  for (std::size_t c = 0; c < 3; ++c) {
    for (std::size_t row = 0; row < 3; ++row) m[4 * c + row] = r[3 * c + row] * scale[c];
  }
  m[12] = translation[0];
  m[13] = translation[1];
  m[14] = translation[2];
  m[15] = 1.0;
  return m;
}

Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 m{};
  for (std::size_t c = 0; c < 4; ++c) {
    for (std::size_t r = 0; r < 4; ++r) {
      double sum = 0.0;
      for (std::size_t k = 0; k < 4; ++k) sum += a[4 * k + r] * b[4 * c + k];
      m[4 * c + r] = sum;
    }
  }
  return m;
}

Mat4 affine_inverse(const Mat4& m) {
  auto at = [&](std::size_t r, std::size_t c) { return m[4 * c + r]; };
  const double det = at(0, 0) * (at(1, 1) * at(2, 2) - at(1, 2) * at(2, 1)) -
                     at(0, 1) * (at(1, 0) * at(2, 2) - at(1, 2) * at(2, 0)) +
                     at(0, 2) * (at(1, 0) * at(2, 1) - at(1, 1) * at(2, 0));
  Mat4 inv{};
  for (std::size_t r = 0; r < 3; ++r) {
    for (std::size_t c = 0; c < 3; ++c) {
      // inverse(r, c) = cofactor(c, r) / det
      const std::size_t r0 = (c + 1) % 3, r1 = (c + 2) % 3, c0 = (r + 1) % 3, c1 = (r + 2) % 3;
      inv[4 * c + r] = (at(r0, c0) * at(r1, c1) - at(r0, c1) * at(r1, c0)) / det;
    }
  }
  for (std::size_t r = 0; r < 3; ++r) {
    inv[12 + r] = -(inv[r] * m[12] + inv[4 + r] * m[13] + inv[8 + r] * m[14]);
  }
  inv[15] = 1.0;
  return inv;
}

DVec3 transform_point(const Mat4& m, DVec3 p) {
  return {m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12],
          m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13],
          m[2] * p[0] + m[6] * p[1] + m[10] * p[2] + m[14]};
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

int ModelBuilder::add_vec3_accessor(const std::vector<float>& values, bool with_bounds) {
  const int accessor =
      add_accessor(values.data(), values.size() * sizeof(float), TINYGLTF_TARGET_ARRAY_BUFFER,
                   TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, values.size() / 3);
  if (with_bounds) {
    std::vector<double> min(3, std::numeric_limits<double>::infinity());
    std::vector<double> max(3, -std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < values.size(); ++i) {
      min[i % 3] = std::min(min[i % 3], static_cast<double>(values[i]));
      max[i % 3] = std::max(max[i % 3], static_cast<double>(values[i]));
    }
    model_.accessors[static_cast<std::size_t>(accessor)].minValues = min;
    model_.accessors[static_cast<std::size_t>(accessor)].maxValues = max;
  }
  return accessor;
}

int ModelBuilder::add_mesh(const std::string& name, const MeshData& data, int material) {
  const std::size_t vertices = data.vertex_count();
  if (data.normals.size() != data.positions.size() ||
      (!data.joints.empty() &&
       (data.joints.size() != 4 * vertices || data.weights.size() != 4 * vertices))) {
    throw std::invalid_argument("add_mesh: attribute sizes differ: " + name);  // a generator bug
  }
  const int position = add_vec3_accessor(data.positions, true);
  const int normal = add_vec3_accessor(data.normals, false);
  int joints = -1;
  int weights = -1;
  if (!data.joints.empty()) {
    joints = add_accessor(data.joints.data(), data.joints.size() * sizeof(std::uint16_t),
                          TINYGLTF_TARGET_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                          TINYGLTF_TYPE_VEC4, vertices);
    weights = add_accessor(data.weights.data(), data.weights.size() * sizeof(float),
                           TINYGLTF_TARGET_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_FLOAT,
                           TINYGLTF_TYPE_VEC4, vertices);
  }
  std::vector<std::map<std::string, int>> targets;
  tinygltf::Value::Array target_names;
  for (const MorphTarget& target : data.targets) {
    if (target.positions.size() != data.positions.size() ||
        target.normals.size() != data.normals.size()) {
      throw std::invalid_argument("add_mesh: morph target size differs: " + target.name);
    }
    targets.push_back({{"POSITION", add_vec3_accessor(target.positions, true)},
                       {"NORMAL", add_vec3_accessor(target.normals, false)}});
    target_names.emplace_back(target.name);
  }
  const int indices =
      add_accessor(data.indices.data(), data.indices.size() * sizeof(std::uint16_t),
                   TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                   TINYGLTF_TYPE_SCALAR, data.indices.size());

  tinygltf::Primitive primitive;
  primitive.attributes["POSITION"] = position;
  primitive.attributes["NORMAL"] = normal;
  if (joints >= 0) {
    primitive.attributes["JOINTS_0"] = joints;
    primitive.attributes["WEIGHTS_0"] = weights;
  }
  primitive.targets = std::move(targets);
  primitive.indices = indices;
  primitive.material = material;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  tinygltf::Mesh mesh;
  mesh.name = name;
  if (!data.targets.empty()) {
    mesh.weights.assign(data.targets.size(), 0.0);
    tinygltf::Value::Object extras;
    extras["targetNames"] = tinygltf::Value(std::move(target_names));
    mesh.extras = tinygltf::Value(std::move(extras));
  }
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
  parent_.push_back(-1);
  return static_cast<int>(model_.nodes.size()) - 1;
}

void ModelBuilder::add_child(int parent, int child) {
  model_.nodes[static_cast<std::size_t>(parent)].children.push_back(child);
  parent_[static_cast<std::size_t>(child)] = parent;
}

void ModelBuilder::set_scale(int node, DVec3 scale) {
  model_.nodes[static_cast<std::size_t>(node)].scale = {scale[0], scale[1], scale[2]};
}

void ModelBuilder::set_extras(int node, tinygltf::Value extras) {
  model_.nodes[static_cast<std::size_t>(node)].extras = std::move(extras);
}

Mat4 ModelBuilder::world_matrix(int node) const {
  Mat4 world = compose({0, 0, 0}, {0, 0, 0, 1});
  for (int n = node; n >= 0; n = parent_[static_cast<std::size_t>(n)]) {
    const tinygltf::Node& at = model_.nodes[static_cast<std::size_t>(n)];
    const DVec3 t = at.translation.empty()
                        ? DVec3{0, 0, 0}
                        : DVec3{at.translation[0], at.translation[1], at.translation[2]};
    const Quat r = at.rotation.empty()
                       ? Quat{0, 0, 0, 1}
                       : Quat{at.rotation[0], at.rotation[1], at.rotation[2], at.rotation[3]};
    const DVec3 s =
        at.scale.empty() ? DVec3{1, 1, 1} : DVec3{at.scale[0], at.scale[1], at.scale[2]};
    world = multiply(compose(t, r, s), world);
  }
  return world;
}

int ModelBuilder::add_skin(const std::string& name, const std::vector<int>& joints,
                           int skeleton_root) {
  std::vector<float> matrices;
  for (const int joint : joints) {
    const Mat4 inverse = affine_inverse(world_matrix(joint));
    for (const double value : inverse) matrices.push_back(static_cast<float>(value));
  }
  tinygltf::Skin skin;
  skin.name = name;
  skin.joints = joints;
  skin.skeleton = skeleton_root;
  skin.inverseBindMatrices =
      add_accessor(matrices.data(), matrices.size() * sizeof(float), 0,
                   TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_MAT4, joints.size());
  model_.skins.push_back(std::move(skin));
  return static_cast<int>(model_.skins.size()) - 1;
}

void ModelBuilder::set_skin(int node, int skin) {
  model_.nodes[static_cast<std::size_t>(node)].skin = skin;
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
