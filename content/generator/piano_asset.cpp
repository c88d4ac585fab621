// SPDX-License-Identifier: MIT
#include <tutti/generator/piano_asset.hpp>

#include <algorithm>
#include <string>

#include <tutti/generator/gltf_builder.hpp>
#include <tutti/piano_model/pedal_geometry.hpp>

namespace tutti::content_generator {
namespace {

// The pedals (pedal_geometry.hpp) hinged at the console's front `hinge_z_m`, on a frame on the
// floor: `root` > `pedalboard` > `pedal_36`..`pedal_67`.
void add_pedalboard(ModelBuilder& builder, const piano_model::Pedalboard& board, double hinge_z_m,
                    int root) {
  using G = piano_model::PedalGeometry;
  const int natural_material = builder.add_material({"pedal_natural", {0.55, 0.36, 0.2, 1.0}, 0.0, 0.4});
  const int sharp_material = builder.add_material({"pedal_sharp", {0.03, 0.025, 0.02, 1.0}, 0.0, 0.3});
  const int frame_material = builder.add_material({"pedal_frame", {0.2, 0.11, 0.05, 1.0}, 0.0, 0.5});
  const auto f = [](double v) { return static_cast<float>(v); };
  const double half_w = G::kPedalWidth_m / 2.0;
  MeshData natural;
  add_box(natural, {f(-half_w), f(-G::kPedalThickness_m), 0.0f},
          {f(half_w), 0.0f, f(G::kNaturalLength_m)});
  const int natural_mesh = builder.add_mesh("pedal_natural", natural, natural_material);
  MeshData sharp;
  add_box(sharp, {f(-half_w), f(-G::kPedalThickness_m - G::kSharpRise_m), 0.0f},
          {f(half_w), 0.0f, f(G::kSharpLength_m)});
  const int sharp_mesh = builder.add_mesh("pedal_sharp", sharp, sharp_material);
  // The frame under the pedals: a board on the floor, and the sharps' rail at the back.
  MeshData frame;
  const double half = piano_model::pedalboard_half_width_m(board) + 0.02;
  const double top = G::kNaturalTopAboveFloor_m;
  add_box(frame, {f(-half), f(-top), 0.0f}, {f(half), f(-top + 0.012), f(G::kNaturalLength_m + 0.02)});
  add_box(frame, {f(-half), f(-top), 0.0f}, {f(half), f(-G::kPedalThickness_m - 0.002), 0.04f});
  const int frame_mesh = builder.add_mesh("pedal_frame", frame, frame_material);
  const int board_node = builder.add_node("pedalboard", frame_mesh, {0.0, top, hinge_z_m});
  builder.add_child(root, board_node);
  for (int key = board.lowest_key; key <= board.highest_key; ++key) {
    const bool is_sharp = piano_model::pedal_is_sharp(key);
    const int node = builder.add_node(
        "pedal_" + std::to_string(key), is_sharp ? sharp_mesh : natural_mesh,
        {piano_model::pedal_x_m(board, key), is_sharp ? G::kSharpRise_m : 0.0, 0.0});
    builder.add_child(board_node, node);
  }
}

}  // namespace

tinygltf::Model build_piano(const piano_model::Keyboard& keyboard, const PianoDimensions& dims,
                            const std::array<double, 3>& case_color, const std::string& root_name,
                            const piano_model::Pedalboard* pedalboard) {
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
  // An organ's case stands outside its pedalboard: the legs either side of the pedals.
  const double case_half_mm =
      pedalboard == nullptr
          ? half_width_mm
          : std::max(half_width_mm,
                     1000.0 * piano_model::pedalboard_half_width_m(*pedalboard) + 30.0);
  const double outer = case_half_mm + dims.cheek_width_mm;
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
  // An organ's pedals go in under the console, below a kick board.
  const double kick_mm =
      pedalboard == nullptr ? 0.0 : 1000.0 * piano_model::PedalGeometry::kKickBoardHeight_m;
  const double under_mm =
      pedalboard == nullptr ? 0.0 : 1000.0 * piano_model::PedalGeometry::kUnderConsole_m;
  add_box(body, {m(-outer), m(kick_mm), m(-dims.cabinet_depth_mm)},
          {m(outer), m(dims.cabinet_height_mm), m(cabinet_front)});  // cabinet
  if (pedalboard != nullptr) {
    add_box(body, {m(-outer), 0.0f, m(-dims.cabinet_depth_mm)},
            {m(outer), m(kick_mm), m(cabinet_front - under_mm)});  // below the kick board
    if (pedalboard->seat_raise_mm > 0.0) {
      // The bench's platform, in front of the pedals' ends (the bench stands 600 mm in front of
      // the keys at the default spot, piano_plugin.cpp).
      const double front_of_pedals =
          cabinet_front - under_mm + 1000.0 * piano_model::PedalGeometry::kNaturalLength_m;
      add_box(body, {m(-450.0), 0.0f, m(front_of_pedals + 20.0)},
              {m(450.0), m(pedalboard->seat_raise_mm), m(1000.0)});
    }
  }
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
  if (pedalboard != nullptr) {
    add_pedalboard(builder, *pedalboard, (cabinet_front - under_mm) / 1000.0, piano);
  }
  return builder.finish();
}

}  // namespace tutti::content_generator
