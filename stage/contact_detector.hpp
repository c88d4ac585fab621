// SPDX-License-Identifier: MIT
#pragma once
// The one contact detector: where the evaluated components reach their stops, read on a time
// grid. What a stop is belongs to the family whose players reach it: each family names the kinds
// of stop it reports (StopKind: the host API's event name, how `sync-report` reads it) and gives
// a tracker that watches its own components at every grid time (FamilyPlugin::track_stops). The
// detector only runs the frame and asks the trackers, family by family in the stage's order.
// The performance's events (performance.hpp), `sync-report` and the C API all read these stops.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <ostream>
#include <string_view>
#include <vector>

#include <tutti/ecs/world.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::stage {

// A stop kind's name: text that lives as long as the program and ends in a NUL, because the C
// API hands it to hosts as a C string (tutti_event_kind_name). Only a constant made from a
// string literal converts to it: a std::string or a buffer on the stack does not compile.
class StopName {
 public:
  template <std::size_t N>
  consteval StopName(const char (&literal)[N]) : text_(literal, N - 1) {}  // NOLINT: implicit
  constexpr operator std::string_view() const { return text_; }            // NOLINT: implicit
  constexpr std::string_view view() const { return text_; }
  constexpr const char* c_str() const { return text_.data(); }
  constexpr bool empty() const { return text_.empty(); }
  friend constexpr bool operator==(StopName a, std::string_view b) { return a.text_ == b; }
  friend std::ostream& operator<<(std::ostream& out, StopName name) { return out << name.text_; }

 private:
  std::string_view text_;
};

// A kind of stop, declared once by the family that reports it (a static object: stops point at
// it, and two stops are of one kind when they point at the same one).
struct StopKind {
  // The host API's event kind (performance::event_kinds(), the C API's tutti_event_kind_name);
  // families reporting the same name share the kind there.
  StopName name;
  // `sync-report`: a sound starts here, named so in its report; empty: no sound starts (a key
  // coming back up).
  std::string_view sync_label;
  // A host event; false when another event already says it (a tongue: the note's note_on).
  bool host_event = true;
};

struct Stop {
  double t_s = 0.0;
  const StopKind* kind = nullptr;
  ecs::Entity performer = ecs::Entity::null;  // the Performer entity (null: none known)
  std::int32_t value = -1;                    // what the kind says: a MIDI key, a valve number
  // Whether the player sounds at that sample and the next (a slide moving in a rest makes no
  // sound); true where the stop itself makes the sound (a key).
  bool sounding = true;
};

struct StopGrid {
  double from_s = 0.0;
  double to_s = 0.0;
  double step_s = 0.001;
  bool include_end = false;  // a last sample at (or just past) to_s
};

// One grid time: the stage's evaluate phase has just run at `t`.
struct StopSample {
  double previous_t = 0.0;  // the previous grid time (== t on the first)
  double t = 0.0;
  bool first = false;  // nothing is crossed on the first sample: there is no sample before it
};

// A family's watch over its components for one run of the detector. Made on the stage's world
// before the first sample (it finds its entities there); sample() is called after every grid
// time's evaluate phase and appends the stops crossed since the previous one, placed between
// the two samples where they can be (linear interpolation), else at the sample that sees them. It
// may also set `sounding` on stops it appended at the previous sample (their indices stay valid:
// stops are only appended).
class StopTracker {
 public:
  virtual ~StopTracker() = default;
  virtual void sample(const ecs::World& world, const StopSample& sample,
                      std::vector<Stop>& stops) = 0;
};

// Runs the stage's evaluate phase at every grid time and returns the stops in the order they
// were found: per sample, family by family in the stage's order, each in its tracker's order.
// Leaves the stage evaluated at the grid's last time. Nothing for a step <= 0 or an empty range.
std::vector<Stop> detect_stops(Stage& stage, const StopGrid& grid);
// The same in a caller's sampling context (Stage::make_context): const on the stage, the same
// stops; the context is left evaluated at the grid's last time.
std::vector<Stop> detect_stops(const Stage& stage, StageContext& context, const StopGrid& grid);

// For trackers: a pressed thing (a key under a finger, a pedal under a foot) whose press depth
// runs from 0 (up) to 1 (at its bed). Down when the depth crosses 0.999 upward with a key
// given, up (the key that went down) when it falls back past 0.001; both placed between samples.
struct PressTrack {
  ecs::Entity entity = ecs::Entity::null;     // what carries the depth (a Finger, a Foot)
  ecs::Entity performer = ecs::Entity::null;
  double depth = 0.0;
  std::int32_t key_down = -1;  // the key held at its bed
};
void track_press(PressTrack& track, double depth, std::int32_t key, const StopSample& sample,
                 const StopKind& down, const StopKind& up, std::vector<Stop>& stops);

// Where a value crossing `level` between (t0, v0) and (t1, v1) crosses it, linearly.
double stop_crossing(double t0, double v0, double t1, double v1, double level);

// The levels a pressed key, pedal or valve is at its bed (down) or back at its top (up).
inline constexpr double kStopFullyDown = 0.999;
inline constexpr double kStopFullyUp = 0.001;

}  // namespace tutti::stage
