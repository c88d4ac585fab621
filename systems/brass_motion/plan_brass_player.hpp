// SPDX-License-Identifier: MIT
#pragma once
// Everything one brass player does, planned together from a fingered line: the breaths first
// (they may shorten a note to make room for a catch-breath), then valves, slide and embouchure
// on the line as it will actually be played.

#include <tutti/brass_model/brass_line.hpp>
#include <tutti/brass_motion/brass_motion_params.hpp>
#include <tutti/brass_motion/brass_pose_system.hpp>
#include <tutti/brass_motion/breath_params.hpp>
#include <tutti/fingering_planner/brass_planner.hpp>
#include <tutti/music/score.hpp>

namespace tutti::brass_motion {

// The brass planner's names used here (systems/fingering_planner).
using fingering_planner::BrassPlanSummary;
using fingering_planner::PlannerWeights;

// The brass model's names used here (systems/brass_model).
using brass_model::BrassLine;
using brass_model::ChangeWindow;

// The line with the breath plan's shortened notes applied (offsets moved earlier).
BrassLine as_played(const BrassLine& line, const BreathPlan& breaths);

// Chooses the line's fingerings (plan_line) on the line as it will be played: the breaths are
// planned first (they do not depend on the fingering), so a note shortened for a catch-breath
// gives the slide the time it frees (a trombone's F3 before a breath can take a far alternate
// and still reach first position for the next entry). Offsets in `line` are left as written.
BrassPlanSummary plan_line_around_breaths(BrassLine& line, const music::Score& score,
                                          const PlannerWeights& weights, const BreathParams& breath,
                                          const BreathMarks& marks = {});

// `line` must have its fingerings (plan_line); `window` is the planner's change window; `marks`
// are the editor's breath marks (plan_breaths).
BrassPlayerMotion plan_brass_player(const BrassLine& line, const music::Score& score,
                                    const BrassMotionParams& motion, const BreathParams& breath,
                                    const ChangeWindow& window, const BreathMarks& marks = {});

}  // namespace tutti::brass_motion
