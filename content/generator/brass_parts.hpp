// SPDX-License-Identifier: MIT
#pragma once
// Parts the generated brass instruments share (brass_assets.cpp, upright_brass.cpp): pipes
// through points, U-bends, bells, mouthpieces, millimetre helpers. Lengths in millimetres unless
// a name says otherwise; meshes are in metres.

#include <tiny_gltf.h>

#include <vector>

#include <tutti/generator/gltf_builder.hpp>

namespace tutti::content_generator {

Vec3 mm(double x, double y, double z);

// A constant-radius pipe through `points` (metres, as mm() makes them), open ends by default.
void add_pipe(MeshData& mesh, const std::vector<Vec3>& points, double radius_mm, int segments = 12,
              Tube::End ends = Tube::End::open);

// Appends the points of `more` to `path`, skipping a first point equal to the path's last.
void extend(std::vector<Vec3>& path, const std::vector<Vec3>& more);

// A U-bend (half circle) from `from` to `to`, bulging along `bulge` (unit).
std::vector<Vec3> u_bend(Vec3 from, Vec3 to, Vec3 bulge, int steps = 10);

// A bell along -Z from `throat_z` to the rim at `rim_z`, centred on (x, y): outer and inner
// surfaces flaring like 1 / distance-from-rim, plus a rolled rim bead.
void add_bell(MeshData& mesh, double x, double y, double throat_z, double rim_z,
              double throat_radius_mm, double rim_radius_mm);

// A mouthpiece along -Z from the rim at z = 0: rim, cup, throat, shank.
MeshData mouthpiece_mesh(double length_mm, double rim_diameter_mm, double shank_radius_mm);

// Node extras {key: value}.
tinygltf::Value travel_extras(const char* key, double value);

// Rotation of `degrees` about a unit axis, as a glTF quaternion.
Quat about(DVec3 axis, double degrees);

}  // namespace tutti::content_generator
