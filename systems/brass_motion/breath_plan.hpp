// SPDX-License-Identifier: MIT
#pragma once
// Where a brass player breathes, and how much air they have, over a whole line (Horii 2018's
// rules plus an air model). Plan once; evaluate_breath(plan, t) is pure and allocation-free.
//
// Rules (rest lengths in beats of the meter at that point, music/meter.hpp):
//   a rest >= 0.5 and < 1 beat   -> breathe during the rest;
//   a rest >= 1 and < 2 beats    -> breathe in its last beat;
//   a rest >= 2 beats            -> a preparatory motion, then the breath in its last two beats;
//   before the first entrance    -> a breath (as for a rest of >= 2 beats when there is room).
// Beyond the source: air drains while playing (faster when loud or high) and refills with each
// breath in proportion to its length; a phrase that outlasts the air raises `strain`; a
// catch-breath is inserted at the best place inside such a phrase when one exists (the note
// before it is shortened: LineNote offsets in `shortened`).
//
// Details (README.md in this folder):
//  - Only playable notes are played; unplayable ones (playable == false) count as rest. A note's
//    end is cut at the next played onset when they overlap.
//  - A rest is measured in beats of the meter (music::beat_length_at: 6/8 counts dotted
//    quarters), across time-signature changes; its windows ("last beat", "last two beats") are
//    found in beats and converted to seconds with score.tempo_map, so tempo changes inside a
//    rest are exact. The inhale fills the end of the window, at most inhale_max_s; a window
//    shorter than inhale_min_s gives no breath. The preparatory motion (prepared,
//    before_entrance) takes prepare_s before the inhale, not before the rest's start.
//  - Before the first entrance the window is its last two beats, extended before t = 0 at the
//    opening tempo when the music starts sooner (events may have negative times).
//  - Air starts at resting_air, drains while a note sounds at
//    (1 / capacity_s) × loudness factor × register factor per second (register: the written
//    pitch's place in line.instrument's range, else in the line's own range), is constant in
//    rests, and rises during an inhale by refill_per_s × its length (at most to 1) along a
//    smooth ease. Air never leaves [0, 1].
//  - Catch-breaths: when the air would fall below catch_reserve_air inside a phrase (notes
//    between two rule breaths), the best boundary between two of its notes up to that point is
//    chosen (README: the score), the note before it is shortened when the gap is too short, and
//    planning goes on from there (as often as needed). Where none fits, the player plays on
//    what is left, down to 0 (counted in out_of_air), and breathes at the first boundary that
//    fits.
//  - Breath marks (the editor's, BreathMarks) override the rules at one note boundary each: an
//    add mark makes the player breathe there (in the rest, or as a catch-breath when the rest is
//    shorter than inhale_min_s or the notes are contiguous), a remove mark forbids any breath
//    there (rule, catch-breath or before the entrance). Marked breaths are phrase boundaries for
//    the air model like rule breaths (README: breath marks).
// Deterministic: the same inputs give the same plan bit for bit.

#include <vector>

#include <tutti/brass_model/brass_line.hpp>
#include <tutti/brass_motion/breath_params.hpp>
#include <tutti/music/score.hpp>

namespace tutti::brass_motion {

// The brass model's names used here (systems/brass_model).
using brass_model::BrassLine;

enum class BreathKind { before_entrance, in_rest, last_beat, prepared, catch_breath };

struct BreathEvent {
  BreathKind kind = BreathKind::in_rest;
  double prepare_start_s = 0.0;  // = start_s unless kind == prepared / before_entrance
  double start_s = 0.0;          // inhaling from start_s to end_s
  double end_s = 0.0;
  double depth = 1.0;           // 0..1, how full the lungs get
  int before_note = -1;         // BrassLine::notes index of the note it precedes
  double window_start_s = 0.0;  // where the rule's window begins (rest start, last beat, last
                                // two beats; for a catch-breath = start_s); end = end_s
  double rest_beats = 0.0;      // the rest's length in beats of the meter (catch-breath: the
                                // gap before the next note, usually 0)
  bool marked = false;          // it exists because of an add mark (the rules gave none there)
};

// The editor's breath marks, times in seconds. A mark refers to the boundary before note n, n =
// the first played note whose onset is >= t (1 ns tolerance); a mark after the last onset (or
// not finite) refers to nothing and is ignored (BreathPlan::ignored_marks). Order and duplicates
// do not matter. A boundary that is both added and removed keeps no breath: the remove wins and
// the add counts as ignored.
struct BreathMarks {
  std::vector<double> add_s;     // breathe before the first note whose onset is >= t
  std::vector<double> remove_s;  // no breath before the first note whose onset is >= t
};

struct ShortenedNote {
  int note = -1;              // BrassLine::notes index
  double offset_s = 0.0;      // new, earlier end (room for a catch-breath)
  double offset_beats = 0.0;  // the same moment in quarter notes
};

// The air level between start_s and end_s: from `from` to `to`, linearly while a note drains it,
// along a minimum-jerk ease during an inhale. Before the first segment the air is
// BreathPlan::initial_air, between and after segments it stays at the previous segment's `to`.
struct AirSegment {
  double start_s = 0.0;
  double end_s = 0.0;
  double from = 0.0;
  double to = 0.0;
  bool inhale = false;
};

struct BreathPlan {
  std::vector<BreathEvent> events;       // in time order, [prepare_start_s, end_s] disjoint
  std::vector<ShortenedNote> shortened;  // in note order
  std::vector<AirSegment> air;           // in time order, disjoint
  double initial_air = 1.0;
  double strain_from_air = 0.25;  // BreathParams::strain_from_air
  // Figures for reports.
  double min_air = 1.0;     // lowest air level after the first breath (initial_air if none)
  double max_strain = 0.0;  // strain at min_air
  int catch_breaths = 0;  // the planner's (a marked catch-breath is not counted)
  int out_of_air = 0;     // stretches where the air reached 0 (no catch-breath fitted before)
  int skipped_rests = 0;  // rests long enough in beats but shorter than inhale_min_s (and not
                          // breathed in because of an add mark)
  int ignored_marks = 0;  // marks that refer to no boundary (after the last note, not finite,
                          // or an add overruled by a remove at the same boundary)
};

// Plans the breathing of one line. `score` supplies the tempo map and time signatures the
// line's notes were timed with. Never fails; an empty line gives an empty plan.
BreathPlan plan_breaths(const BrassLine& line, const music::Score& score,
                        const BreathParams& params);
// The same, honouring the editor's breath marks (empty marks = the 3-argument overload).
BreathPlan plan_breaths(const BrassLine& line, const music::Score& score,
                        const BreathParams& params, const BreathMarks& marks);

// What evaluate_breath returns (copied into components::Breath and Mouth::open each frame).
struct BreathState {
  double air = 1.0;        // 0..1
  double inhale = 0.0;     // 0..1
  double preparing = 0.0;  // 0..1
  double strain = 0.0;     // 0..1
  int breath_index = -1;   // event under way or last taken, -1 = none yet
};

// The breathing at time t (seconds, any value; NaN counts as before everything). Pure and
// allocation-free: binary searches over the plan's events and air segments. Air is continuous
// in t; inhale rises and falls smoothly (0 → 1 → 0, zero slope at both ends) over
// [start_s, end_s] and preparing likewise over [prepare_start_s, start_s]; strain is a smooth
// function of the air. breath_index counts an event from its prepare_start_s on.
BreathState evaluate_breath(const BreathPlan& plan, double t);

// Strain (0..1) at an air level: 0 at or above strain_from_air, 1 at 0, smoothstep between.
double strain_at_air(double air, double strain_from_air);

}  // namespace tutti::brass_motion
