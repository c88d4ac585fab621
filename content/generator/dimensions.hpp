// SPDX-License-Identifier: MIT
#pragma once
// The assets' real dimensions (millimetres, degrees), read strictly from
// content/generator/dimensions.json: every key required, unknown keys and out-of-range values are
// one-line errors naming the file and the JSON path ("dimensions.json: /chair/seat_top_mm: ...").
// The defaults below equal the shipped file, so code can build an asset without reading it.

#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include <tutti/core/result.hpp>

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

struct StageDimensions {
  double width_mm = 12000.0;          // along X
  double depth_mm = 8000.0;           // along Z
  double platform_height_mm = 400.0;  // the skirt below the floor's top (y = 0)
  double plank_width_mm = 150.0;
  double plank_gap_mm = 2.0;
  double edge_height_mm = 15.0;  // the nosing strip around the edge, above the floor
  double edge_width_mm = 60.0;
};

// B-flat trumpet (brass_assets.hpp). Lengths from the mouthpiece rim forward (toward -Z).
struct TrumpetDimensions {
  double overall_length_mm = 480.0;  // mouthpiece rim to bell rim
  double bell_diameter_mm = 123.0;
  double bore_mm = 11.66;
  double mouthpiece_length_mm = 88.0;
  double mouthpiece_rim_diameter_mm = 26.0;
  double valve_casing_diameter_mm = 22.0;
  double valve_pitch_mm = 25.0;  // centre to centre, along the instrument
  double button_diameter_mm = 16.0;
  double piston_travel_mm = 18.0;  // button top at rest to fully down
};

// Tenor trombone (brass_assets.hpp). The slide's maximum extension is not here: it is the 7th
// position from content/instruments/trombone_tenor.json.
struct TromboneDimensions {
  double bell_diameter_mm = 216.0;
  double bore_mm = 13.9;
  double mouthpiece_length_mm = 90.0;
  double mouthpiece_rim_diameter_mm = 38.0;
  double inner_slide_length_mm = 700.0;  // the fixed inner tubes, receiver to their ends
  double slide_spacing_mm = 95.0;        // centre to centre of the two slide tubes
  double bell_forward_mm = 650.0;        // bell rim ahead of the mouthpiece rim
  double bell_offset_mm = 125.0;         // bell axis to the player's left of the slide
  double tuning_bow_back_mm = 230.0;     // tuning-slide bow behind the mouthpiece rim
};

// An upright valved instrument (upright_brass.hpp): euphonium or tuba, four top-action pistons
// in a row on the player's right, the bell up. Lengths from the mouthpiece rim (the player at
// +Z, their right +X, up +Y).
struct UprightDimensions {
  double height_mm = 640.0;            // bottom bow to bell rim
  double top_above_mm = 180.0;         // bell rim above the mouthpiece rim
  double bell_diameter_mm = 300.0;
  double bell_tilt_deg = 12.0;         // bell axis from vertical, toward the audience
  double bell_forward_mm = 200.0;      // bell branch axis ahead of the mouthpiece
  double bell_left_mm = 200.0;         // bell branch axis to the player's left (clear of the face)
  double bore_mm = 14.5;
  double mouthpiece_length_mm = 90.0;
  double mouthpiece_rim_diameter_mm = 40.0;
  double valve_casing_diameter_mm = 24.0;
  double valve_pitch_mm = 30.0;        // centre to centre, front to back
  double valves_forward_mm = 110.0;    // first valve ahead of the mouthpiece
  double valves_right_mm = 70.0;       // valve row to the player's right
  double button_drop_mm = 110.0;       // button tops below the mouthpiece
  double button_diameter_mm = 18.0;
  double piston_travel_mm = 20.0;
};

// A double horn (horn_asset.hpp). Lengths from the mouthpiece rim (the player at +Z, their right
// +X, up +Y).
struct HornDimensions {
  double bore_mm = 12.0;
  double bell_diameter_mm = 310.0;
  double bell_flare_mm = 450.0;          // the bell's length from its throat to the rim
  double bell_throat_diameter_mm = 40.0; // where the last coil turn, widening, becomes the bell
  double bell_back_x = 0.55;             // the bell's axis: (x, -y, 1) normalised, pointing back
  double bell_back_y = 0.8;              //   toward the player's right side and down
  double mouthpiece_length_mm = 80.0;
  double mouthpiece_rim_diameter_mm = 27.0;
  double valves_left_mm = 60.0;          // rotor row to the player's left of the mouthpiece
  double valves_drop_mm = 110.0;         // rotor row's middle below the mouthpiece
  double valves_forward_mm = 150.0;      // first rotor ahead of the mouthpiece
  double rotor_diameter_mm = 30.0;
  double rotor_pitch_mm = 30.0;          // centre to centre, front to back
  double lever_left_mm = 45.0;           // lever pads to the left of their rotors
  double lever_rise_mm = 8.0;            // pad tops above the casings' tops
  double lever_travel_mm = 10.0;         // pad top at rest to fully down
  double coil_right_mm = 60.0;           // the coils' centre
  double coil_drop_mm = 270.0;
  double coil_forward_mm = 240.0;
  double coil_radius_mm = 150.0;
};

// The performer rig (performer_asset.hpp): an adult of about 1.75 m standing in the A-pose. Bone
// lengths are joint to joint; the head's joint is at chin height, the crown head_height_mm above.
struct PerformerDimensions {
  double ankle_height_mm = 80.0;       // ankle joint (foot bone) above the floor
  double shin_length_mm = 420.0;       // knee to ankle
  double thigh_length_mm = 430.0;      // hip joint to knee
  double hip_width_mm = 180.0;         // between the hip joints
  double spine_length_mm = 110.0;      // hips to spine (lumbar)
  double chest_length_mm = 150.0;      // spine to chest
  double neck_base_mm = 230.0;         // chest to the neck's base
  double neck_length_mm = 95.0;        // neck base to the head joint (chin height)
  double head_height_mm = 230.0;       // chin to crown
  double shoulder_width_mm = 360.0;    // between the shoulder joints (upper arm origins)
  double upper_arm_length_mm = 300.0;  // shoulder to elbow
  double forearm_length_mm = 255.0;    // elbow to wrist
  double arm_spread_deg = 12.0;        // the A-pose: the arms' angle out from vertical
  double foot_length_mm = 260.0;       // heel to toe (the shoe)
};

struct AssetDimensions {
  PianoDimensions piano;
  MusicStandDimensions music_stand;
  ChairDimensions chair;
  StageDimensions stage;
  TrumpetDimensions trumpet;
  TromboneDimensions trombone;
  UprightDimensions euphonium;
  UprightDimensions tuba;
  HornDimensions horn;
  PerformerDimensions performer;

  static Result<AssetDimensions> load(const std::filesystem::path& path);
  static Result<AssetDimensions> from_json(const nlohmann::json& document,
                                           const std::string& file_name);
};

}  // namespace tutti::content_generator
