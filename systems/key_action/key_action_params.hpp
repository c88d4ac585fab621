// SPDX-License-Identifier: MIT
#pragma once
// The piano key as a lever, from content/piano/key_action.json: each key pivots on the balance
// rail (pivot_y_mm into the keys) and is stopped by the key bed at the angle that gives
// front_dip_mm at its front edge. A fingertip at depth d below the key's top, y into the keys,
// holds the key at angle atan(d / (pivot_y - y)); the hammer escapes when the key passes
// escapement_fraction of its full angle, the damper falls back at damper_fraction, and a key must
// rise to reset_fraction before it can strike again. Velocities come from the key's front-edge
// speed at escapement. Strict loading: errors name the file and the JSON path.
//
// Units: millimetres, seconds, radians; speeds mm/s at the key's front edge.

#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include <tutti/core/result.hpp>

namespace tutti::key_action {

struct KeyLever {
  double front_y_mm = 0.0;     // the key's front edge, into the keys from the white keys' front
  double pivot_y_mm = 250.0;   // balance rail (> front_y_mm)
  double front_dip_mm = 10.0;  // key travel at the front edge (> 0)

  double length_mm() const { return pivot_y_mm - front_y_mm; }
  double bed_angle_rad() const;  // atan(front_dip_mm / length_mm())
  // Key travel at `y_mm` (the contact point, clamped onto the key's length): where the key bed
  // stops a fingertip pressing there.
  double travel_at_mm(double y_mm) const;
  // The key's angle when a tip at y_mm is depth_mm below the key's top (clamped to the bed).
  double angle_rad(double y_mm, double depth_mm) const;
};

struct VelocityCurve {
  double silent_below_mm_s = 70.0;  // slower at escapement: the hammer never reaches the string
  double min_mm_s = 100.0;          // MIDI velocity 1 (>= silent_below_mm_s)
  double max_mm_s = 1200.0;         // MIDI velocity 127 (> min_mm_s)
  // 1..127: every sounding note at this velocity, whatever the key's speed (an organ's pallet or
  // a harpsichord's plectrum has no dynamics); 0 = from the speed.
  double fixed = 0.0;

  // `fixed`, else 1..127, logarithmic in speed between min and max (clamped). Precondition:
  // finite speed.
  int velocity_for(double speed_mm_s) const;
  // The speed that gives `velocity` (1..127).
  double speed_for(int velocity) const;
};

struct KeyAction {
  KeyLever white;
  KeyLever black{50.0, 250.0, 10.0};
  double escapement_fraction = 0.85;  // (0, 1)
  double damper_fraction = 0.5;       // (0, escapement_fraction)
  double reset_fraction = 0.6;        // [damper_fraction, escapement_fraction)
  double return_s = 0.03;  // a released key's spring brings it from the bed to rest this fast
  VelocityCurve velocity;

  const KeyLever& lever(bool black_key) const { return black_key ? black : white; }
};

Result<KeyAction> load_key_action(const std::filesystem::path& path);
// key_action.json with `touch` merged over it (RFC 7386: an instrument's own touch, content/piano/
// instruments.json), checked as a whole; errors name `touch_name` ("instruments.json
// /instruments/organ/touch") and the merged document's path.
Result<KeyAction> load_key_action(const std::filesystem::path& path, const nlohmann::json& touch,
                                  const std::string& touch_name);
Result<KeyAction> key_action_from_json(const nlohmann::json& document,
                                       const std::string& file_name);

// <content_dir>/piano/key_action.json.
std::filesystem::path key_action_path(const std::filesystem::path& content_dir);

}  // namespace tutti::key_action
