// SPDX-License-Identifier: MIT
#pragma once
// From a style to strokes: how each note is struck (finger_motion::NoteStroke), offline.
//
// The player means each note to sound at its written onset with its written velocity. For a
// note on finger f they pick the stroke that would do it: the key speed at escapement that gives
// the velocity (times the style's strength), hence a stroke duration T (within the style's
// fastest/slowest), and start it so that escapement falls on the onset, knowing where their
// fingertip meets the key (the contact point's key travel and lever, from the finger's bend and
// reach). Then the finger executes it at its own speed: T / finger_speed[f], with the style's
// seeded motor noise on the start time and the speed. A precise player's fingers do what is
// meant; a beginner's weak fingers arrive late and soft. A key the same key's next note
// repeats is let go release_anticipation x release_s before that note's stroke starts (less
// anticipation: the key has not risen when it is struck again).
//
// The noise is keyed on (seed, hand, finger, written onset), so it does not depend on the note
// order and chord notes sharing a finger get the same stroke.

#include <cstdint>
#include <span>
#include <vector>

#include <tutti/finger_motion/finger_motion_params.hpp>
#include <tutti/finger_motion/plan_finger_motion.hpp>
#include <tutti/fingering_planner/plan_score.hpp>
#include <tutti/key_action/key_action_params.hpp>
#include <tutti/key_action/performance_style.hpp>
#include <tutti/music/score.hpp>
#include <tutti/piano_model/hand_model.hpp>
#include <tutti/piano_model/keyboard.hpp>

namespace tutti::key_action {

// What the stroke planner meant for one note (reports and tests compare the outcome with it).
struct StrokeIntent {
  double sound_s = 0.0;         // when escapement was meant to happen (onset + motor noise)
  double key_speed_mm_s = 0.0;  // the key-front speed at escapement meant (from the velocity)
  double lever_ratio = 1.0;     // key-front speed / fingertip speed at the contact point
  double contact_y_mm = 0.0;    // where the tip meets the key, into the keys
};

struct NoteStrokes {
  std::vector<finger_motion::NoteStroke> strokes;  // one per Score note
  std::vector<StrokeIntent> intents;               // one per Score note
};

// `params`: the finger-motion parameters with the style applied (apply_style). Notes without a
// hand or finger (not played) get the default stroke (bottom at the onset).
NoteStrokes plan_note_strokes(const music::Score& score,
                              const fingering_planner::ScorePlan& fingering,
                              const piano_model::Keyboard& keyboard,
                              const piano_model::HandModel& hand_model,
                              const finger_motion::FingerMotionParams& params,
                              const KeyAction& action, const PerformanceStyle& style,
                              std::uint64_t seed);

}  // namespace tutti::key_action
