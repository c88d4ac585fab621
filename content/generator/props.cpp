// SPDX-License-Identifier: MIT
#include <tutti/generator/props.hpp>

#include <numbers>

#include <tutti/generator/gltf_builder.hpp>

namespace tutti::content_generator {
tinygltf::Model build_music_stand(const MusicStandDimensions& dims) {
  ModelBuilder builder;
  const int steel = builder.add_material({"stand_steel", {0.05, 0.05, 0.055, 1.0}, 1.0, 0.45});

  MeshData base;
  add_cylinder(base, {0, 0, 0}, m(dims.base_radius_mm), m(dims.base_height_mm), 32);
  MeshData shaft;
  add_cylinder(shaft, {0, m(dims.base_height_mm), 0}, m(dims.shaft_radius_mm),
               m(dims.hinge_height_mm - dims.base_height_mm), 16);
  // Desk in its hinge frame: the panel rises from the hinge, its face toward the reader (+Z),
  // the ledge sticks out in front at the bottom.
  MeshData desk;
  add_box(desk, {m(-dims.desk_width_mm / 2), 0.0f, m(-dims.desk_thickness_mm)},
          {m(dims.desk_width_mm / 2), m(dims.desk_height_mm), 0.0f});
  add_box(desk, {m(-dims.desk_width_mm / 2), m(-10.0), 0.0f},
          {m(dims.desk_width_mm / 2), m(15.0), m(dims.ledge_depth_mm)});

  const int stand = builder.add_node("music_stand");
  builder.add_root(stand);
  builder.add_child(stand, builder.add_node("base", builder.add_mesh("stand_base", base, steel)));
  builder.add_child(stand,
                    builder.add_node("shaft", builder.add_mesh("stand_shaft", shaft, steel)));
  // Negative rotation about +X tips the top of the desk away from the reader (toward -Z).
  const double lean = -dims.desk_lean_deg * std::numbers::pi / 180.0;
  builder.add_child(
      stand, builder.add_node("desk", builder.add_mesh("stand_desk", desk, steel),
                              {0.0, dims.hinge_height_mm / 1000.0, 0.0}, rotation_about_x(lean)));
  return builder.finish();
}

tinygltf::Model build_chair(const ChairDimensions& dims) {
  ModelBuilder builder;
  const int wood = builder.add_material({"chair_wood", {0.25, 0.13, 0.06, 1.0}, 0.0, 0.6});
  const int cushion = builder.add_material({"chair_cushion", {0.05, 0.05, 0.06, 1.0}, 0.0, 0.9});

  MeshData seat;
  add_box(seat,
          {m(-dims.seat_width_mm / 2), m(dims.seat_top_mm - dims.seat_thickness_mm),
           m(-dims.seat_depth_mm / 2)},
          {m(dims.seat_width_mm / 2), m(dims.seat_top_mm), m(dims.seat_depth_mm / 2)});
  MeshData leg;  // in the leg's frame: from the floor to the underside of the seat
  add_cylinder(leg, {0, 0, 0}, m(dims.leg_radius_mm), m(dims.seat_top_mm - dims.seat_thickness_mm),
               12);
  MeshData backrest;  // a panel on two posts that rise from the back legs
  const double back_z = -dims.seat_depth_mm / 2 + dims.leg_inset_mm;
  add_box(backrest,
          {m(-dims.seat_width_mm / 2), m(dims.backrest_bottom_mm),
           m(back_z - dims.backrest_thickness_mm / 2)},
          {m(dims.seat_width_mm / 2), m(dims.backrest_top_mm),
           m(back_z + dims.backrest_thickness_mm / 2)});
  for (const double side : {-1.0, 1.0}) {
    add_cylinder(
        backrest,
        {m(side * (dims.seat_width_mm / 2 - dims.leg_inset_mm)), m(dims.seat_top_mm), m(back_z)},
        m(dims.leg_radius_mm), m(dims.backrest_bottom_mm - dims.seat_top_mm), 12);
  }

  const int chair = builder.add_node("chair");
  builder.add_root(chair);
  builder.add_child(chair, builder.add_node("seat", builder.add_mesh("chair_seat", seat, cushion)));
  const int leg_mesh = builder.add_mesh("chair_leg", leg, wood);
  const double leg_x = (dims.seat_width_mm / 2 - dims.leg_inset_mm) / 1000.0;
  const double leg_z = (dims.seat_depth_mm / 2 - dims.leg_inset_mm) / 1000.0;
  builder.add_child(chair, builder.add_node("leg_front_left", leg_mesh, {-leg_x, 0.0, leg_z}));
  builder.add_child(chair, builder.add_node("leg_front_right", leg_mesh, {leg_x, 0.0, leg_z}));
  builder.add_child(chair, builder.add_node("leg_back_left", leg_mesh, {-leg_x, 0.0, -leg_z}));
  builder.add_child(chair, builder.add_node("leg_back_right", leg_mesh, {leg_x, 0.0, -leg_z}));
  builder.add_child(
      chair, builder.add_node("backrest", builder.add_mesh("chair_backrest", backrest, wood)));
  return builder.finish();
}

}  // namespace tutti::content_generator
