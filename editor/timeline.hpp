// SPDX-License-Identifier: MIT
#pragma once
// What the editor's timeline shows, read from a planned stage: bar lines and beats from the tempo
// map and time signatures, each player's notes and planned breaths (marked or by the rules),
// their expressions, the lead's cues, the camera cuts, and for a player whose notes have fingers
// each note's finger (pinned or planned) with the hands' allowed areas and paths. Rebuilt after
// every re-plan.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <tutti/scene/scene.hpp>
#include <tutti/stage/player_view.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::editor {

struct TimelineNote {
  double start_s = 0.0;
  double end_s = 0.0;
  int key = 60;
  int finger = 0;  // 1..5 as planned (0 = none: the player's notes have no fingers)
  bool pinned = false;
  bool right_hand = true;
  bool playable = true;
  // A note played by a foot (0 right, 1 left: an organ's pedals); -1 = the hands'.
  int foot = -1;
};

struct TimelineBreath {
  double prepare_s = 0.0;  // the preparation's start (= start_s for most)
  double start_s = 0.0;    // inhaling from start_s to end_s
  double end_s = 0.0;
  double boundary_s = 0.0;  // the onset of the note it precedes: how the scene names it
  bool marked = false;      // there because of a breath mark
  bool catch_breath = false;
};

// The allowed hand positions of one event (keyboard x, mm).
using HandCorridorView = stage::HandBand;

struct TimelineLane {
  std::string name;
  std::string family;     // the family that plays it (stage::Seat::family)
  std::size_t index = 0;  // which of the family's players (stage::Seat::index)
  std::string player;     // where the scene file writes the player: a JSON pointer (edits go there)
  // Its notes carry the hand and finger that play them, and may be pinned to a finger (`pins`).
  bool fingered = false;
  // It breathes by the rules (a BreathSchedule): breath marks apply.
  bool breathes = false;
  // Its family takes expression spans (the player's "expressions").
  bool expressive = false;
  // For the inspector, as the family describes the player (stage::PlayerView).
  std::string summary;
  scene::Variation variation;
  std::uint64_t seed = 0;
  std::vector<stage::PinView> pins;
  std::vector<TimelineNote> notes;
  std::vector<TimelineBreath> breaths;
  std::vector<scene::Expression> expressions;
  int lowest_key = 127;
  int highest_key = 0;
  std::array<std::vector<HandCorridorView>, 2> corridors;  // a fingered player's: right, left
  // The planned hand path through them, sampled every kHandPathStep_s: (time, keyboard x mm).
  std::array<std::vector<std::array<double, 2>>, 2> hand_path;
};

struct Timeline {
  double start_s = 0.0;
  double end_s = 0.0;
  std::vector<double> bars_s;       // bar lines
  std::vector<double> beats_s;      // every beat (bar lines included)
  std::vector<TimelineLane> lanes;  // the stage's performers in order (family by family)
  std::vector<double> cues_s;       // the lead's cues as planned (the entrance times)
  bool cues_automatic = true;       // the scene lists none
  struct Shot {
    double start_s = 0.0;
    std::string camera;
  };
  std::vector<Shot> shots;
};

using stage::kHandPathStep_s;

Timeline build_timeline(const stage::Stage& stage);

// The first bar line or beat within `tolerance_s` of t, else t: clicks snap to the grid.
double snap_to_beat(const Timeline& timeline, double t, double tolerance_s);

}  // namespace tutti::editor
