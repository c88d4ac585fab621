// SPDX-License-Identifier: MIT
#pragma once
// A cutscene as plain data (content/scenes/*.json, format in scene/README.md): which music,
// who plays it where (each family's players, read by its SceneSection), the cameras and the shot list that cuts
// between them, the lights and the output settings. load_scene.hpp reads and validates it; the
// planners, ensemble variation and the renderer read the struct and never the JSON.
//
// Axes and units: glTF's (metres, +Y up, right-handed). A performer with facing_deg 0 faces +Z,
// toward the default camera and the audience; positive facing_deg turns toward +X (a rotation
// about +Y). Times are seconds of the music (the score's clock, 0 = its start).

#include <any>
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <tutti/ensemble_variation/variation_params.hpp>

namespace tutti::scene {

struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
  friend bool operator==(const Vec3&, const Vec3&) = default;
};

// Linear RGB, each channel in [0, 1].
struct Color {
  double r = 0.0;
  double g = 0.0;
  double b = 0.0;
  friend bool operator==(const Color&, const Color&) = default;
};

enum class Stance { standing, seated };

// Per-performer expression controls (systems/ensemble_variation owns their meaning): absent =
// drawn from the performer's seed. The fixed list of keys is kVariationFields below.
using Variation = ensemble_variation::VariationOverrides;

struct VariationField {
  std::string_view key;
  std::optional<double> Variation::*value;
  std::string_view meaning;
};
inline constexpr std::array<VariationField, 7> kVariationFields{{
    {"sway_amount", &Variation::sway_amount, "0 = still, 1 = the widest body sway"},
    {"sway_period", &Variation::sway_period, "0 = the shortest sway period, 1 = the longest"},
    {"sway_phase", &Variation::sway_phase, "where in its cycle the sway starts"},
    {"weight_shift_rate", &Variation::weight_shift_rate, "how often the weight changes feet"},
    {"breath_depth", &Variation::breath_depth, "how visibly the chest and shoulders breathe"},
    {"cue_strength", &Variation::cue_strength, "size of the lead's cue and the others' reply"},
    {"head_motion", &Variation::head_motion, "how much the head follows the phrase"},
}};

// Performance marks, as an animator places them in the editor (times: seconds of the music).
// A breath mark names the boundary before the first note starting at or after its time.
struct BreathMarks {
  std::vector<double> add_s;     // breathe here (in the rest, or a catch-breath in a phrase)
  std::vector<double> remove_s;  // no breath here, whatever the rules say
  friend bool operator==(const BreathMarks&, const BreathMarks&) = default;
};

enum class ExpressionKind { strain, relaxed };

// How a player looks over a span: "strain" works hard (shoulders up, less sway, a tense mouth),
// "relaxed" lets go (shoulders down, easier sway).
struct Expression {
  ExpressionKind kind = ExpressionKind::strain;
  double start_s = 0.0;
  double end_s = 0.0;   // > start_s
  double amount = 1.0;  // [0, 1]
  friend bool operator==(const Expression&, const Expression&) = default;
};

// The pianist plays the note of `key` starting at `time_s` with `finger` (1 = thumb .. 5); the
// fingering is planned around it.
struct FingerPin {
  double time_s = 0.0;
  int key = 60;    // MIDI key, [0, 127]
  int finger = 1;  // [1, 5]
  friend bool operator==(const FingerPin&, const FingerPin&) = default;
};

// A brass player.
struct Performer {
  std::string name;            // unique in the scene, non-empty
  std::string instrument;      // id of content/instruments/<id>.json
  std::string part;            // the score part: its name (case-insensitive) or its id ("P2")
  int voice = 1;               // 1-based player within the part
  std::size_t music_file = 0;  // index into Scene::music
  Vec3 position_m;             // feet on the floor (y = 0 for the floor)
  double facing_deg = 0.0;     // 0 = facing +Z; [-360, 360]
  Stance stance = Stance::standing;
  bool music_stand = true;  // a music stand in front of the performer
  bool lead = false;        // gives the cues (at most one lead per scene)
  std::uint64_t seed = 0;   // as written, or derived from the scene seed (seed_given false)
  bool seed_given = false;
  Variation variation;
  // User assets (asset_mapping.hpp files), resolved against the scene file's folder; empty = the
  // default rig / the generated instrument.
  std::filesystem::path character_mapping;   // kind "character"
  std::filesystem::path instrument_mapping;  // kind "trumpet" or "trombone"
  BreathMarks breaths;
  std::vector<Expression> expressions;  // in start order
  friend bool operator==(const Performer&, const Performer&) = default;
};

// A keyboard player (a pianist, an organist, ...) at an instrument of their own. A scene has any
// number: "pianists" (an array), or "pianist" (one object,
// the format before two pianos could be written; still read).
struct Pianist {
  // Unique among the scene's keyboard players, non-empty; when not given, the instrument's player
  // ("pianist", "organist"), then "pianist 2", ...
  std::string name;
  // A keyboard instrument of content/piano/instruments.json: "piano" (default), "organ",
  // "harpsichord", "synth", ... Each has its own compass and model.
  std::string instrument = "piano";
  std::string pointer;             // where it is in the file ("/pianist", "/pianists/1")
  std::vector<std::string> parts;  // score parts the pianist plays (name or id), at least one
  std::size_t music_file = 0;      // index into Scene::music
  std::string hand_size;  // a preset of content/piano/hands.json (default: its default_preset)
  Vec3 position_m{0.0, 0.0, 0.6};  // the bench centre on the floor; the keys' front is at z = 0
  double facing_deg = 180.0;       // 180 = looking toward -Z, at the keyboard
  std::uint64_t seed = 0;
  bool seed_given = false;
  Variation variation;
  std::filesystem::path character_mapping;  // kind "character"
  std::filesystem::path hands_mapping;      // kind "hand"
  std::vector<FingerPin> pins;              // in file order (errors name the index)
  // A performance style of content/piano/styles.json: how the fingers strike (empty = the
  // stroke timing of finger_motion.json, every note struck exactly on time).
  std::string style;
  // The pianist's notes are heard as the simulated keys sound them (escapement times,
  // velocities from key speed, missed notes left out) instead of as written. Implies a style
  // ("precise" when none is given).
  bool sound_from_keys = false;
  friend bool operator==(const Pianist&, const Pianist&) = default;
};

// What a family's SceneSection (scene_section.hpp) read from its keys, as the family's own
// struct: families without a place of their own in Scene keep their players here.
struct FamilySection {
  std::string key;  // the top-level key it was read from, e.g. "strings"
  std::any data;    // the family's struct; Scene::section<T>(key) reads it
};

// A score part a player plays, for checking the parts against the music (check_scene_parts).
struct PartClaim {
  std::string part;            // name (case-insensitive) or id, as written
  std::size_t music_file = 0;  // index into Scene::music
  std::string pointer;         // where it is written, e.g. "/pianists/0/parts/1"
  std::string player;          // the player's JSON pointer, e.g. "/pianists/0"
  // A note has one player: no other player may claim an exclusive part of the same music
  // (keyboard players); players sharing a part by voice claim it non-exclusively.
  bool exclusive = false;
};

struct Camera {
  std::string name;  // unique, non-empty
  Vec3 position_m;
  Vec3 target_m;          // the point looked at (distinct from position_m)
  double fov_deg = 40.0;  // vertical field of view, [5, 120]
};

// From start_s on, `camera` is on screen until the next shot starts.
struct Shot {
  std::size_t camera = 0;  // index into Scene::cameras
  double start_s = 0.0;
};

struct DirectionalLight {
  Vec3 direction{0.0, -1.0, 0.0};  // the way the light travels; unit length after loading
  Color color{1.0, 1.0, 1.0};
  double intensity = 1.0;  // [0, 100]
};

struct Lights {
  DirectionalLight key{{-0.4, -1.0, -0.5}, {1.0, 0.96, 0.9}, 3.0};
  DirectionalLight fill{{0.6, -0.3, -0.4}, {0.8, 0.85, 1.0}, 0.6};
  Color ambient_sky{0.35, 0.38, 0.45};    // hemisphere light from above
  Color ambient_ground{0.15, 0.12, 0.1};  // ... and from below
};

struct Output {
  int width = 1280;  // pixels, even, [16, 7680]
  int height = 720;  // pixels, even, [16, 4320]
  int fps = 30;      // [1, 240]
  int msaa = 4;      // samples: 1, 2, 4 or 8
  // "hard": one filtered shadow-map comparison per pixel; "soft": four (wider penumbra, on
  // lavapipe about a fifth more time per frame at 720p).
  bool soft_shadows = false;
  Color background{0.02, 0.02, 0.03};
  double start_s = 0.0;         // [-60, 86400]; < 0 = a pre-roll before the music starts
  std::optional<double> end_s;  // nullopt = the end of the music; else > start_s
};

struct Scene {
  std::string source;  // scene file name, for messages
  std::string description;
  std::vector<std::filesystem::path> music;  // at least one; resolved, each an existing file
  std::uint64_t seed = 0;
  std::vector<Performer> performers;
  std::vector<Pianist> pianists;
  // Players of other families (their SceneSection's struct, by key), and every player's parts:
  // a scene has at least one player, so at least one claim.
  std::vector<FamilySection> sections;
  std::vector<PartClaim> part_claims;
  std::vector<Camera> cameras;     // at least one
  std::vector<Shot> shots;         // at least one; first at 0 s, start_s strictly increasing
  Lights lights;
  Output output;
  // The lead's cues: nullopt = one before the first entrance (automatic); else exactly these
  // entrance times, in order.
  std::optional<std::vector<double>> cues_s;

  // The shot on screen at t_s: the last one starting at or before t_s (the first one before 0).
  // Pure, O(log shots). Precondition: shots is not empty (true for every loaded scene).
  std::size_t shot_at(double t_s) const;
  const Camera& camera_at(double t_s) const { return cameras[shots[shot_at(t_s)].camera]; }
  // Index into cameras, -1 if none has this name.
  int find_camera(std::string_view name) const;
  // What the section read from `key` as T, or nullptr (no such key in the file, or not a T).
  template <class T>
  const T* section(std::string_view key) const {
    for (const FamilySection& s : sections) {
      if (s.key == key) return std::any_cast<T>(&s.data);
    }
    return nullptr;
  }
};

// Seed of a performer (stream k + 1 for performers[k]) or of a pianist (pianist_seed_stream)
// when the scene file gives none: splitmix64 of the scene seed and the stream, so adding a
// performer at the end leaves the others' seeds unchanged.
std::uint64_t derive_seed(std::uint64_t scene_seed, std::uint64_t stream);
// pianists[0]: stream 0 (as when a scene had one pianist); pianists[k]: a stream of their own,
// far above any performer's.
std::uint64_t pianist_seed_stream(std::size_t index);

std::string_view stance_name(Stance stance);
std::string_view expression_name(ExpressionKind kind);

}  // namespace tutti::scene
