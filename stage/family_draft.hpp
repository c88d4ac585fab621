// SPDX-License-Identifier: MIT
#pragma once
// A family's part of a scene drafted from music alone (`tutti scene new`, `tutti render
// PIECE.mid`; tutti::performance::draft_scene puts the families' drafts together). In the order
// the families are listed, each recognises the parts it plays among those nobody has taken (by
// name in English, German, Italian and French, and by General MIDI program); then each drafts
// its players for those parts: its section of the scene file, its cameras, and its groups, the
// camera sets the shot list cuts between. Families sit side by side from the audience's left in
// their seating order; each drafts in a frame of its own, moved along x to its place.
//
// The helpers below write cameras and positions as every drafted scene does (millimetres, the
// JSON layout of the hand-written scenes).

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/music/score.hpp>

namespace tutti::stage {

// A set of cameras the shot list cycles through while its parts play the most notes.
struct DraftedGroup {
  std::string name;                  // unique across the scene: "horn", "organ", "violins"
  std::vector<int> parts;            // score parts whose onsets count for it
  std::vector<std::string> cameras;  // names, in the order they are cut to
};

struct FamilyDraft {
  // Top-level keys of the scene file and their values, e.g. "performers": [...].
  std::vector<std::pair<std::string, nlohmann::ordered_json>> section;
  std::vector<nlohmann::ordered_json> cameras;
  std::vector<DraftedGroup> groups;
  // For the description: "2 horns, 1 tuba", "an organist and a harpsichordist".
  std::string summary;
  // What the players occupy along x (metres, in the frame the family drafted in), for placing
  // the families side by side and framing the wide shot.
  double left_m = 0.0;
  double right_m = 0.0;
  // How long before the music the scene starts (the lead's cue is seen before the entrance).
  double pre_roll_s = 0.0;
  // When the family plays alone: the wide camera the scene opens on (else one is made to frame
  // every family's players).
  std::optional<nlohmann::ordered_json> wide_camera_alone;
};

struct DraftPlace {
  double origin_x = 0.0;  // where the family's frame's origin goes on the floor
  bool alone = true;      // no other family has players
};

// The name of part p as a scene names it: its name when no other part shares it, else its id.
std::string draft_part_reference(const music::Score& score, int p);

// Millimetre rounding, [x, y, z] as written, a camera object, and a point `distance` metres from
// (x, z) toward `angle_deg` (0 = +Z, positive toward +X).
double draft_round_mm(double v);
nlohmann::ordered_json draft_vec3(double x, double y, double z);
nlohmann::ordered_json draft_camera(const std::string& name, double px, double py, double pz,
                                    double tx, double ty, double tz, double fov_deg);
std::pair<double, double> draft_ahead(double x, double z, double angle_deg, double distance);
// A camera framing everything in x in [left, right] near the floor from the front.
nlohmann::ordered_json draft_wide_camera(const std::string& name, double left, double right,
                                         double front_z, double fov_deg);

}  // namespace tutti::stage
