#include "generator/dimensions.hpp"

#include <array>
#include <nlohmann/json.hpp>

#include "content/json_reader.hpp"

namespace tutti::content_generator {
namespace {

using content::NumberField;

// Sizes are strictly positive and below 3 m; a gap or inset may be zero.
constexpr double kMinSize = 0.1;
constexpr double kMaxSize = 3000.0;

Status read_section(const content::JsonReader& reader, const nlohmann::json& document,
                    const char* key, std::span<const NumberField> fields) {
  const std::string path = std::string("/") + key;
  if (!document.contains(key)) return reader.error(path, "missing");
  return reader.read_number_fields(document.at(key), path, fields, true);
}

}  // namespace

Result<AssetDimensions> AssetDimensions::load(const std::filesystem::path& path) {
  auto document = content::read_json_file(path);
  if (!document) return document.error();
  return from_json(*document, path.filename().string());
}

Result<AssetDimensions> AssetDimensions::from_json(const nlohmann::json& document,
                                                   const std::string& file_name) {
  const content::JsonReader reader(file_name);
  if (auto ok = reader.check_keys(document, "", {"description", "piano", "music_stand", "chair"});
      !ok) {
    return ok.error();
  }
  AssetDimensions d;
  PianoDimensions& p = d.piano;
  const std::array piano{
      NumberField{"white_key_gap_mm", &p.white_key_gap_mm, 0.0, 5.0},
      NumberField{"white_key_length_mm", &p.white_key_length_mm, kMinSize, kMaxSize},
      NumberField{"white_key_height_mm", &p.white_key_height_mm, kMinSize, kMaxSize},
      NumberField{"black_key_width_mm", &p.black_key_width_mm, kMinSize, kMaxSize},
      NumberField{"black_key_length_mm", &p.black_key_length_mm, kMinSize, kMaxSize},
      NumberField{"black_key_height_mm", &p.black_key_height_mm, kMinSize, kMaxSize},
      NumberField{"black_key_rise_mm", &p.black_key_rise_mm, 0.0, kMaxSize},
      NumberField{"key_top_above_floor_mm", &p.key_top_above_floor_mm, kMinSize, kMaxSize},
      NumberField{"cheek_width_mm", &p.cheek_width_mm, kMinSize, kMaxSize},
      NumberField{"cabinet_height_mm", &p.cabinet_height_mm, kMinSize, kMaxSize},
      NumberField{"cabinet_depth_mm", &p.cabinet_depth_mm, kMinSize, kMaxSize},
  };
  if (auto ok = read_section(reader, document, "piano", piano); !ok) return ok.error();
  MusicStandDimensions& s = d.music_stand;
  const std::array stand{
      NumberField{"base_radius_mm", &s.base_radius_mm, kMinSize, kMaxSize},
      NumberField{"base_height_mm", &s.base_height_mm, kMinSize, kMaxSize},
      NumberField{"shaft_radius_mm", &s.shaft_radius_mm, kMinSize, kMaxSize},
      NumberField{"hinge_height_mm", &s.hinge_height_mm, kMinSize, kMaxSize},
      NumberField{"desk_width_mm", &s.desk_width_mm, kMinSize, kMaxSize},
      NumberField{"desk_height_mm", &s.desk_height_mm, kMinSize, kMaxSize},
      NumberField{"desk_thickness_mm", &s.desk_thickness_mm, kMinSize, kMaxSize},
      NumberField{"ledge_depth_mm", &s.ledge_depth_mm, kMinSize, kMaxSize},
      NumberField{"desk_lean_deg", &s.desk_lean_deg, 0.0, 80.0},
  };
  if (auto ok = read_section(reader, document, "music_stand", stand); !ok) return ok.error();
  ChairDimensions& c = d.chair;
  const std::array chair{
      NumberField{"seat_width_mm", &c.seat_width_mm, kMinSize, kMaxSize},
      NumberField{"seat_depth_mm", &c.seat_depth_mm, kMinSize, kMaxSize},
      NumberField{"seat_thickness_mm", &c.seat_thickness_mm, kMinSize, kMaxSize},
      NumberField{"seat_top_mm", &c.seat_top_mm, kMinSize, kMaxSize},
      NumberField{"leg_radius_mm", &c.leg_radius_mm, kMinSize, kMaxSize},
      NumberField{"leg_inset_mm", &c.leg_inset_mm, 0.0, kMaxSize},
      NumberField{"backrest_bottom_mm", &c.backrest_bottom_mm, kMinSize, kMaxSize},
      NumberField{"backrest_top_mm", &c.backrest_top_mm, kMinSize, kMaxSize},
      NumberField{"backrest_thickness_mm", &c.backrest_thickness_mm, kMinSize, kMaxSize},
  };
  if (auto ok = read_section(reader, document, "chair", chair); !ok) return ok.error();

  // Relations the shapes rely on.
  if (c.seat_thickness_mm >= c.seat_top_mm) {
    return reader.error("/chair/seat_thickness_mm", "must be less than seat_top_mm");
  }
  if (c.backrest_bottom_mm <= c.seat_top_mm || c.backrest_top_mm <= c.backrest_bottom_mm) {
    return reader.error("/chair/backrest_bottom_mm",
                        "need seat_top_mm < backrest_bottom_mm < backrest_top_mm");
  }
  if (s.base_height_mm >= s.hinge_height_mm) {
    return reader.error("/music_stand/base_height_mm", "must be less than hinge_height_mm");
  }
  if (p.black_key_length_mm > p.white_key_length_mm) {
    return reader.error("/piano/black_key_length_mm", "must not exceed white_key_length_mm");
  }
  if (p.white_key_height_mm + 52.0 >= p.key_top_above_floor_mm) {
    return reader.error("/piano/key_top_above_floor_mm", "leaves no room for the keybed");
  }
  return d;
}

}  // namespace tutti::content_generator
