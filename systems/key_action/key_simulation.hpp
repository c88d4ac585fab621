// SPDX-License-Identifier: MIT
#pragma once
// Sound from motion: every key's angle follows the fingertips that press it, and the notes are
// what the keys do. Offline, over the planned motion (finger_motion::evaluate_finger_pose), at a
// fixed step:
//  - a fingertip `d` mm below the key's top, `y` mm into the keys, holds the key at
//    atan(d / (pivot - y)), up to the key bed; with no finger on it the key's spring lifts it at
//    most bed angle / return_s;
//  - the note sounds when the key passes the escapement angle (time interpolated between steps),
//    with the velocity of the key's front-edge speed there; slower than the silent threshold,
//    the hammer never reaches the string (a missed note);
//  - a key that has not risen to its reset angle since it last escaped does not strike again
//    (missed: not reset);
//  - the note stops when the key rises past the damper angle.
// The result is a pure function of the motion and the key action: deterministic, bit for bit.

#include <cstdint>
#include <limits>
#include <vector>

#include <tutti/finger_motion/finger_pose_system.hpp>
#include <tutti/fingering_planner/plan_score.hpp>
#include <tutti/key_action/key_action_params.hpp>
#include <tutti/music/score.hpp>

namespace tutti::key_action {

enum class KeyOutcome : std::uint8_t {
  sounded,
  too_soft,    // escaped too slowly: the hammer did not reach the string
  not_reset,   // struck before the key had risen enough to strike again
  not_played,  // no finger played it (no hand or finger planned)
};

struct PlayedNote {
  KeyOutcome outcome = KeyOutcome::not_played;
  int key = 60;
  double onset_s = std::numeric_limits<double>::quiet_NaN();   // escapement
  double offset_s = std::numeric_limits<double>::quiet_NaN();  // damper back on the string
  double key_speed_mm_s = 0.0;  // key-front speed at escapement (0 when it never escaped)
  int velocity = 0;             // 1..127 when sounded
};

struct KeySimulationOptions {
  double step_s = 0.0005;  // sampling step of the motion (> 0)
};

// One PlayedNote per Score note (index = Score::notes index). A chord note that shares its
// finger with a neighbouring key (more than five keys in a hand) sounds with that contact.
std::vector<PlayedNote> simulate_keys(const music::Score& score,
                                      const fingering_planner::ScorePlan& fingering,
                                      const finger_motion::PianistMotion& motion,
                                      const KeyAction& action,
                                      const KeySimulationOptions& options = {});

const char* outcome_name(KeyOutcome outcome);

}  // namespace tutti::key_action
