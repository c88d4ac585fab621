// SPDX-License-Identifier: MIT
#include <tutti/generator/brass_parts.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tutti::content_generator {

Vec3 mm(double x, double y, double z) { return {m(x), m(y), m(z)}; }

// A constant-radius pipe through `points` (millimetres), open ends.
void add_pipe(MeshData& mesh, const std::vector<Vec3>& points, double radius_mm, int segments,
              Tube::End ends) {
  Tube tube;
  tube.centres = points;
  tube.radii.assign(points.size(), m(radius_mm));
  tube.segments = segments;
  tube.start = ends;
  tube.end = ends;
  add_tube(mesh, tube);
}

// Appends the points of `more` to `path`, skipping a first point equal to the path's last.
void extend(std::vector<Vec3>& path, const std::vector<Vec3>& more) {
  for (const Vec3& p : more) {
    if (!path.empty() && path.back() == p) continue;
    path.push_back(p);
  }
}

// A U-bend (half circle) from `from` to `to` (millimetres), bulging along `bulge` (unit).
std::vector<Vec3> u_bend(Vec3 from, Vec3 to, Vec3 bulge, int steps) {
  const Vec3 centre{(from[0] + to[0]) / 2, (from[1] + to[1]) / 2, (from[2] + to[2]) / 2};
  const Vec3 r{from[0] - centre[0], from[1] - centre[1], from[2] - centre[2]};
  // Axis = r x bulge: rotating r about it by +90 degrees gives the bulge direction.
  Vec3 axis{r[1] * bulge[2] - r[2] * bulge[1], r[2] * bulge[0] - r[0] * bulge[2],
            r[0] * bulge[1] - r[1] * bulge[0]};
  const float length = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  for (float& a : axis) a /= length;
  return arc_points(centre, from, axis, kPi, steps);
}

// A bell: outer and inner (inward) surfaces of revolution along -Z from `throat_z` to the rim at
// `rim_z` (millimetres), flaring like 1 / distance-from-rim, plus a rolled rim bead.
void add_bell(MeshData& mesh, double x, double y, double throat_z, double rim_z,
              double throat_radius_mm, double rim_radius_mm) {
  const double length = throat_z - rim_z;  // > 0
  // r(d) = B / (d + d0) with d the distance behind the rim: r(0) = rim, r(length) = throat.
  const double d0 = length / (rim_radius_mm / throat_radius_mm - 1.0);
  const double b = rim_radius_mm * d0;
  Tube outer;
  constexpr int kSteps = 24;
  for (int i = 0; i <= kSteps; ++i) {
    // Denser toward the rim, where the flare turns fast.
    const double u = static_cast<double>(i) / kSteps;
    const double d = length * (1.0 - u) * (1.0 - u);
    outer.centres.push_back(mm(x, y, rim_z + d));
    outer.radii.push_back(m(b / (d + d0)));
  }
  outer.segments = 32;
  outer.start = Tube::End::open;
  outer.end = Tube::End::open;
  add_tube(mesh, outer);
  Tube inner = outer;
  for (float& r : inner.radii) r = std::max(r - m(0.8), m(0.5));
  inner.inward = true;
  add_tube(mesh, inner);
  // The rim bead: a ring of wire around the edge.
  std::vector<Vec3> ring =
      arc_points(mm(x, y, rim_z), mm(x + rim_radius_mm, y, rim_z), {0, 0, 1}, 2 * kPi, 48);
  add_pipe(mesh, ring, 1.6, 8);
}

// A mouthpiece along -Z from the rim at z = 0: rim, cup, throat, shank (millimetres).
MeshData mouthpiece_mesh(double length_mm, double rim_diameter_mm, double shank_radius_mm) {
  MeshData mesh;
  const double rim = rim_diameter_mm / 2;
  Tube body;
  const double profile[][2] = {{0.0, rim - 1.5},
                               {1.5, rim},
                               {5.0, rim},
                               {0.2 * length_mm, rim * 0.62},
                               {0.3 * length_mm, rim * 0.42},
                               {0.45 * length_mm, shank_radius_mm * 1.25},
                               {length_mm, shank_radius_mm}};
  for (const auto& [depth, radius] : profile) {
    body.centres.push_back(mm(0, 0, -depth));
    body.radii.push_back(m(radius));
  }
  body.segments = 24;
  add_tube(mesh, body);  // flat ends: the rim face the lips meet, the shank's end
  return mesh;
}

tinygltf::Value travel_extras(const char* key, double value) {
  tinygltf::Value::Object extras;
  extras[key] = tinygltf::Value(value);
  return tinygltf::Value(std::move(extras));
}

// glTF quaternion turning the hand frame (fingers -Z, palm normal -Y) into a grip frame.
Quat about(DVec3 axis, double degrees) { return rotation_about(axis, degrees * kPi / 180.0); }

}  // namespace tutti::content_generator
