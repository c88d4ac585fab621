// SPDX-License-Identifier: MIT
#include <tutti/generator/brass_assets.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <tutti/generator/brass_parts.hpp>
#include <tutti/generator/gltf_builder.hpp>

namespace tutti::content_generator {

tinygltf::Model build_trumpet(const TrumpetDimensions& dims) {
  ModelBuilder builder;
  const int brass = builder.add_material({"brass_lacquer", {0.90, 0.68, 0.32, 1.0}, 1.0, 0.3});
  const int silver = builder.add_material({"silver_plate", {0.93, 0.92, 0.89, 1.0}, 1.0, 0.2});
  const int pearl = builder.add_material({"button_pearl", {0.88, 0.85, 0.78, 1.0}, 0.0, 0.25});

  const double bore = dims.bore_mm / 2;
  const double length = dims.overall_length_mm;
  const double casing_r = dims.valve_casing_diameter_mm / 2;
  const double valve_x = casing_r + bore + 3.5;  // the casings stand right of the leadpipe
  const double bell_x = -(bore + 6.5);           // the bell tube runs left of it
  const double bell_y = 30.0;
  const double casing_top = 15.0;
  const double casing_bottom = -70.0;
  const double button_top = 50.0;
  // Valve 1 is nearest the player; the block sits a third of the way along.
  const double valve_z[3] = {-0.31 * length, -0.31 * length - dims.valve_pitch_mm,
                             -0.31 * length - 2 * dims.valve_pitch_mm};
  const double front_z = -(length - 0.37 * length);  // where the bell flare starts
  const double crook_z = front_z + 10.0;             // main tuning slide crook

  MeshData body;
  // Leadpipe: from the mouthpiece receiver forward to the main tuning slide, then back into
  // the third valve.
  Tube leadpipe;
  leadpipe.centres = {mm(0, 0, -60), mm(0, -3, -0.4 * length), mm(0, -6, crook_z)};
  leadpipe.radii = {m(bore * 0.85), m(bore * 0.95), m(bore)};
  leadpipe.start = Tube::End::flat;
  leadpipe.end = Tube::End::open;
  add_tube(body, leadpipe);
  std::vector<Vec3> tuning = u_bend(mm(0, -6, crook_z), mm(0, -46, crook_z), {0, 0, -1});
  extend(tuning, {mm(0, -46, crook_z + 40), mm(valve_x, -46, valve_z[2])});
  add_pipe(body, tuning, bore);
  // Valve 1 to the bell bow and the bell tube above, left of the valves.
  std::vector<Vec3> bell_pipe{mm(valve_x, -30, valve_z[0]), mm(bell_x, -30, valve_z[0] + 30)};
  const double bow_z = valve_z[0] + 45;
  extend(bell_pipe, {mm(bell_x, -30, bow_z)});
  extend(bell_pipe, u_bend(mm(bell_x, -30, bow_z), mm(bell_x, bell_y, bow_z), {0, 0, 1}, 14));
  extend(bell_pipe, {mm(bell_x, bell_y, front_z)});
  add_pipe(body, bell_pipe, bore);
  const double rim_z = -length;
  add_bell(body, bell_x, bell_y, front_z, rim_z, bore, dims.bell_diameter_mm / 2);
  // Valve casings with their caps, and the valve slides under them.
  for (const double z : valve_z) {
    add_cylinder(body, mm(valve_x, casing_bottom, z), m(casing_r), m(casing_top - casing_bottom),
                 20);
    add_cylinder(body, mm(valve_x, casing_top, z), m(casing_r + 1.2), m(5.0), 20);
    add_cylinder(body, mm(valve_x, casing_bottom - 4.0, z), m(casing_r + 1.2), m(4.0), 20);
  }
  std::vector<Vec3> slide1{mm(valve_x, -58, valve_z[0]), mm(valve_x, -58, valve_z[0] + 40)};
  extend(slide1, u_bend(mm(valve_x, -58, valve_z[0] + 40), mm(valve_x, -80, valve_z[0] + 40),
                        {0, 0, 1}, 8));
  extend(slide1, {mm(valve_x, -80, valve_z[0])});
  add_pipe(body, slide1, bore * 0.9);
  std::vector<Vec3> slide2{mm(valve_x - 6, -74, valve_z[1]), mm(valve_x - 6, -92, valve_z[1])};
  extend(slide2,
         u_bend(mm(valve_x - 6, -92, valve_z[1]), mm(valve_x + 6, -92, valve_z[1]), {0, -1, 0}, 6));
  extend(slide2, {mm(valve_x + 6, -74, valve_z[1])});
  add_pipe(body, slide2, bore * 0.8);
  std::vector<Vec3> slide3{mm(valve_x, -60, valve_z[2]), mm(valve_x, -60, valve_z[2] - 55)};
  extend(slide3, u_bend(mm(valve_x, -60, valve_z[2] - 55), mm(valve_x, -84, valve_z[2] - 55),
                        {0, 0, -1}, 8));
  extend(slide3, {mm(valve_x, -84, valve_z[2])});
  add_pipe(body, slide3, bore * 0.9);
  // The little finger's hook on the leadpipe, just past the third valve.
  const double hook_z = valve_z[2] - 0.9 * dims.valve_pitch_mm;
  std::vector<Vec3> hook{mm(0, 0, hook_z + 6), mm(0, 9, hook_z + 6)};
  extend(hook, u_bend(mm(0, 9, hook_z + 6), mm(0, 9, hook_z - 6), {0, 1, 0}, 6));
  add_pipe(body, hook, 1.6, 8);
  // Braces between the leadpipe and the bell tube.
  add_pipe(body, {mm(0, 0, -0.22 * length), mm(bell_x, bell_y, -0.22 * length)}, 2.0, 8);
  add_pipe(body, {mm(0, -4, front_z + 30), mm(bell_x, bell_y, front_z + 30)}, 2.0, 8);

  // One piston: its finger button (top at the node's origin) and the stem into the casing.
  MeshData piston;
  add_cylinder(piston, mm(0, -4.0, 0), m(dims.button_diameter_mm / 2), m(4.0), 20);
  add_cylinder(piston, mm(0, -(button_top - casing_top) - 2.0, 0), m(2.5),
               m(button_top - casing_top - 2.0), 10);
  add_cylinder(piston, mm(0, -8.0, 0), m(4.0), m(4.0), 12);  // the button's collar

  const int trumpet = builder.add_node("trumpet");
  builder.add_root(trumpet);
  builder.add_child(trumpet,
                    builder.add_node("body", builder.add_mesh("trumpet_body", body, brass)));
  builder.add_child(
      trumpet, builder.add_node(
                   "mouthpiece",
                   builder.add_mesh("trumpet_mouthpiece",
                                    mouthpiece_mesh(dims.mouthpiece_length_mm,
                                                    dims.mouthpiece_rim_diameter_mm, bore * 0.82),
                                    silver)));
  const int piston_mesh = builder.add_mesh("trumpet_piston", piston, pearl);
  for (int i = 0; i < 3; ++i) {
    const int valve = builder.add_node("valve_" + std::to_string(i + 1), piston_mesh,
                                       {valve_x / 1000, button_top / 1000, valve_z[i] / 1000});
    builder.set_extras(valve, travel_extras("travel_mm", dims.piston_travel_mm));
    builder.add_child(trumpet, valve);
  }
  // Grips, in the hand frame of README.md (fingers along local -Z, palm normal local -Y). Left:
  // palm against the casings' left side, fingers wrapping forward and down, thumb up.
  // Fingers forward and 40° down round the casings toward the third slide, the wrist under
  // and behind them.
  builder.add_child(trumpet,
                    builder.add_node("grip_left", -1,
                                     {(valve_x - casing_r - 16) / 1000, -0.030, valve_z[1] / 1000},
                                     quat_multiply(about({1, 0, 0}, -40), about({0, 0, 1}, 90))));
  // Where the right thumb and little finger rest (content/instruments/holds/trumpet.json): the
  // node's -Y points into the surface. The thumb against the casings' right side between valves
  // 1 and 2; the little finger on the hook.
  builder.add_child(trumpet, builder.add_node("thumb_rest", -1,
                                              {(valve_x + casing_r + 1) / 1000, -0.030,
                                               (valve_z[0] + valve_z[1]) / 2000},
                                              about({0, 0, 1}, -90)));
  builder.add_child(trumpet, builder.add_node("hook", -1, {0.0, 0.018, hook_z / 1000}));
  // Right: palm down above and right of the buttons, fingers toward -X, index over valve 1.
  builder.add_child(trumpet, builder.add_node("grip_right", -1,
                                              {(valve_x + 55) / 1000, (button_top + 25) / 1000,
                                               valve_z[1] / 1000},
                                              about({0, 1, 0}, 90)));
  return builder.finish();
}

tinygltf::Model build_trombone(double max_extension_mm, const TromboneDimensions& dims) {
  ModelBuilder builder;
  const int brass = builder.add_material({"brass_lacquer", {0.90, 0.68, 0.32, 1.0}, 1.0, 0.3});
  const int silver = builder.add_material({"silver_plate", {0.93, 0.92, 0.89, 1.0}, 1.0, 0.2});

  const double bore = dims.bore_mm / 2;
  const double s = dims.slide_spacing_mm;
  const double receiver_z = -70.0;
  const double inner_end = receiver_z - dims.inner_slide_length_mm;
  const double brace_z = -105.0;  // the inner slide's brace, where the bell brace meets it
  const double bx = -dims.bell_offset_mm;
  const double by = -s / 2;
  const double back_y = 10.0;

  // Inner slide: two fixed tubes from the receivers forward, with their brace.
  MeshData inner;
  add_pipe(inner, {mm(0, 0, receiver_z), mm(0, 0, inner_end)}, bore, 14, Tube::End::flat);
  add_pipe(inner, {mm(0, -s, receiver_z), mm(0, -s, inner_end)}, bore, 14, Tube::End::flat);
  add_cylinder(inner, mm(0, -s, brace_z), m(4.0), m(s), 10);
  add_cylinder(inner, mm(0, -3.0, receiver_z + 10), m(bore + 3), m(6.0), 14);  // receiver
  // Outer slide (node `slide`): tubes over the inner ones, the end crook, the slide brace.
  MeshData outer;
  const double near_z = brace_z - 15.0;
  const double far_z = inner_end - 20.0;
  add_pipe(outer, {mm(0, 0, near_z), mm(0, 0, far_z)}, bore + 1.6, 14);
  add_pipe(outer, {mm(0, -s, near_z), mm(0, -s, far_z)}, bore + 1.6, 14);
  add_pipe(outer, u_bend(mm(0, 0, far_z), mm(0, -s, far_z), {0, 0, -1}, 14), bore + 1.6, 14);
  const double slide_brace_z = near_z - 70.0;
  add_cylinder(outer, mm(0, -s + 4, slide_brace_z), m(5.0), m(s - 8), 12);
  add_cylinder(outer, mm(0, -s / 2 - 25, slide_brace_z), m(8.0), m(50.0), 14);  // hand grip
  for (const double y : {0.0, -s}) {  // bumper at the end, the collar at the near end
    add_pipe(outer, {mm(0, y, near_z + 3), mm(0, y, near_z - 12)}, bore + 3.0, 14, Tube::End::flat);
  }
  // Bell section: from the lower inner tube back over the player's left shoulder to the tuning
  // bow, then forward as the bell tube to the bell.
  MeshData bell;
  std::vector<Vec3> neck{mm(0, -s, receiver_z), mm(0, -s, -20), mm(bx * 0.35, -s * 0.7, 30),
                         mm(bx * 0.85, back_y - 15, 70), mm(bx, back_y, 95)};
  const double bow_z = dims.tuning_bow_back_mm;
  extend(neck, {mm(bx, back_y, bow_z)});
  extend(neck, u_bend(mm(bx, back_y, bow_z), mm(bx, by, bow_z), {0, 0, 1}, 12));
  const double flare_z = -0.5 * dims.bell_forward_mm;
  extend(neck, {mm(bx, by, flare_z)});
  add_pipe(bell, neck, bore, 14);
  add_bell(bell, bx, by, flare_z, -dims.bell_forward_mm, bore, dims.bell_diameter_mm / 2);
  // Bell brace (the left hand's grip) to the inner slide brace, and a stay near the bow.
  add_pipe(bell, {mm(bx + bore, by, brace_z), mm(-4, by, brace_z)}, 4.0, 10, Tube::End::flat);
  add_pipe(bell, {mm(bx, back_y - bore, bow_z - 60), mm(bx, by + bore, bow_z - 60)}, 3.0, 8,
           Tube::End::flat);

  const int trombone = builder.add_node("trombone");
  builder.add_root(trombone);
  builder.add_child(
      trombone,
      builder.add_node("bell_section", builder.add_mesh("trombone_bell_section", bell, brass)));
  builder.add_child(
      trombone,
      builder.add_node("inner_slide", builder.add_mesh("trombone_inner_slide", inner, silver)));
  const int slide = builder.add_node("slide", builder.add_mesh("trombone_slide", outer, brass));
  builder.set_extras(slide, travel_extras("max_extension_mm", max_extension_mm));
  builder.add_child(trombone, slide);
  builder.add_child(
      trombone, builder.add_node(
                    "mouthpiece",
                    builder.add_mesh("trombone_mouthpiece",
                                     mouthpiece_mesh(dims.mouthpiece_length_mm,
                                                     dims.mouthpiece_rim_diameter_mm, bore * 0.8),
                                     silver)));
  // Grips in the hand frame (README.md). Left: on the bell brace, palm forward, fingers down
  // over the brace, thumb outward (-X).
  const double r = 1.0 / std::sqrt(2.0);
  builder.add_child(
      trombone,
      builder.add_node("grip_left", -1, {(bx / 2) / 1000, (by + 22) / 1000, (brace_z + 25) / 1000},
                       {0.0, r, r, 0.0}));
  // Right: on the slide's hand grip, palm toward -X, fingers forward, thumb up.
  builder.add_child(
      slide, builder.add_node("grip_right", -1, {0.030, (-s / 2) / 1000, slide_brace_z / 1000},
                              about({0, 0, 1}, -90)));
  return builder.finish();
}

}  // namespace tutti::content_generator
