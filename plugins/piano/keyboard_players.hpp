// SPDX-License-Identifier: MIT
#pragma once
// The keyboard family's players as its scene section reads them ("pianists", or the older
// "pianist"; format in scene/README.md): kept in Scene::sections under kKeyboardPlayersKey, as
// every family keeps its own, so that the scene knows no instrument.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <tutti/scene/scene.hpp>

namespace tutti::piano {

// The player plays the note of `key` starting at `time_s` with `finger` (1 = thumb .. 5); the
// fingering is planned around it.
struct FingerPin {
  double time_s = 0.0;
  int key = 60;    // MIDI key, [0, 127]
  int finger = 1;  // [1, 5]
  friend bool operator==(const FingerPin&, const FingerPin&) = default;
};

// A keyboard player (a pianist, an organist, ...) at an instrument of their own.
struct KeyboardPlayer {
  // Unique among the scene's keyboard players, non-empty; when not given, the instrument's player
  // ("pianist", "organist"), then "pianist 2", ...
  std::string name;
  // A keyboard instrument of content/piano/instruments.json: "piano" (default), "organ",
  // "harpsichord", "synth", ... Each has its own compass and model.
  std::string instrument = "piano";
  std::string pointer;             // where it is in the file ("/pianist", "/pianists/1")
  std::vector<std::string> parts;  // score parts the player plays (name or id), at least one
  std::size_t music_file = 0;      // index into Scene::music
  std::string hand_size;  // a preset of content/piano/hands.json (default: its default_preset)
  scene::Vec3 position_m{0.0, 0.0, 0.6};  // the bench centre on the floor; the keys' front at z 0
  double facing_deg = 180.0;              // 180 = looking toward -Z, at the keyboard
  // As written, or derived from the scene seed (seed_given false; keyboard_seed_stream).
  std::uint64_t seed = 0;
  bool seed_given = false;
  scene::Variation variation;
  std::filesystem::path character_mapping;  // kind "character"
  std::filesystem::path hands_mapping;      // kind "hand"
  std::vector<FingerPin> pins;              // in file order (errors name the index)
  // A performance style of content/piano/styles.json: how the fingers strike (empty = the
  // stroke timing of finger_motion.json, every note struck exactly on time).
  std::string style;
  // The player's notes are heard as the simulated keys sound them (escapement times, velocities
  // from key speed, missed notes left out) instead of as written. Implies a style ("precise"
  // when none is given).
  bool sound_from_keys = false;
  friend bool operator==(const KeyboardPlayer&, const KeyboardPlayer&) = default;
};

// The seed stream of the index-th keyboard player (scene::derive_seed): the first has stream 0
// (as when a scene had one pianist); the k-th one of its own, far above any brass player's.
std::uint64_t keyboard_seed_stream(std::size_t index);

// The key of Scene::sections that holds them; "pianist" (one object) is read into it too.
inline constexpr std::string_view kKeyboardPlayersKey = "pianists";

// The scene's keyboard players in file order (none when the scene has none).
inline const std::vector<KeyboardPlayer>& keyboard_players(const scene::Scene& scene) {
  return scene.section_or_empty<std::vector<KeyboardPlayer>>(kKeyboardPlayersKey);
}

// The same, to change (the section reading them, or a tool's edited copy of a loaded scene); an
// empty list is added when there is none.
inline std::vector<KeyboardPlayer>& edit_keyboard_players(scene::Scene& scene) {
  return scene.section_or_add<std::vector<KeyboardPlayer>>(kKeyboardPlayersKey);
}

}  // namespace tutti::piano
