// SPDX-License-Identifier: MIT
#include <tutti/piano_performance/performance_plan.hpp>

#include <chrono>
#include <cmath>

namespace tutti::piano_performance {
namespace {

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// The originals minus those no check can mean anything for (non-finite or reversed: the repair
// dropped or rewrote them, and says so).
piano_model::HandCorridors well_formed(const piano_model::HandCorridors& corridors) {
  piano_model::HandCorridors out;
  out.reserve(corridors.size());
  for (const piano_model::HandCorridor& c : corridors) {
    if (std::isfinite(c.start_s) && std::isfinite(c.end_s) && std::isfinite(c.lo_mm) &&
        std::isfinite(c.hi_mm) && c.start_s <= c.end_s && c.lo_mm <= c.hi_mm) {
      out.push_back(c);
    }
  }
  return out;
}

}  // namespace

spline_motion::HandPath plan_hand_motion(const piano_model::HandCorridors& corridors,
                                         const PerformanceOptions& options, HandReport& report,
                                         const OtherHand& other_hand) {
  const auto start = std::chrono::steady_clock::now();
  report.events = corridors.size();
  report.repair = repair_corridors(
      other_hand.path == nullptr
          ? corridors
          : with_idle_room(corridors, other_hand.corridors, *other_hand.path, report.hand,
                           options.idle_room),
      options.repair);
  auto path = plan_hand_path(report.repair.corridors, options.path);
  spline_motion::HandPath result;
  if (path) {
    result = std::move(*path);
    report.against_used = spline_motion::corridor_violations(result, report.repair.corridors);
    report.against_original = spline_motion::corridor_violations(result, well_formed(corridors));
  } else {
    report.path_error = path.error().message;
  }
  report.path_ms = ms_since(start);
  return result;
}

PianoPerformancePlan plan_performance_paths(fingering_planner::ScorePlan fingering,
                                            const PerformanceOptions& options) {
  PianoPerformancePlan plan;
  plan.fingering = std::move(fingering);
  plan.report.smoothing = options.path.smoothing;

  HandReport& right = plan.report.right;
  right.hand = music::Hand::right;
  right.notes = plan.fingering.right_notes.size();
  right.diagnostics = plan.fingering.right.diagnostics.size();
  plan.right_path = plan_hand_motion(plan.fingering.right.corridors, options, right);

  HandReport& left = plan.report.left;
  left.hand = music::Hand::left;
  left.notes = plan.fingering.left_notes.size();
  left.diagnostics = plan.fingering.left.diagnostics.size();
  plan.left_path = plan_hand_motion(plan.fingering.left.corridors, options, left,
                                    {plan.fingering.right.corridors, &plan.right_path});
  // The right hand again, its idle moments clear of the left hand's path (the left hand's idle
  // moments were kept clear of the first right path; this one only moves further from it).
  plan.right_path = plan_hand_motion(plan.fingering.right.corridors, options, right,
                                     {plan.fingering.left.corridors, &plan.left_path});
  return plan;
}

Result<PianoPerformancePlan> plan_performance(const music::Score& score,
                                              const fingering_planner::FingeringModel& model,
                                              const PerformanceOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  auto fingering = fingering_planner::plan_score(score, model, options.fingering);
  if (!fingering) return fingering.error();
  const double fingering_ms = ms_since(start);
  PianoPerformancePlan plan = plan_performance_paths(std::move(*fingering), options);
  plan.report.fingering_ms = fingering_ms;
  return plan;
}

}  // namespace tutti::piano_performance
