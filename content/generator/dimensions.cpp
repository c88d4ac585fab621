// SPDX-License-Identifier: MIT
#include <tutti/generator/dimensions.hpp>

#include <array>
#include <string>
#include <nlohmann/json.hpp>

#include <tutti/content/json_reader.hpp>

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
  if (auto ok = reader.check_keys(document, "",
                                  {"description", "piano", "music_stand", "chair", "stage",
                                   "trumpet", "trombone", "euphonium", "tuba", "horn",
                                   "performer"});
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

  StageDimensions& g = d.stage;
  const std::array stage{
      NumberField{"width_mm", &g.width_mm, 1000.0, 50000.0},
      NumberField{"depth_mm", &g.depth_mm, 1000.0, 50000.0},
      NumberField{"platform_height_mm", &g.platform_height_mm, kMinSize, kMaxSize},
      NumberField{"plank_width_mm", &g.plank_width_mm, 20.0, 1000.0},
      NumberField{"plank_gap_mm", &g.plank_gap_mm, 0.0, 20.0},
      NumberField{"edge_height_mm", &g.edge_height_mm, 0.0, 200.0},
      NumberField{"edge_width_mm", &g.edge_width_mm, kMinSize, 500.0},
  };
  if (auto ok = read_section(reader, document, "stage", stage); !ok) return ok.error();
  TrumpetDimensions& t = d.trumpet;
  const std::array trumpet{
      NumberField{"overall_length_mm", &t.overall_length_mm, 380.0, 700.0},
      NumberField{"bell_diameter_mm", &t.bell_diameter_mm, 80.0, 200.0},
      NumberField{"bore_mm", &t.bore_mm, 8.0, 16.0},
      NumberField{"mouthpiece_length_mm", &t.mouthpiece_length_mm, 50.0, 120.0},
      NumberField{"mouthpiece_rim_diameter_mm", &t.mouthpiece_rim_diameter_mm, 15.0, 40.0},
      NumberField{"valve_casing_diameter_mm", &t.valve_casing_diameter_mm, 15.0, 30.0},
      NumberField{"valve_pitch_mm", &t.valve_pitch_mm, 15.0, 40.0},
      NumberField{"button_diameter_mm", &t.button_diameter_mm, 8.0, 25.0},
      NumberField{"piston_travel_mm", &t.piston_travel_mm, 5.0, 30.0},
  };
  if (auto ok = read_section(reader, document, "trumpet", trumpet); !ok) return ok.error();
  TromboneDimensions& b = d.trombone;
  const std::array trombone{
      NumberField{"bell_diameter_mm", &b.bell_diameter_mm, 150.0, 300.0},
      NumberField{"bore_mm", &b.bore_mm, 10.0, 16.0},
      NumberField{"mouthpiece_length_mm", &b.mouthpiece_length_mm, 60.0, 130.0},
      NumberField{"mouthpiece_rim_diameter_mm", &b.mouthpiece_rim_diameter_mm, 25.0, 50.0},
      NumberField{"inner_slide_length_mm", &b.inner_slide_length_mm, 400.0, 1000.0},
      NumberField{"slide_spacing_mm", &b.slide_spacing_mm, 60.0, 150.0},
      NumberField{"bell_forward_mm", &b.bell_forward_mm, 400.0, 900.0},
      NumberField{"bell_offset_mm", &b.bell_offset_mm, 80.0, 250.0},
      NumberField{"tuning_bow_back_mm", &b.tuning_bow_back_mm, 100.0, 400.0},
  };
  if (auto ok = read_section(reader, document, "trombone", trombone); !ok) return ok.error();

  for (const char* name : {"euphonium", "tuba"}) {
    UprightDimensions& u = std::string(name) == "tuba" ? d.tuba : d.euphonium;
    const std::array upright{
        NumberField{"height_mm", &u.height_mm, 400.0, 1300.0},
        NumberField{"top_above_mm", &u.top_above_mm, 0.0, 600.0},
        NumberField{"bell_diameter_mm", &u.bell_diameter_mm, 150.0, 600.0},
        NumberField{"bell_tilt_deg", &u.bell_tilt_deg, 0.0, 45.0},
        NumberField{"bell_forward_mm", &u.bell_forward_mm, 80.0, 500.0},
        NumberField{"bell_left_mm", &u.bell_left_mm, 0.0, 300.0},
        NumberField{"bore_mm", &u.bore_mm, 10.0, 25.0},
        NumberField{"mouthpiece_length_mm", &u.mouthpiece_length_mm, 60.0, 140.0},
        NumberField{"mouthpiece_rim_diameter_mm", &u.mouthpiece_rim_diameter_mm, 25.0, 60.0},
        NumberField{"valve_casing_diameter_mm", &u.valve_casing_diameter_mm, 15.0, 45.0},
        NumberField{"valve_pitch_mm", &u.valve_pitch_mm, 15.0, 60.0},
        NumberField{"valves_forward_mm", &u.valves_forward_mm, 40.0, 400.0},
        NumberField{"valves_right_mm", &u.valves_right_mm, 20.0, 250.0},
        NumberField{"button_drop_mm", &u.button_drop_mm, 0.0, 400.0},
        NumberField{"button_diameter_mm", &u.button_diameter_mm, 8.0, 35.0},
        NumberField{"piston_travel_mm", &u.piston_travel_mm, 5.0, 40.0},
    };
    if (auto ok = read_section(reader, document, name, upright); !ok) return ok.error();
    const std::string at = std::string("/") + name;
    if (u.valve_pitch_mm < u.valve_casing_diameter_mm) {
      return reader.error(at + "/valve_pitch_mm", "must be at least valve_casing_diameter_mm");
    }
    if (u.top_above_mm + u.button_drop_mm + 200.0 > u.height_mm) {
      return reader.error(at + "/height_mm",
                          "must exceed top_above_mm + button_drop_mm by 200 (the valve block)");
    }
  }

  HornDimensions& h = d.horn;
  const std::array horn{
      NumberField{"bore_mm", &h.bore_mm, 8.0, 16.0},
      NumberField{"bell_diameter_mm", &h.bell_diameter_mm, 200.0, 400.0},
      NumberField{"bell_flare_mm", &h.bell_flare_mm, 150.0, 600.0},
      NumberField{"bell_throat_diameter_mm", &h.bell_throat_diameter_mm, 15.0, 80.0},
      NumberField{"bell_back_x", &h.bell_back_x, 0.0, 2.0},
      NumberField{"bell_back_y", &h.bell_back_y, 0.0, 2.0},
      NumberField{"mouthpiece_length_mm", &h.mouthpiece_length_mm, 50.0, 120.0},
      NumberField{"mouthpiece_rim_diameter_mm", &h.mouthpiece_rim_diameter_mm, 15.0, 40.0},
      NumberField{"valves_left_mm", &h.valves_left_mm, 0.0, 200.0},
      NumberField{"valves_drop_mm", &h.valves_drop_mm, 20.0, 300.0},
      NumberField{"valves_forward_mm", &h.valves_forward_mm, 60.0, 400.0},
      NumberField{"rotor_diameter_mm", &h.rotor_diameter_mm, 15.0, 50.0},
      NumberField{"rotor_pitch_mm", &h.rotor_pitch_mm, 15.0, 60.0},
      NumberField{"lever_left_mm", &h.lever_left_mm, 20.0, 100.0},
      NumberField{"lever_rise_mm", &h.lever_rise_mm, 0.0, 40.0},
      NumberField{"lever_travel_mm", &h.lever_travel_mm, 3.0, 25.0},
      NumberField{"coil_right_mm", &h.coil_right_mm, -100.0, 300.0},
      NumberField{"coil_drop_mm", &h.coil_drop_mm, 50.0, 500.0},
      NumberField{"coil_forward_mm", &h.coil_forward_mm, 80.0, 500.0},
      NumberField{"coil_radius_mm", &h.coil_radius_mm, 80.0, 250.0},
  };
  if (auto ok = read_section(reader, document, "horn", horn); !ok) return ok.error();
  if (h.rotor_pitch_mm < h.rotor_diameter_mm) {
    return reader.error("/horn/rotor_pitch_mm", "must be at least rotor_diameter_mm");
  }

  PerformerDimensions& r = d.performer;
  const std::array performer{
      NumberField{"ankle_height_mm", &r.ankle_height_mm, 40.0, 150.0},
      NumberField{"shin_length_mm", &r.shin_length_mm, 300.0, 550.0},
      NumberField{"thigh_length_mm", &r.thigh_length_mm, 300.0, 550.0},
      NumberField{"hip_width_mm", &r.hip_width_mm, 120.0, 260.0},
      NumberField{"spine_length_mm", &r.spine_length_mm, 60.0, 200.0},
      NumberField{"chest_length_mm", &r.chest_length_mm, 80.0, 250.0},
      NumberField{"neck_base_mm", &r.neck_base_mm, 150.0, 320.0},
      NumberField{"neck_length_mm", &r.neck_length_mm, 50.0, 150.0},
      NumberField{"head_height_mm", &r.head_height_mm, 190.0, 270.0},
      NumberField{"shoulder_width_mm", &r.shoulder_width_mm, 280.0, 480.0},
      NumberField{"upper_arm_length_mm", &r.upper_arm_length_mm, 220.0, 380.0},
      NumberField{"forearm_length_mm", &r.forearm_length_mm, 200.0, 330.0},
      NumberField{"arm_spread_deg", &r.arm_spread_deg, 0.0, 45.0},
      NumberField{"foot_length_mm", &r.foot_length_mm, 200.0, 320.0},
  };
  if (auto ok = read_section(reader, document, "performer", performer); !ok) return ok.error();

  // Relations the shapes rely on.
  if (t.valve_pitch_mm < t.valve_casing_diameter_mm) {
    return reader.error("/trumpet/valve_pitch_mm", "must be at least valve_casing_diameter_mm");
  }
  if (b.bell_diameter_mm / 2 > b.bell_offset_mm) {
    return reader.error("/trombone/bell_offset_mm",
                        "must be at least the bell's radius (the bell would cut the slide)");
  }
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
