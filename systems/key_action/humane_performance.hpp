// SPDX-License-Identifier: MIT
#pragma once
// A pianist's performance in a style, from the fingering and the hands' paths: strokes
// (note_strokes.hpp), the finger motion they make (finger_motion, with each contact's key travel
// from the key lever), and what the keys do with it (key_simulation.hpp) — what you see pressing
// is what you hear. Offline; deterministic for a seed.

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/finger_motion/finger_motion_params.hpp>
#include <tutti/finger_motion/finger_pose_system.hpp>
#include <tutti/fingering_planner/plan_score.hpp>
#include <tutti/key_action/key_action_params.hpp>
#include <tutti/key_action/key_simulation.hpp>
#include <tutti/key_action/note_strokes.hpp>
#include <tutti/key_action/performance_report.hpp>
#include <tutti/key_action/performance_style.hpp>
#include <tutti/music/score.hpp>
#include <tutti/piano_model/hand_model.hpp>
#include <tutti/piano_model/keyboard.hpp>
#include <tutti/spline_motion/hand_path.hpp>

namespace tutti::key_action {

struct HumaneInputs {
  const music::Score* score = nullptr;
  const fingering_planner::ScorePlan* fingering = nullptr;
  const spline_motion::HandPath* right_path = nullptr;
  const spline_motion::HandPath* left_path = nullptr;
  const piano_model::Keyboard* keyboard = nullptr;
  const piano_model::HandModel* hand_model = nullptr;
  const finger_motion::FingerMotionParams* params = nullptr;  // content's, before the style
  const KeyAction* action = nullptr;
  const PerformanceStyle* style = nullptr;
  std::uint64_t seed = 0;
};

struct HumanePerformance {
  std::shared_ptr<finger_motion::PianistMotion> motion;
  NoteStrokes strokes;
  std::vector<PlayedNote> played;  // one per Score note
  PerformanceReport report;
};

// Errors: the finger-motion planner's (bad notes or plans); every input must be set.
Result<HumanePerformance> perform(const HumaneInputs& in, const KeySimulationOptions& options = {});

// The score as heard: every note with a PlayedNote that sounded gets its played onset, offset and
// velocity (seconds exact, ticks rounded through the tempo map), notes that did not sound are
// left out, notes nobody played (other parts) are kept as written. Note order is kept. A note
// sounded before time 0 (motor noise on a first note) starts at 0.
music::Score performed_score(const music::Score& score, std::span<const PlayedNote> played);

}  // namespace tutti::key_action
