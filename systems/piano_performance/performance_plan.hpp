// SPDX-License-Identifier: MIT
#pragma once
// A whole piano performance, offline: the fingering planner's fingers and corridors for each
// hand, then each hand's smooth path through its corridors (spline_motion), with a report of
// how well the path honours them.
//
// The corridors are repaired first (corridor_repair.hpp: transition gaps at legato hand jumps,
// contract fixes), so a run never fails because of one awkward moment; the report counts the
// repairs. A path that still cannot be planned leaves that hand's path empty and its reason in
// HandReport::path_error (the run itself succeeds). Only the fingering planner's errors (bad
// input notes) fail plan_performance.

#include <span>
#include <string>

#include <tutti/core/result.hpp>
#include <tutti/fingering_planner/plan_score.hpp>
#include <tutti/music/score.hpp>
#include <tutti/piano_performance/corridor_repair.hpp>
#include <tutti/piano_performance/idle_hand_room.hpp>
#include <tutti/spline_motion/path_report.hpp>
#include <tutti/spline_motion/smoothing.hpp>

namespace tutti::piano_performance {

struct PerformanceOptions {
  fingering_planner::PlanOptions fingering;
  spline_motion::PlanOptions path;
  RepairOptions repair;
  IdleRoomOptions idle_room;  // each hand out of the other's way while it does not play
};

struct HandReport {
  music::Hand hand = music::Hand::right;
  std::size_t notes = 0;   // notes this hand plays
  std::size_t events = 0;  // corridors from the fingering planner (notes starting together)
  CorridorRepair repair;   // the corridors actually planned through + what was repaired
  // The smoothed path checked against the corridors it was planned through (the repaired ones:
  // zero violations by construction) and against the planner's original corridors (violations
  // there are exactly the repaired jump moments, where the hand leaves early / arrives late).
  spline_motion::PathReport against_used;
  spline_motion::PathReport against_original;
  std::size_t diagnostics = 0;  // fingering diagnostics of this hand
  std::string path_error;       // non-empty = the path could not be planned (path left empty)
  double path_ms = 0.0;         // wall time: repair + path + reports (not deterministic)
};

struct PerformanceReport {
  spline_motion::SmoothingMode smoothing = spline_motion::SmoothingMode::monotone_quintic;  // both hands' paths
  HandReport right;
  HandReport left;
  double fingering_ms = 0.0;  // wall time of plan_score (not deterministic)
};

struct PianoPerformancePlan {
  fingering_planner::ScorePlan fingering;
  spline_motion::HandPath right_path;
  spline_motion::HandPath left_path;
  PerformanceReport report;
};

Result<PianoPerformancePlan> plan_performance(const music::Score& score,
                                              const fingering_planner::FingeringModel& model,
                                              const PerformanceOptions& options = {});

// The hands' paths (repair + path + reports) for a fingering planned already, e.g. by
// fingering_planner::replan_score_locally after a pin. report.fingering_ms is 0.
PianoPerformancePlan plan_performance_paths(fingering_planner::ScorePlan fingering,
                                            const PerformanceOptions& options = {});

// The other hand, for one hand's path: its corridors and its path (null = plan the hand alone).
struct OtherHand {
  std::span<const piano_model::HandCorridor> corridors;
  const spline_motion::HandPath* path = nullptr;
};

// One hand's repair + path + reports, from its corridors (exposed for tests and tools). With
// the other hand's path, this hand's idle gaps keep out of its way (idle_hand_room.hpp,
// options.idle_room; report.hand says which hand this is).
spline_motion::HandPath plan_hand_motion(const piano_model::HandCorridors& corridors,
                                         const PerformanceOptions& options, HandReport& report,
                                         const OtherHand& other_hand = {});

}  // namespace tutti::piano_performance
