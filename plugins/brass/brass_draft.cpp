// SPDX-License-Identifier: MIT
// The brass family's part of `tutti scene new` (stage/family_draft.hpp): each brass part its name
// or General MIDI program names gets as many players as it has voices; they sit in a shallow arc
// by section (trumpets, horns, trombones, euphoniums, tubas from the audience's left), the first
// one leads; cameras frame each section and each player, and the lead from the side.
#include <tutti/brass/brass_plugin.hpp>

#include <algorithm>
#include <cctype>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include <tutti/brass_model/instrument.hpp>
#include <tutti/fingering_planner/brass_lines.hpp>
#include <tutti/stage/family_draft.hpp>

namespace tutti::brass {
namespace {

using nlohmann::ordered_json;

// Sections in seating order, from the audience's left.
struct Section {
  std::string_view model;
  std::string_view word;  // for player names: "Trumpet 1"
};
constexpr Section kSections[] = {{"trumpet", "Trumpet"},
                                 {"horn", "Horn"},
                                 {"trombone", "Trombone"},
                                 {"euphonium", "Euphonium"},
                                 {"tuba", "Tuba"}};

std::size_t section_of(const brass_model::Instrument& instrument) {
  for (std::size_t s = 0; s < std::size(kSections); ++s) {
    if (instrument.model_name() == kSections[s].model) return s;
  }
  return std::size(kSections) - 1;
}

struct Player {
  std::string name;
  std::string camera_stem;  // "trumpet_1"
  const brass_model::Instrument* instrument = nullptr;
  int part = 0;
  int voice = 1;
  std::size_t section = 0;
  double x = 0.0;
  double z = 0.0;
  double facing_deg = 0.0;
};

std::string camera_stem_of(const std::string& name) {
  std::string stem;
  for (char c : name) {
    stem += std::isalnum(static_cast<unsigned char>(c)) != 0
                ? static_cast<char>(std::tolower(static_cast<unsigned char>(c)))
                : '_';
  }
  return stem;
}

// Seated players in a shallow arc (content/scenes/quintet.json's seating, for any number): one
// metre apart, the middle ones forward, each turned a little toward the middle.
void seat_in_arc(std::vector<Player>& players, double centre_x) {
  const double n = static_cast<double>(players.size());
  const double half = (n - 1.0) / 2.0;
  for (std::size_t i = 0; i < players.size(); ++i) {
    const double offset = static_cast<double>(i) - half;
    players[i].x = centre_x + offset;
    players[i].z = half > 0 ? 0.6 * (1.0 - (offset / half) * (offset / half)) : 0.6;
    players[i].facing_deg = std::clamp(-10.0 * offset, -30.0, 30.0);
  }
}

// The brass parts among `parts`, as find_brass_parts recognises them.
std::vector<fingering_planner::BrassPart> brass_parts_among(
    const music::Score& score, std::span<const int> parts,
    const std::vector<brass_model::Instrument>& known) {
  std::vector<fingering_planner::BrassPart> found;
  for (const fingering_planner::BrassPart& b : fingering_planner::find_brass_parts(score, known)) {
    if (std::find(parts.begin(), parts.end(), b.part) != parts.end()) found.push_back(b);
  }
  return found;
}

}  // namespace

Result<std::vector<int>> BrassPlugin::draft_recognise(const music::Score& score,
                                                      std::span<const int> available) const {
  auto known = brass_model::load_all_instruments();
  if (!known) return known.error();
  std::vector<int> parts;
  for (const fingering_planner::BrassPart& b : brass_parts_among(score, available, *known)) {
    parts.push_back(b.part);
  }
  return parts;
}

Result<stage::FamilyDraft> BrassPlugin::draft(const music::Score& score,
                                              std::span<const int> parts,
                                              const stage::DraftPlace& place) const {
  auto known = brass_model::load_all_instruments();
  if (!known) return known.error();
  const std::vector<fingering_planner::BrassPart> found = brass_parts_among(score, parts, *known);

  // Players, by section, then part order, then voice.
  std::vector<Player> players;
  for (const fingering_planner::BrassPart& b : found) {
    for (int v = 0; v < b.voices; ++v) {
      Player player;
      player.instrument = b.instrument;
      player.part = b.part;
      player.voice = v + 1;
      player.section = section_of(*b.instrument);
      players.push_back(player);
    }
  }
  std::stable_sort(players.begin(), players.end(),
                   [](const Player& a, const Player& b) { return a.section < b.section; });
  std::map<std::size_t, int> section_sizes;
  for (const Player& p : players) ++section_sizes[p.section];
  std::map<std::size_t, int> numbered;
  for (Player& p : players) {
    const int n = ++numbered[p.section];
    p.name = std::string(kSections[p.section].word);
    if (section_sizes[p.section] > 1) p.name += " " + std::to_string(n);
    p.camera_stem = camera_stem_of(p.name);
  }
  const double arc_centre = place.origin_x;
  seat_in_arc(players, arc_centre);

  stage::FamilyDraft draft;
  for (const auto& [section, count] : section_sizes) {
    draft.summary += (draft.summary.empty() ? "" : ", ") + std::to_string(count) + " " +
                     std::string(kSections[section].model) + (count > 1 ? "s" : "");
  }
  ordered_json performers = ordered_json::array();
  for (std::size_t i = 0; i < players.size(); ++i) {
    const Player& p = players[i];
    ordered_json performer{{"name", p.name},
                           {"instrument", p.instrument->id},
                           {"part", stage::draft_part_reference(score, p.part)},
                           {"position_m", stage::draft_vec3(p.x, 0.0, p.z)},
                           {"facing_deg", stage::draft_round_mm(p.facing_deg)},
                           {"stance", "seated"},
                           {"music_stand", false}};
    if (p.voice != 1) performer["voice"] = p.voice;
    if (i == 0) performer["lead"] = true;
    performers.push_back(std::move(performer));
  }
  if (players.empty()) return draft;
  draft.section.emplace_back("performers", std::move(performers));
  draft.left_m = players.front().x;
  draft.right_m = players.back().x;
  // The lead's cue comes a beat before the first entrance: start early enough to see it.
  draft.pre_roll_s = 2.0;

  // Cameras: each section of two or more (unless it is everyone), each player from the front,
  // the lead from the side too.
  std::map<std::size_t, stage::DraftedGroup> groups;
  for (const auto& [section, count] : section_sizes) {
    stage::DraftedGroup& group = groups[section];
    group.name = std::string(kSections[section].model);
    if (count < 2 || count == static_cast<int>(players.size())) continue;
    double l = 1e9;
    double r = -1e9;
    for (const Player& p : players) {
      if (p.section == section) l = std::min(l, p.x), r = std::max(r, p.x);
    }
    const std::string name = std::string(kSections[section].model) + "s";
    draft.cameras.push_back(stage::draft_wide_camera(name, l - 0.6, r + 0.6, 0.8, 32.0));
    group.cameras.push_back(name);
  }
  for (std::size_t i = 0; i < players.size(); ++i) {
    const Player& p = players[i];
    const auto [cx, cz] = stage::draft_ahead(p.x, p.z, p.facing_deg, 2.3);
    const auto [tx, tz] = stage::draft_ahead(p.x, p.z, p.facing_deg, 0.1);
    draft.cameras.push_back(
        stage::draft_camera(p.camera_stem + "_front", cx, 1.3, cz, tx, 1.0, tz, 30.0));
    stage::DraftedGroup& group = groups[p.section];
    group.cameras.push_back(p.camera_stem + "_front");
    if (std::find(group.parts.begin(), group.parts.end(), p.part) == group.parts.end()) {
      group.parts.push_back(p.part);
    }
    if (i == 0) {
      const auto [sx, sz] = stage::draft_ahead(
          p.x, p.z, p.facing_deg + (p.x <= arc_centre ? -45.0 : 45.0), 1.34);
      draft.cameras.push_back(
          stage::draft_camera(p.camera_stem + "_side", sx, 1.3, sz, tx, 0.98, tz, 38.0));
      group.cameras.insert(group.cameras.begin() + 1, p.camera_stem + "_side");
    }
  }
  for (auto& [section, group] : groups) draft.groups.push_back(std::move(group));
  return draft;
}

}  // namespace tutti::brass
