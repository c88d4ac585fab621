// SPDX-License-Identifier: MIT
#pragma once
// The brass family's players as its scene section reads them ("performers", format in
// scene/README.md): kept in Scene::sections under kBrassPlayersKey, as every family keeps its
// own, so that the scene knows no instrument.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <tutti/scene/scene.hpp>

namespace tutti::brass {

struct BrassPlayer {
  std::string name;            // unique in the scene, non-empty
  std::string instrument;      // id of content/instruments/<id>.json
  std::string part;            // the score part: its name (case-insensitive) or its id ("P2")
  int voice = 1;               // 1-based player within the part
  std::size_t music_file = 0;  // index into Scene::music
  scene::Vec3 position_m;      // feet on the floor (y = 0 for the floor)
  double facing_deg = 0.0;     // 0 = facing +Z; [-360, 360]
  scene::Stance stance = scene::Stance::standing;
  bool music_stand = true;  // a music stand in front of the performer
  bool lead = false;        // gives the cues (at most one lead per scene)
  // As written, or derived from the scene seed (seed_given false): stream k + 1 for the k-th
  // player, so adding one at the end leaves the others' seeds unchanged.
  std::uint64_t seed = 0;
  bool seed_given = false;
  scene::Variation variation;
  // User assets (asset_mapping.hpp files), resolved against the scene file's folder; empty = the
  // default rig / the generated instrument.
  std::filesystem::path character_mapping;   // kind "character"
  std::filesystem::path instrument_mapping;  // kind "trumpet" or "trombone"
  scene::BreathMarks breaths;
  std::vector<scene::Expression> expressions;  // in start order
  friend bool operator==(const BrassPlayer&, const BrassPlayer&) = default;
};

// The key of Scene::sections that holds them (the scene file's key).
inline constexpr std::string_view kBrassPlayersKey = "performers";

// The scene's brass players in file order (none when the scene has no "performers").
inline const std::vector<BrassPlayer>& brass_players(const scene::Scene& scene) {
  return scene.section_or_empty<std::vector<BrassPlayer>>(kBrassPlayersKey);
}

// The same, to change (the section reading them, or a tool's edited copy of a loaded scene); an
// empty list is added when there is none.
inline std::vector<BrassPlayer>& edit_brass_players(scene::Scene& scene) {
  return scene.section_or_add<std::vector<BrassPlayer>>(kBrassPlayersKey);
}

}  // namespace tutti::brass
