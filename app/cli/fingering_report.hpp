// SPDX-License-Identifier: MIT
#pragma once
// The human-readable report `tutti fingering` prints: per hand notes, corridor violations
// (against the corridors the path was planned through and against the planner's originals),
// peak speed and acceleration, repairs, diagnostics (the first few lines), planning speed.

#include <string>

#include <tutti/music/score.hpp>
#include <tutti/piano_performance/performance_plan.hpp>

namespace tutti::cli {

std::string fingering_report_text(const music::Score& score,
                                  const piano_performance::PianoPerformancePlan& plan,
                                  int max_diagnostic_lines = 5);

}  // namespace tutti::cli
