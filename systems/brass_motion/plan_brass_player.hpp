#pragma once
// Everything one brass player does, planned together from a fingered line: the breaths first
// (they may shorten a note to make room for a catch-breath), then valves, slide and embouchure
// on the line as it will actually be played.

#include <tutti/brass_model/brass_line.hpp>
#include <tutti/brass_motion/brass_motion_params.hpp>
#include <tutti/brass_motion/brass_pose_system.hpp>
#include <tutti/brass_motion/breath_params.hpp>
#include <tutti/music/score.hpp>

namespace tutti::brass {

// The line with the breath plan's shortened notes applied (offsets moved earlier).
BrassLine as_played(const BrassLine& line, const BreathPlan& breaths);

// `line` must have its fingerings (plan_line); `window` is the planner's change window; `marks`
// are the editor's breath marks (plan_breaths).
BrassPlayerMotion plan_brass_player(const BrassLine& line, const music::Score& score,
                                    const BrassMotionParams& motion, const BreathParams& breath,
                                    const ChangeWindow& window, const BreathMarks& marks = {});

}  // namespace tutti::brass
