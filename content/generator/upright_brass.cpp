// SPDX-License-Identifier: MIT
#include <tutti/generator/upright_brass.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include <tutti/generator/brass_parts.hpp>
#include <tutti/generator/gltf_builder.hpp>

namespace tutti::content_generator {

tinygltf::Model build_upright(const std::string& name, const UprightDimensions& dims) {
  ModelBuilder builder;
  const int brass = builder.add_material({"brass_lacquer", {0.90, 0.68, 0.32, 1.0}, 1.0, 0.3});
  const int silver = builder.add_material({"silver_plate", {0.93, 0.92, 0.89, 1.0}, 1.0, 0.2});
  const int pearl = builder.add_material({"button_pearl", {0.88, 0.85, 0.78, 1.0}, 0.0, 0.25});

  const double bore = dims.bore_mm / 2;
  const double casing_r = dims.valve_casing_diameter_mm / 2;
  const double vx = dims.valves_right_mm;
  const double button_top = -dims.button_drop_mm;
  const double casing_top = button_top - 2.2 * dims.piston_travel_mm;
  const double casing_bottom = casing_top - 4.5 * dims.valve_casing_diameter_mm;
  std::array<double, 4> vz{};
  for (std::size_t i = 0; i < 4; ++i) {
    vz[i] = -(dims.valves_forward_mm + static_cast<double>(i) * dims.valve_pitch_mm);
  }
  // The bell branch (the player's left) and the small branch under the valves meet in the
  // bottom bow; the bell flares up from the branch, tilted toward the audience (-Z).
  const double bx = -dims.bell_left_mm;
  const double bz = -dims.bell_forward_mm;
  const double sx = vx - casing_r;
  const double bow_r = (sx - bx) / 2;
  const double bow_pipe_r = 2.6 * bore;
  // The lowest point is the bottom bow's underside, the highest the tilted rim's back edge.
  const double bottom_y = dims.top_above_mm - dims.height_mm + bow_r + bow_pipe_r;
  const double tilt = dims.bell_tilt_deg * std::numbers::pi / 180.0;
  const double flare = 0.32 * dims.height_mm;
  const double rim_r = dims.bell_diameter_mm / 2;
  const double throat_r = std::max(3.0 * bore, 0.34 * rim_r);
  const double throat_y = dims.top_above_mm - rim_r * std::sin(tilt) - flare * std::cos(tilt);
  const double throat_z = bz + flare * std::sin(tilt);

  MeshData body;
  // Bell branch: conical from the bottom bow to the bell's throat.
  Tube branch;
  constexpr int kBranchSteps = 8;
  for (int i = 0; i <= kBranchSteps; ++i) {
    const double u = static_cast<double>(i) / kBranchSteps;
    branch.centres.push_back(mm(bx, bottom_y + (throat_y - bottom_y) * u, bz + (throat_z - bz) * u));
    branch.radii.push_back(m(2.6 * bore + (throat_r - 2.6 * bore) * u * u));
  }
  branch.start = Tube::End::open;
  branch.end = Tube::End::open;
  add_tube(body, branch);
  const std::size_t bell_first = body.vertex_count();
  add_bell(body, 0, 0, 0, -flare, throat_r, rim_r);
  transform_vertices(body, bell_first,
                     compose({bx / 1000, throat_y / 1000, throat_z / 1000},
                             about({1, 0, 0}, 90.0 - dims.bell_tilt_deg)));
  // Bottom bow and the small branch up to the last valve.
  std::vector<Vec3> bow = u_bend(mm(sx, bottom_y, bz), mm(bx, bottom_y, bz), {0, -1, 0}, 12);
  add_pipe(body, bow, bow_pipe_r, 18);
  std::vector<Vec3> small{mm(sx, bottom_y, bz), mm(sx, casing_bottom - 40, bz),
                          mm(vx, casing_bottom - 10, vz[3])};
  add_pipe(body, small, 1.6 * bore, 14);
  // Main tuning slide: a loop on the bell branch's player side, back toward the player.
  const double loop_y = casing_bottom + 0.3 * (casing_top - casing_bottom);
  std::vector<Vec3> tuning{mm(bx, loop_y, bz), mm(bx, loop_y, bz + 0.45 * dims.bell_forward_mm)};
  extend(tuning, u_bend(mm(bx, loop_y, bz + 0.45 * dims.bell_forward_mm),
                        mm(bx, loop_y - 70, bz + 0.45 * dims.bell_forward_mm), {0, 0, 1}, 10));
  extend(tuning, {mm(bx, loop_y - 70, bz), mm(vx - casing_r, loop_y - 70, vz[1])});
  add_pipe(body, tuning, 1.1 * bore, 12);
  // Leadpipe: from the mouthpiece receiver forward and down into the first valve.
  Tube leadpipe;
  leadpipe.centres = {mm(0, 0, -40), mm(0, -0.35 * dims.button_drop_mm, -0.45 * dims.valves_forward_mm),
                      mm(0.5 * vx, casing_top - 10, vz[0] + casing_r + 30),
                      mm(vx - casing_r, casing_top - 25, vz[0])};
  leadpipe.radii = {m(bore * 0.7), m(bore * 0.8), m(bore * 0.9), m(bore)};
  leadpipe.start = Tube::End::flat;
  leadpipe.end = Tube::End::open;
  add_tube(body, leadpipe);
  // Valve casings with caps, and each valve's loop hanging below it.
  for (std::size_t i = 0; i < 4; ++i) {
    add_cylinder(body, mm(vx, casing_bottom, vz[i]), m(casing_r), m(casing_top - casing_bottom), 20);
    add_cylinder(body, mm(vx, casing_top, vz[i]), m(casing_r + 1.5), m(6.0), 20);
    add_cylinder(body, mm(vx, casing_bottom - 5.0, vz[i]), m(casing_r + 1.5), m(5.0), 20);
    const double drop = 50.0 + 25.0 * static_cast<double>(i);
    std::vector<Vec3> loop{mm(vx - 0.5 * casing_r, casing_bottom - 5, vz[i]),
                           mm(vx - 0.5 * casing_r, casing_bottom - drop, vz[i])};
    extend(loop, u_bend(mm(vx - 0.5 * casing_r, casing_bottom - drop, vz[i]),
                        mm(vx + 0.5 * casing_r + 14, casing_bottom - drop, vz[i]), {0, -1, 0}, 8));
    extend(loop, {mm(vx + 0.5 * casing_r + 14, casing_bottom + 0.2 * (casing_top - casing_bottom), vz[i]),
                  mm(vx + casing_r, casing_bottom + 0.25 * (casing_top - casing_bottom), vz[i])});
    add_pipe(body, loop, 0.8 * bore, 10);
  }
  // Stays: valve block to the bell branch, top and bottom.
  add_pipe(body, {mm(vx - casing_r, casing_top - 15, vz[2]), mm(bx + 2.6 * bore, casing_top - 15, bz)},
           2.5, 8);
  add_pipe(body, {mm(vx - casing_r, casing_bottom + 15, vz[2]), mm(bx + 2.6 * bore, casing_bottom + 15, bz)},
           2.5, 8);

  // One piston: its button (top at the node's origin), the stem, the collar.
  MeshData piston;
  const double stem = button_top - casing_top;
  add_cylinder(piston, mm(0, -5.0, 0), m(dims.button_diameter_mm / 2), m(5.0), 20);
  add_cylinder(piston, mm(0, -stem - 2.0, 0), m(3.0), m(stem - 3.0), 10);
  add_cylinder(piston, mm(0, -10.0, 0), m(5.0), m(5.0), 12);

  const int root = builder.add_node(name);
  builder.add_root(root);
  builder.add_child(root, builder.add_node("body", builder.add_mesh(name + "_body", body, brass)));
  builder.add_child(
      root, builder.add_node("mouthpiece",
                             builder.add_mesh(name + "_mouthpiece",
                                              mouthpiece_mesh(dims.mouthpiece_length_mm,
                                                              dims.mouthpiece_rim_diameter_mm,
                                                              bore * 0.85),
                                              silver)));
  const int piston_mesh = builder.add_mesh(name + "_piston", piston, pearl);
  for (std::size_t i = 0; i < 4; ++i) {
    const int valve = builder.add_node("valve_" + std::to_string(i + 1), piston_mesh,
                                       {vx / 1000, button_top / 1000, vz[i] / 1000});
    builder.set_extras(valve, travel_extras("travel_mm", dims.piston_travel_mm));
    builder.add_child(root, valve);
  }
  // Left palm on the bell branch's player side at the valves' height, facing the audience
  // (palm normal -Z), fingers round toward the player's right (+X) — hand frame of README.md.
  const double grip_y = casing_top - 30.0;
  builder.add_child(root, builder.add_node("grip_left", -1,
                                           {(bx + 10) / 1000, grip_y / 1000,
                                            (bz + 3.0 * bore + 18) / 1000},
                                           {0.5, -0.5, -0.5, 0.5}));
  // Right: palm down above and right of the buttons (a mapping's fallback: the hold puts the
  // fingertips on the buttons), and where the right thumb rests against the casings.
  builder.add_child(root, builder.add_node("grip_right", -1,
                                           {(vx + 55) / 1000, (button_top + 25) / 1000,
                                            vz[1] / 1000},
                                           about({0, 1, 0}, 90)));
  builder.add_child(root, builder.add_node("thumb_rest", -1,
                                           {(vx + casing_r + 1) / 1000, (casing_top - 35) / 1000,
                                            (vz[0] + vz[1]) / 2000},
                                           about({0, 0, 1}, -90)));
  return builder.finish();
}

}  // namespace tutti::content_generator
