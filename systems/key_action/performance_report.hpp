// SPDX-License-Identifier: MIT
#pragma once
// What a style made of a piece: how far the sounded onsets are from the written ones, how the
// velocities spread, how many notes did not sound and why.

#include <cstddef>
#include <span>
#include <string>

#include <tutti/key_action/key_simulation.hpp>
#include <tutti/music/score.hpp>

namespace tutti::key_action {

struct PerformanceReport {
  std::size_t notes = 0;  // notes the pianist played (a hand and finger planned)
  std::size_t sounded = 0;
  std::size_t too_soft = 0;
  std::size_t not_reset = 0;
  // Sounded onset - written onset, milliseconds.
  double onset_mean_ms = 0.0;      // signed mean (> 0 = late)
  double onset_mean_abs_ms = 0.0;  // mean |error|
  double onset_std_ms = 0.0;
  double onset_max_abs_ms = 0.0;
  // Velocities of the sounded notes, and their difference from the written ones.
  int velocity_min = 0;
  int velocity_max = 0;
  double velocity_mean = 0.0;
  double velocity_std = 0.0;
  double velocity_error_mean_abs = 0.0;  // mean |played - written|
  std::size_t missed() const { return too_soft + not_reset; }
};

PerformanceReport report_performance(const music::Score& score, std::span<const PlayedNote> played);

// "sounded 120/122 (too soft 1, not reset 1); onset error mean 0.4 ms, |mean| 0.6, std 0.5,
// max 1.9 ms; velocity 52..96 (mean 78.1, std 9.2, |error| 3.4)".
std::string format_report(const PerformanceReport& report);

}  // namespace tutti::key_action
