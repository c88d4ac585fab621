// SPDX-License-Identifier: MIT
#include <tutti/generator/piano_asset.hpp>

#include <string>

#include <tutti/generator/gltf_builder.hpp>

namespace tutti::content_generator {
namespace {

float m(double mm) { return static_cast<float>(mm / 1000.0); }

}  // namespace

tinygltf::Model build_piano(const piano::Keyboard& keyboard, const PianoDimensions& dims,
                            const std::array<double, 3>& case_color, const std::string& root_name) {
  ModelBuilder builder;
  const int ivory = builder.add_material({"key_white", {0.86, 0.84, 0.80, 1.0}, 0.0, 0.35});
  const int ebony = builder.add_material({"key_black", {0.02, 0.02, 0.02, 1.0}, 0.0, 0.3});
  const int lacquer = builder.add_material(
      {"case_lacquer", {case_color[0], case_color[1], case_color[2], 1.0}, 0.0, 0.15});

  // Key meshes in the key's own frame: origin at the pivot, which is the key's back edge at
  // its top surface and centre line; the key extends toward the player (+Z) and down (-Y).
  MeshData white;
  const double white_width_mm = keyboard.white_key_width_mm() - dims.white_key_gap_mm;
  add_box(white, {m(-white_width_mm / 2), m(-dims.white_key_height_mm), 0.0f},
          {m(white_width_mm / 2), 0.0f, m(dims.white_key_length_mm)});
  const int white_mesh = builder.add_mesh("white_key", white, ivory);
  MeshData black;
  add_box(black, {m(-dims.black_key_width_mm / 2), m(-dims.black_key_height_mm), 0.0f},
          {m(dims.black_key_width_mm / 2), 0.0f, m(dims.black_key_length_mm)});
  const int black_mesh = builder.add_mesh("black_key", black, ebony);

  // Outer edges of the keyboard (the end keys are white on a standard piano).
  const double half_pitch = keyboard.white_key_width_mm() / 2;
  const double left_mm = keyboard.x_mm(keyboard.lowest_key()) - half_pitch;
  const double right_mm = keyboard.x_mm(keyboard.highest_key()) + half_pitch;
  const double centre_mm = (left_mm + right_mm) / 2;
  const double half_width_mm = (right_mm - left_mm) / 2;

  // The case in the piano's frame (origin on the floor, centred under the keys, Z = 0 at the
  // front edge of the white keys).
  MeshData body;
  const double outer = half_width_mm + dims.cheek_width_mm;
  const double key_top = dims.key_top_above_floor_mm;
  const double key_bottom = key_top - dims.white_key_height_mm;
  const double back_of_keys = -dims.white_key_length_mm;
  const double front = 20.0;  // keybed and cheeks stand a little proud of the keys
  const double cabinet_front = back_of_keys - 110.0;
  add_box(body, {m(-outer), m(key_bottom - 50), m(cabinet_front)},
          {m(outer), m(key_bottom - 2), m(front)});  // keybed
  add_box(body, {m(-outer), m(key_bottom - 2), m(cabinet_front)},
          {m(-half_width_mm - 1), m(key_top + 60), m(front)});  // left cheek
  add_box(body, {m(half_width_mm + 1), m(key_bottom - 2), m(cabinet_front)},
          {m(outer), m(key_top + 60), m(front)});  // right cheek
  add_box(body, {m(-half_width_mm - 1), m(key_bottom - 2), m(cabinet_front)},
          {m(half_width_mm + 1), m(key_top + 90), m(back_of_keys - 1)});  // fallboard
  add_box(body, {m(-outer), 0.0f, m(-dims.cabinet_depth_mm)},
          {m(outer), m(dims.cabinet_height_mm), m(cabinet_front)});  // cabinet
  add_box(body, {m(-outer), 0.0f, m(cabinet_front)},
          {m(-outer + dims.cheek_width_mm), m(key_bottom - 50), m(front)});  // left leg
  add_box(body, {m(outer - dims.cheek_width_mm), 0.0f, m(cabinet_front)},
          {m(outer), m(key_bottom - 50), m(front)});  // right leg
  const int case_mesh = builder.add_mesh("case", body, lacquer);

  const int piano = builder.add_node(root_name);
  builder.add_root(piano);
  builder.add_child(piano, builder.add_node("case", case_mesh));
  // The keyboard node's frame is the keyboard frame mapped to glTF: x -> X, z -> Y, y -> -Z,
  // origin at the left edge of the lowest key, the white keys' front edge and top surface.
  const int keyboard_node =
      builder.add_node("keyboard", -1, {-centre_mm / 1000.0, key_top / 1000.0, 0.0});
  builder.add_child(piano, keyboard_node);
  for (int key = keyboard.lowest_key(); key <= keyboard.highest_key(); ++key) {
    const bool is_black = keyboard.is_black(key);
    const double top_mm = is_black ? dims.black_key_rise_mm : 0.0;
    const int node =
        builder.add_node("key_" + std::to_string(key), is_black ? black_mesh : white_mesh,
                         {keyboard.x_mm(key) / 1000.0, top_mm / 1000.0, back_of_keys / 1000.0});
    builder.add_child(keyboard_node, node);
  }
  return builder.finish();
}

}  // namespace tutti::content_generator
