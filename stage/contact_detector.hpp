// SPDX-License-Identifier: MIT
#pragma once
// The one contact detector: where the evaluated components reach their stops, read on a time
// grid. A finger's key reaching its bed (press depth crossing 0.999) and leaving it (0.001), a
// foot's pedal the same, a valve reaching its bottom and its top, a slide coming to rest, a player starting to sound.
// The performance's events (performance.hpp), `sync-report` and the C API all read these.
//
// Each stop is placed between two samples by linear interpolation (slides and tongues at the
// sample that sees them). `sounding` says whether the player sounds at that sample and the next
// (a slide moving in a rest makes no sound); always true for keys.

#include <cstdint>
#include <vector>

#include <tutti/ecs/world.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::stage {

enum class StopKind : std::uint8_t {
  key_down,       // value: MIDI key
  key_up,         // value: MIDI key (the one that went down)
  valve_down,     // value: valve number, 1-based
  valve_up,       // value: valve number
  slide_arrives,  // value: the position, rounded (1..7)
  tongue,         // the player starts to sound; value: -1
  pedal_down,     // a foot's pedal reaches its bottom; value: MIDI key
  pedal_up,       // value: MIDI key (the one that went down)
};

struct Stop {
  double t_s = 0.0;
  StopKind kind = StopKind::key_down;
  ecs::Entity performer = ecs::Entity::null;  // the Performer entity (null: none known)
  std::int32_t value = -1;
  bool sounding = true;
};

struct StopGrid {
  double from_s = 0.0;
  double to_s = 0.0;
  double step_s = 0.001;
  bool include_end = false;  // a last sample at (or just past) to_s
};

// Runs the stage's evaluate phase at every grid time and returns the stops in the order they
// were found: per sample, fingers, feet, then instruments, each in spawn order. Leaves the stage
// evaluated at the grid's last time. Nothing for a step <= 0 or an empty range.
std::vector<Stop> detect_stops(Stage& stage, const StopGrid& grid);

}  // namespace tutti::stage
