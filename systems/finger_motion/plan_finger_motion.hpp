// SPDX-License-Identifier: MIT
#pragma once
// Planning (offline, allocates): Score + fingering + hand paths -> FingerMotionPlan.
//
// For each Score note with a planned hand and finger (ScorePlan::hands / ::fingers), one key
// contact on that hand's finger. Per finger, contacts are sorted by onset; two at the same onset
// (the fingering planner shares a finger when more than five keys sound) merge into the first,
// keeping the later offset. Keys off the keyboard are clamped to its ends.
//
// Timing (StrokeTiming), for a contact after the same finger's previous one:
//  - stroke: starts press_lead_s before the onset (not before the previous onset);
//  - the previous offset is trimmed to the stroke start, so the key rises before it is struck
//  again;
//  - a key the other hand strikes beside (at most a whole tone toward the holding hand's side)
//  or beyond, within press_lead_s + release_s after its offset, is let go that early: it is up
//  before the other finger starts down (never before its own onset);
//  - lateral move: minimum-jerk, duration clamp(move_min_s + move_s_per_mm x distance, min, max),
//    ending at the onset and starting no earlier than the previous offset (late and quick);
//  - bend and hover height adapt over shape_s before the stroke (not before the previous offset).
//
// Where the hands come onto each other, the crossing one is lifted over the other
// (pass_over.hpp, params.pass_over).
//
// With `strokes` (one per Score note), each contact's onset is the stroke's bottom_s, its stroke
// start, offset and key travel the stroke's (the same clamps to the finger's previous contact
// apply).
//
// Errors (one line, naming the note index): plan or stroke sizes that do not match the score, a
// finger outside 0..5, a non-finite time, offset < onset.

#include <span>

#include <tutti/core/result.hpp>
#include <tutti/finger_motion/finger_motion_params.hpp>
#include <tutti/finger_motion/finger_motion_plan.hpp>
#include <tutti/fingering_planner/plan_score.hpp>
#include <tutti/music/score.hpp>
#include <tutti/piano_model/hand_model.hpp>
#include <tutti/piano_model/keyboard.hpp>
#include <tutti/spline_motion/hand_path.hpp>

namespace tutti::finger_motion {

// How one note is struck when a performance style decides it (systems/key_action): the stroke
// leaves hover height at stroke_start_s and reaches the key bed, travel_mm below the key's top,
// at bottom_s; the finger lets the key go at release_s. Without strokes, every note is struck
// with the StrokeTiming defaults: bottom at the written onset, press_lead_s before it, released
// at the written offset, travel = keys.dip_mm.
struct NoteStroke {
  double stroke_start_s = 0.0;  // < bottom_s
  double bottom_s = 0.0;
  double release_s = 0.0;   // clamped to >= bottom_s
  double travel_mm = 10.0;  // > 0
};

// `right_path` / `left_path`: the hands' planned paths (used for each release's lateral offset).
// Phalanx lengths and root heights are scaled by hand_model.scale().
Result<FingerMotionPlan> plan_finger_motion(
    const music::Score& score, const fingering_planner::ScorePlan& score_plan,
    const spline_motion::HandPath& right_path, const spline_motion::HandPath& left_path,
    const piano_model::Keyboard& keyboard, const piano_model::HandModel& hand_model,
    const FingerMotionParams& params, std::span<const NoteStroke> strokes = {});

// The finger geometry plan_finger_motion uses: params' lengths and root heights scaled by the
// hand model.
std::array<FingerGeometry, 5> scaled_geometry(const FingerMotionParams& params,
                                              const piano_model::HandModel& hand_model);

}  // namespace tutti::finger_motion
