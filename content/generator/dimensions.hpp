#pragma once
// The assets' real dimensions (millimetres, degrees), read strictly from
// content/generator/dimensions.json: every key required, unknown keys and out-of-range values are
// one-line errors naming the file and the JSON path ("dimensions.json: /chair/seat_top_mm: ...").
// The defaults below equal the shipped file, so code can build an asset without reading it.

#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "core/result.hpp"

namespace tutti::content_generator {

struct PianoDimensions {
  double white_key_gap_mm = 1.0;       // white key width = pitch (keyboard.json) - gap
  double white_key_length_mm = 150.0;  // visible length, front edge to the fallboard
  double white_key_height_mm = 22.0;
  double black_key_width_mm = 11.0;
  double black_key_length_mm = 95.0;  // ends on the same back line as the white keys
  double black_key_height_mm = 22.0;
  double black_key_rise_mm = 12.0;  // black key top above the white key top
  double key_top_above_floor_mm = 720.0;
  double cheek_width_mm = 60.0;  // the blocks left and right of the keys
  double cabinet_height_mm = 1250.0;
  double cabinet_depth_mm = 600.0;  // front of the keys to the back of the piano
};

struct MusicStandDimensions {
  double base_radius_mm = 180.0;
  double base_height_mm = 20.0;
  double shaft_radius_mm = 12.5;
  double hinge_height_mm = 1000.0;  // the desk's hinge above the floor
  double desk_width_mm = 510.0;
  double desk_height_mm = 330.0;
  double desk_thickness_mm = 4.0;
  double ledge_depth_mm = 45.0;  // the lip the music rests on
  double desk_lean_deg = 20.0;   // top of the desk tipped away from the reader
};

struct ChairDimensions {
  double seat_width_mm = 450.0;
  double seat_depth_mm = 420.0;
  double seat_thickness_mm = 40.0;
  double seat_top_mm = 460.0;  // above the floor
  double leg_radius_mm = 15.0;
  double leg_inset_mm = 30.0;  // leg centre inside the seat's edge
  double backrest_bottom_mm = 650.0;
  double backrest_top_mm = 880.0;
  double backrest_thickness_mm = 25.0;
};

struct AssetDimensions {
  PianoDimensions piano;
  MusicStandDimensions music_stand;
  ChairDimensions chair;

  static Result<AssetDimensions> load(const std::filesystem::path& path);
  static Result<AssetDimensions> from_json(const nlohmann::json& document,
                                           const std::string& file_name);
};

}  // namespace tutti::content_generator
