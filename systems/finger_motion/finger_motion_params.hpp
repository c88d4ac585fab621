// SPDX-License-Identifier: MIT
#pragma once
// Finger geometry and key-stroke timing, from content/piano/finger_motion.json (medium hand; the
// planner scales lengths by the hands.json preset). Strictly checked: unknown keys, missing
// values, non-positive lengths or times are errors naming the file and JSON path.
//
// Units: millimetres, radians, seconds. Keyboard frame: x along the keys, y into the keys from the
// white keys' front edge, z up from the white keys' top.

#include <array>
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include <tutti/core/result.hpp>

namespace tutti::finger_motion {

// One finger's planar chain (the vertical plane through the finger). Joint 1 is the stroke joint
// (MCP for fingers 2..5, CMC abduction for the thumb); joints 2 and 3 (PIP and DIP; thumb MCP and
// IP) are "bent" together: joint 3 = coupling x joint 2.
struct FingerGeometry {
  std::array<double, 3> phalanges_mm{};  // segment lengths from the root (> 0)
  double root_y_mm = 0.0;                // root joint position relative to the hand reference
  double root_z_mm = 0.0;                // height of the root above the white keys' top (> 0)
  double neutral_bend_rad = 0.0;         // joint 2 at rest, away from keys
  double white_bend_rad = 0.0;           // joint 2 while playing a white key
  double black_bend_rad = 0.0;           // joint 2 while playing a black key (flatter: reaches in)
  double coupling = 2.0 / 3.0;           // joint 3 / joint 2, in [0, 1.5]
  // How far the pad's lowest point lies below the fingertip at a stroke's bottom: the posed tip
  // is held this much above the contact so the flesh meets the key top instead of sinking into
  // it (the thumb strikes with the side of its tip; tutti check-pose measures it).
  double pad_drop_mm = 0.0;
};

struct KeyHeights {
  double white_top_z_mm = 0.0;   // top of a white key at rest
  double black_top_z_mm = 12.5;  // top of a black key at rest (> white)
  double dip_mm = 10.0;          // key travel to the key bottom (> 0)
  double hover_lift_mm = 8.0;    // fingertip height above a key top when not pressing (>= 0)
  double black_front_y_mm = 55.0;  // the black keys' front edge, behind the white keys' front
  double black_press_in_mm = 12.0;  // a finger's pad lands this far behind that edge (>= 0)
  double white_press_in_mm = 12.0;  // and this far behind a white key's front edge (>= 0)
  // The keys are levers on the balance rail this far in (0: none modelled, every key travels
  // dip_mm wherever it is pressed); a key pressed at y travels dip_mm x (pivot - y) / (pivot -
  // its front), its front being 0 for a white key and black_front_y_mm for a black one.
  double pivot_y_mm = 0.0;
};

struct StrokeTiming {
  double press_lead_s = 0.05;          // the stroke starts this long before the onset (> 0)
  double move_min_s = 0.06;            // lateral minimum-jerk move duration, lower bound (> 0)
  double move_max_s = 0.18;            // upper bound (>= move_min_s)
  double move_s_per_mm = 0.0015;       // move duration = clamp(min + this x distance, min, max)
  double shape_s = 0.08;               // joints 2-3 reshape over this long before the stroke (> 0)
  double release_s = 0.05;             // key rise after the offset (> 0)
  double relax_time_constant_s = 0.2;  // exponential relax toward neutral after a release (> 0)
  // The hand's move in toward the fallboard for black keys (spline_motion/plateau_envelope.hpp): its longest ease
  // (> 0), and the dip between two needs it bridges instead of going out and back (>= 0).
  double reach_in_s = 0.15;
  double reach_in_bridge_s = 0.4;
};

// One hand passing over the other (pass_over.hpp). Optional in the file ("pass_over").
struct PassOverParams {
  // Over the other hand's knuckles (its palm's capsule tops out 51 mm above the white keys);
  // pressing fingers straighten to reach down from it.
  double lift_mm = 32.0;
  double gap_mm = 60.0;       // reference points this close on their own sides ...
  double crossed_mm = 130.0;  // ... or crossed by less than this: the hands overlap
  double ease_s = 0.08;       // up before the overlap and down after it, minimum jerk
  double sample_s = 0.01;     // where the paths are compared
};

struct FingerMotionParams {
  std::array<FingerGeometry, 5> fingers{};  // [0] = thumb .. [4] = little finger
  KeyHeights keys;
  StrokeTiming timing;
  PassOverParams pass_over;
};

Result<FingerMotionParams> load_finger_motion_params(const std::filesystem::path& path);
Result<FingerMotionParams> finger_motion_params_from_json(const nlohmann::json& document,
                                                          const std::string& file_name);

// <content_dir>/piano/finger_motion.json.
std::filesystem::path finger_motion_params_path(const std::filesystem::path& content_dir);

}  // namespace tutti::finger_motion
