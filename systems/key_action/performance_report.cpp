// SPDX-License-Identifier: MIT
#include <tutti/key_action/performance_report.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tutti::key_action {

PerformanceReport report_performance(const music::Score& score,
                                     std::span<const PlayedNote> played) {
  PerformanceReport r;
  double sum = 0.0, sum_abs = 0.0, sum_sq = 0.0;
  double v_sum = 0.0, v_sq = 0.0, v_err = 0.0;
  r.velocity_min = 127;
  for (std::size_t i = 0; i < played.size() && i < score.notes.size(); ++i) {
    const PlayedNote& p = played[i];
    if (p.outcome == KeyOutcome::not_played) continue;
    ++r.notes;
    if (p.outcome == KeyOutcome::too_soft) ++r.too_soft;
    if (p.outcome == KeyOutcome::not_reset) ++r.not_reset;
    if (p.outcome != KeyOutcome::sounded) continue;
    ++r.sounded;
    const double error_ms = 1000.0 * (p.onset_s - score.notes[i].onset_s);
    sum += error_ms;
    sum_abs += std::abs(error_ms);
    sum_sq += error_ms * error_ms;
    r.onset_max_abs_ms = std::max(r.onset_max_abs_ms, std::abs(error_ms));
    r.velocity_min = std::min(r.velocity_min, p.velocity);
    r.velocity_max = std::max(r.velocity_max, p.velocity);
    v_sum += p.velocity;
    v_sq += static_cast<double>(p.velocity) * p.velocity;
    v_err += std::abs(p.velocity - score.notes[i].velocity);
  }
  if (r.sounded == 0) {
    r.velocity_min = 0;
    return r;
  }
  const double n = static_cast<double>(r.sounded);
  r.onset_mean_ms = sum / n;
  r.onset_mean_abs_ms = sum_abs / n;
  r.onset_std_ms = std::sqrt(std::max(0.0, sum_sq / n - r.onset_mean_ms * r.onset_mean_ms));
  r.velocity_mean = v_sum / n;
  r.velocity_std = std::sqrt(std::max(0.0, v_sq / n - r.velocity_mean * r.velocity_mean));
  r.velocity_error_mean_abs = v_err / n;
  return r;
}

std::string format_report(const PerformanceReport& r) {
  char line[400];
  std::snprintf(line, sizeof line,
                "sounded %zu/%zu (too soft %zu, not reset %zu); onset error mean %.2f ms, "
                "|mean| %.2f, std %.2f, max %.2f ms; velocity %d..%d (mean %.1f, std %.1f, "
                "|error| %.1f)",
                r.sounded, r.notes, r.too_soft, r.not_reset, r.onset_mean_ms, r.onset_mean_abs_ms,
                r.onset_std_ms, r.onset_max_abs_ms, r.velocity_min, r.velocity_max, r.velocity_mean,
                r.velocity_std, r.velocity_error_mean_abs);
  return line;
}

}  // namespace tutti::key_action
