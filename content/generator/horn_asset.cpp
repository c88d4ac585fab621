// SPDX-License-Identifier: MIT
#include <tutti/generator/horn_asset.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include <tutti/generator/brass_parts.hpp>
#include <tutti/generator/gltf_builder.hpp>

namespace tutti::content_generator {
namespace {

DVec3 unit(DVec3 a) { return scaled(a, 1.0 / std::sqrt(dot(a, a))); }
Vec3 at_mm(DVec3 p) { return mm(p[0], p[1], p[2]); }

// The rotation whose columns are the orthonormal x, y, z, as a glTF quaternion.
Quat from_basis(DVec3 x, DVec3 y, DVec3 z) {
  const double trace = x[0] + y[1] + z[2];
  Quat q{};
  if (trace > 0.0) {
    const double s = 0.5 / std::sqrt(trace + 1.0);
    q = {(y[2] - z[1]) * s, (z[0] - x[2]) * s, (x[1] - y[0]) * s, 0.25 / s};
  } else if (x[0] > y[1] && x[0] > z[2]) {
    const double s = 2.0 * std::sqrt(1.0 + x[0] - y[1] - z[2]);
    q = {0.25 * s, (y[0] + x[1]) / s, (z[0] + x[2]) / s, (y[2] - z[1]) / s};
  } else if (y[1] > z[2]) {
    const double s = 2.0 * std::sqrt(1.0 + y[1] - x[0] - z[2]);
    q = {(y[0] + x[1]) / s, 0.25 * s, (z[1] + y[2]) / s, (z[0] - x[2]) / s};
  } else {
    const double s = 2.0 * std::sqrt(1.0 + z[2] - x[0] - y[1]);
    q = {(z[0] + x[2]) / s, (z[1] + y[2]) / s, 0.25 * s, (x[1] - y[0]) / s};
  }
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  return {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
}

// The rotation taking -Z (the direction add_bell builds along) onto the unit `to`.
Quat from_minus_z(DVec3 to) {
  const DVec3 from{0, 0, -1};
  const DVec3 axis = cross(from, to);
  const double s = std::sqrt(dot(axis, axis));
  if (s < 1e-9) return dot(from, to) > 0 ? Quat{0, 0, 0, 1} : Quat{1, 0, 0, 0};
  return rotation_about(scaled(axis, 1.0 / s), std::atan2(s, dot(from, to)));
}

}  // namespace

tinygltf::Model build_horn(const HornDimensions& dims) {
  ModelBuilder builder;
  const int brass = builder.add_material({"brass_lacquer", {0.90, 0.68, 0.32, 1.0}, 1.0, 0.3});
  const int silver = builder.add_material({"silver_plate", {0.93, 0.92, 0.89, 1.0}, 1.0, 0.2});
  const int nickel = builder.add_material({"nickel_silver", {0.80, 0.80, 0.78, 1.0}, 1.0, 0.25});

  const double bore = dims.bore_mm / 2;
  // The last coil turn widens into the bell's throat.
  const double throat_r = std::max(dims.bell_throat_diameter_mm / 2, bore);
  const double casing_r = dims.rotor_diameter_mm / 2;
  // The valve cluster: four rotor casings with vertical axes in a row from the player forward,
  // on their left; the levers' pads further left, the fingers' row.
  const DVec3 cluster{-dims.valves_left_mm, -dims.valves_drop_mm, -dims.valves_forward_mm};
  std::array<DVec3, 4> casing{};
  for (std::size_t i = 0; i < 4; ++i) {
    casing[i] = add(cluster, {0, 0, -static_cast<double>(i) * dims.rotor_pitch_mm});
  }
  const double casing_height = 0.9 * dims.rotor_diameter_mm;
  // The coils: a vertical plane facing the player, tilted back at the top; centre ahead, below.
  const DVec3 coil_centre{dims.coil_right_mm, -dims.coil_drop_mm, -dims.coil_forward_mm};
  const double tilt = 25.0 * kPi / 180.0;
  const DVec3 u{1, 0, 0};
  const DVec3 v{0, std::cos(tilt), std::sin(tilt)};  // up the plane, leaning toward the player
  const DVec3 n = cross(u, v);

  MeshData body;
  // Leadpipe: mouthpiece receiver forward and down to the first rotor.
  Tube leadpipe;
  leadpipe.centres = {mm(0, 0, -40), mm(-0.3 * dims.valves_left_mm, -0.4 * dims.valves_drop_mm,
                                        -0.6 * dims.valves_forward_mm),
                      at_mm(add(casing[0], {casing_r + 12, 0.2 * casing_height, 20}))};
  leadpipe.radii = {m(bore * 0.6), m(bore * 0.75), m(bore * 0.9)};
  leadpipe.start = Tube::End::flat;
  leadpipe.end = Tube::End::open;
  add_tube(body, leadpipe);
  // Rotor casings and the valve loops behind them.
  for (std::size_t i = 0; i < 4; ++i) {
    add_cylinder(body, at_mm(add(casing[i], {0, -casing_height / 2, 0})), m(casing_r),
                 m(casing_height), 20);
    const double loop = 60.0 + 20.0 * static_cast<double>(i);
    std::vector<Vec3> valve_loop{at_mm(add(casing[i], {casing_r, -0.25 * casing_height, 0})),
                                 at_mm(add(casing[i], {casing_r + loop, -0.25 * casing_height, 0}))};
    extend(valve_loop,
           u_bend(at_mm(add(casing[i], {casing_r + loop, -0.25 * casing_height, 0})),
                  at_mm(add(casing[i], {casing_r + loop, -0.25 * casing_height - 22, 0})),
                  {1, 0, 0}, 8));
    extend(valve_loop, {at_mm(add(casing[i], {casing_r, -0.25 * casing_height - 22, 0}))});
    add_pipe(body, valve_loop, 0.75 * bore, 10);
  }
  // The coils: turns of tube spiralling out round the centre, from the valves to the bell.
  const double turns = 2.5;
  std::vector<Vec3> coil;
  constexpr int kCoilSteps = 90;
  DVec3 last{};
  for (int k = 0; k <= kCoilSteps; ++k) {
    const double s = static_cast<double>(k) / kCoilSteps;
    const double angle = kPi * 0.75 - 2.0 * kPi * turns * s;  // from the upper left, clockwise
    const double radius = dims.coil_radius_mm * (0.78 + 0.22 * s);
    last = add(coil_centre, add(add(scaled(u, radius * std::cos(angle)),
                                    scaled(v, radius * std::sin(angle))),
                                scaled(n, 9.0 * (s - 0.5))));
    coil.push_back(at_mm(last));
  }
  Tube coil_tube;
  coil_tube.centres = coil;
  for (std::size_t k = 0; k < coil.size(); ++k) {
    const double s = static_cast<double>(k) / static_cast<double>(coil.size() - 1);
    coil_tube.radii.push_back(m(0.9 * bore + (throat_r - 0.9 * bore) * s * s));
  }
  coil_tube.segments = 14;
  coil_tube.start = Tube::End::open;
  coil_tube.end = Tube::End::open;
  add_tube(body, coil_tube);
  // The last rotor into the coils.
  add_pipe(body, {at_mm(add(casing[3], {casing_r - 2, -0.3 * casing_height, -4})),
                  coil.front()},
           0.9 * bore, 12);
  // The bell: from the coil's end, flaring back toward the player's right side and down.
  const DVec3 bell_axis = unit({dims.bell_back_x, -dims.bell_back_y, 1.0});
  const double rim_r = dims.bell_diameter_mm / 2;
  const std::size_t bell_first = body.vertex_count();
  add_bell(body, 0, 0, 0, -dims.bell_flare_mm, throat_r, rim_r);
  transform_vertices(body, bell_first,
                     compose({last[0] / 1000, last[1] / 1000, last[2] / 1000},
                             from_minus_z(bell_axis)));
  // Braces: the valve cluster to the coils.
  add_pipe(body, {at_mm(add(casing[1], {casing_r, 0.3 * casing_height, 0})),
                  at_mm(add(coil_centre, scaled(v, dims.coil_radius_mm * 0.8)))},
           2.0, 8);

  const int root = builder.add_node("horn");
  builder.add_root(root);
  builder.add_child(root, builder.add_node("body", builder.add_mesh("horn_body", body, brass)));
  builder.add_child(
      root, builder.add_node("mouthpiece",
                             builder.add_mesh("horn_mouthpiece",
                                              mouthpiece_mesh(dims.mouthpiece_length_mm,
                                                              dims.mouthpiece_rim_diameter_mm,
                                                              bore * 0.7),
                                              silver)));
  // Rotor caps: a disc with a bar across it, turning about the casing's axis.
  MeshData cap;
  add_cylinder(cap, mm(0, 0, 0), m(casing_r + 1.0), m(4.0), 20);
  add_box(cap, mm(-casing_r * 0.9, 4.0, -2.5), mm(casing_r * 0.9, 7.0, 2.5));
  const int cap_mesh = builder.add_mesh("horn_rotor_cap", cap, nickel);
  for (std::size_t i = 0; i < 4; ++i) {
    const DVec3 top = add(casing[i], {0, casing_height / 2, 0});
    builder.add_child(root, builder.add_node("rotor_" + std::to_string(i + 1), cap_mesh,
                                             scaled(top, 1.0 / 1000)));
  }
  // Levers: a pad (its top at the node's origin, pressed along -Y) on an arm back to its rotor.
  const double pad_y = dims.lever_rise_mm;
  for (std::size_t i = 0; i < 3; ++i) {
    MeshData lever;
    add_box(lever, mm(-11, -3, -8), mm(11, 0, 8));  // the finger's pad
    const double arm = dims.lever_left_mm - 11.0;
    add_box(lever, mm(11, -5, -2.5), mm(11 + arm, -2, 2.5));
    const int mesh = builder.add_mesh("horn_lever_" + std::to_string(i + 1), lever, nickel);
    const DVec3 pad = add(casing[i], {-dims.lever_left_mm, casing_height / 2 + pad_y, 0});
    const int node = builder.add_node("valve_" + std::to_string(i + 1), mesh,
                                      scaled(pad, 1.0 / 1000));
    builder.set_extras(node, travel_extras("travel_mm", dims.lever_travel_mm));
    builder.add_child(root, node);
  }
  // The thumb's trigger (valve 4, the B♭ side): a paddle on the player's side of the cluster,
  // pressed toward the instrument (+X): the node's -Y points that way.
  {
    MeshData trigger;
    add_box(trigger, mm(-3, -12, -10), mm(0, 12, 10));
    const int mesh = builder.add_mesh("horn_trigger", trigger, nickel);
    const DVec3 at = add(casing[0], {-dims.lever_left_mm + 8, -0.3 * casing_height, 28});
    const int node = builder.add_node("valve_4", mesh, scaled(at, 1.0 / 1000),
                                      about({0, 0, 1}, 90));
    builder.set_extras(node, travel_extras("travel_mm", dims.lever_travel_mm));
    builder.add_child(root, node);
  }
  // The little finger's hook, past the third lever.
  {
    MeshData hook;
    const DVec3 base = add(casing[3], {-dims.lever_left_mm, casing_height / 2, -6});
    std::vector<Vec3> path{at_mm(add(base, {20, 0, 0})), at_mm(add(base, {20, 10, 0}))};
    extend(path, u_bend(at_mm(add(base, {20, 10, 0})), at_mm(add(base, {0, 10, 0})), {0, 1, 0}, 8));
    add_pipe(hook, path, 1.6, 8);
    builder.add_child(root, builder.add_node("hook_mesh", builder.add_mesh("horn_hook", hook, brass)));
    builder.add_child(root, builder.add_node("hook", -1, scaled(add(base, {10, 20, 0}), 1.0 / 1000)));
  }
  // The right palm inside the bell: fingers toward the throat along its far wall, the palm
  // facing the player's body (hand frame of README.md: fingers -Z, palm normal -Y).
  {
    const DVec3 fingers = scaled(bell_axis, -1.0);
    const DVec3 toward_body = unit(add(DVec3{-1, 0.3, 0}, scaled(bell_axis, bell_axis[0] - 0.3 * bell_axis[1])));
    const DVec3 palm_normal = unit(add(toward_body, scaled(fingers, -dot(toward_body, fingers))));
    const DVec3 y = scaled(palm_normal, -1.0);
    const DVec3 z = scaled(fingers, -1.0);
    const DVec3 x = cross(y, z);
    const double depth = 0.88 * dims.bell_flare_mm;
    // The bell's radius there (add_bell's flare: r = B / (d + d0), d from the rim).
    const double d = dims.bell_flare_mm - depth;
    const double d0 = dims.bell_flare_mm / (rim_r / throat_r - 1.0);
    const double radius = rim_r * d0 / (d + d0);
    const DVec3 palm = add(add(last, scaled(bell_axis, depth)), scaled(palm_normal, -(radius - 40)));
    builder.add_child(root, builder.add_node("grip_right", -1, scaled(palm, 1.0 / 1000),
                                             from_basis(x, y, z)));
    // The rim's centre, its -Z into the bell, with the flare's profile (add_bell: the radius
    // rim · d0 / (d + d0) at d behind the rim): check-pose measures the hand in the bell by it.
    const int rim = builder.add_node("bell_rim", -1,
                                     scaled(add(last, scaled(bell_axis, dims.bell_flare_mm)), 1.0 / 1000),
                                     from_minus_z(scaled(bell_axis, -1.0)));
    tinygltf::Value::Object profile;
    profile["rim_radius_mm"] = tinygltf::Value(rim_r);
    profile["flare_d0_mm"] = tinygltf::Value(d0);
    profile["flare_mm"] = tinygltf::Value(dims.bell_flare_mm);
    builder.set_extras(rim, tinygltf::Value(std::move(profile)));
    builder.add_child(root, rim);
  }
  return builder.finish();
}

}  // namespace tutti::content_generator
