// SPDX-License-Identifier: MIT
#include <tutti/cli/fingering_report.hpp>

#include <cstdio>
#include <string>

namespace tutti::cli {
namespace {

// snprintf into a string of the needed size (a natural-spline path's peaks can be huge numbers).
template <typename... Args>
std::string format(const char* pattern, Args... args) {
  const int size = std::snprintf(nullptr, 0, pattern, args...);
  if (size <= 0) return {};
  std::string text(static_cast<std::size_t>(size) + 1, '\0');
  std::snprintf(text.data(), text.size(), pattern, args...);
  text.pop_back();
  return text;
}

std::string hand_text(const char* name, const piano_performance::HandReport& h) {
  std::string text = format(
      "%s hand: %zu notes, %zu events, %zu diagnostics; path: %zu violations (planned "
      "corridors, worst %.1f mm), %zu violations (original corridors, worst %.1f mm); peak "
      "speed %.0f mm/s, peak acceleration %.0f mm/s^2; repairs: %d jumps, %d sanitized, %d "
      "dropped\n",
      name, h.notes, h.events, h.diagnostics, h.against_used.violating_corridors,
      h.against_used.worst_violation_mm, h.against_original.violating_corridors,
      h.against_original.worst_violation_mm, h.against_used.peak_speed_mm_per_s,
      h.against_used.peak_acceleration_mm_per_s2, h.repair.jumps, h.repair.sanitized,
      h.repair.dropped);
  if (!h.path_error.empty()) text += "  path not planned: " + h.path_error + "\n";
  return text;
}

}  // namespace

std::string fingering_report_text(const music::Score& score,
                                  const piano_performance::PianoPerformancePlan& plan,
                                  int max_diagnostic_lines) {
  const piano_performance::PerformanceReport& r = plan.report;
  std::string text = format("hand paths: %s smoothing\n", spline_motion::to_string(r.smoothing)) +
                     hand_text("right", r.right) + hand_text("left", r.left);
  const double ms = r.fingering_ms + r.right.path_ms + r.left.path_ms;
  const std::size_t notes = score.notes.size();
  text += format("planned %zu notes in %.1f ms (%.0f notes/s; fingering %.1f ms, paths %.1f ms)\n",
                 notes, ms, ms > 0.0 ? 1000.0 * double(notes) / ms : 0.0, r.fingering_ms,
                 r.right.path_ms + r.left.path_ms);
  int shown = 0;
  for (const fingering_planner::HandPlan* hand : {&plan.fingering.right, &plan.fingering.left}) {
    for (const fingering_planner::Diagnostic& d : hand->diagnostics) {
      if (shown++ >= max_diagnostic_lines) break;
      text += "  " + std::string(fingering_planner::diagnostic_kind_name(d.kind)) + ": " +
              d.message + "\n";
    }
  }
  const std::size_t total = r.right.diagnostics + r.left.diagnostics;
  if (total > static_cast<std::size_t>(max_diagnostic_lines)) {
    text += format("  ... %zu diagnostics in all\n", total);
  }
  return text;
}

}  // namespace tutti::cli
