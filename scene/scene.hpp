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

// What a family's SceneSection (scene_section.hpp) read from its keys, as the family's own
// struct: every family keeps its players here (the scene knows no instrument).
struct FamilySection {
  std::string key;  // the top-level key it was read from, e.g. "strings"
  std::any data;    // the family's struct; Scene::section<T>(key) reads it
};

// A score part a player plays, for checking the parts against the music (check_scene_parts).
struct PartClaim {
  std::string part;            // name (case-insensitive) or id, as written
  std::size_t music_file = 0;  // index into Scene::music
  std::string pointer;         // where it is written, e.g. "/<key>/0/parts/1"
  std::string player;          // the player's JSON pointer, e.g. "/<key>/0"
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
  // The families' players (their SceneSection's struct, by key), and every player's parts: a
  // scene has at least one player, so at least one claim.
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
  // What `key` holds as T, or an empty T (one static T) when nothing is there: a family's list,
  // read without a null check.
  template <class T>
  const T& section_or_empty(std::string_view key) const {
    static const T empty{};
    const T* found = section<T>(key);
    return found != nullptr ? *found : empty;
  }
  // The same, to change; a T is added under `key` when there is none. Precondition: what `key`
  // holds, if anything, is a T.
  template <class T>
  T& section_or_add(std::string_view key) {
    for (FamilySection& s : sections) {
      if (s.key == key) return std::any_cast<T&>(s.data);
    }
    sections.push_back({std::string(key), T{}});
    return std::any_cast<T&>(sections.back().data);
  }
};

// Seed of a player when the scene file gives none: splitmix64 of the scene seed and a stream of
// the player's own (each family numbers its players' streams), so adding a player at the end
// leaves the others' seeds unchanged.
std::uint64_t derive_seed(std::uint64_t scene_seed, std::uint64_t stream);

std::string_view stance_name(Stance stance);
std::string_view expression_name(ExpressionKind kind);

}  // namespace tutti::scene
