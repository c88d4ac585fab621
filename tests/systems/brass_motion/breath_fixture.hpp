// SPDX-License-Identifier: MIT
#pragma once
// Hand-made scores and lines for the breath tests: a tempo, a meter, notes placed in quarter
// notes and timed through the score's own tempo map.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include <tutti/brass_model/brass_line.hpp>
#include <tutti/brass_motion/breath_params.hpp>
#include <tutti/brass_motion/breath_plan.hpp>
#include <tutti/music/score.hpp>

namespace tutti::brass_motion::test {

using brass_model::BrassLine;
using brass_model::LineNote;

inline std::filesystem::path content_dir() { return TUTTI_CONTENT_DIR; }

// Fixed values (the documented defaults, as shipped in content/brass/breath.json), so the
// expected timings below do not move when the content file is tuned.
inline BreathParams fixed_params() {
  BreathParams p;
  p.inhale_min_s = 0.15;
  p.inhale_max_s = 1.0;
  p.refill_per_s = 1.25;
  p.prepare_s = 0.6;
  p.resting_air = 0.45;
  p.capacity_s = 8.0;
  p.mf_velocity = 80;
  p.drain_soft = 0.6;
  p.drain_loud = 1.8;
  p.drain_low = 0.85;
  p.drain_high = 1.4;
  p.strain_from_air = 0.25;
  p.catch_reserve_air = 0.1;
  p.catch_inhale_s = 0.25;
  p.catch_min_s = 0.12;
  p.catch_max_cut = 0.4;
  p.catch_below_air = 0.5;
  p.catch_strong_beat_bonus = 0.5;
  return p;
}

constexpr int kTicksPerQuarter = 480;

inline music::Score score_at(double bpm, int numerator = 4, int denominator = 4) {
  music::Score score;
  score.tempo_map = music::TempoMap::with_ticks_per_quarter(kTicksPerQuarter);
  score.tempo_map.set_tempo(0, 60'000'000.0 / bpm);
  score.time_signatures.push_back({0, 0.0, numerator, denominator});
  return score;
}

inline std::int64_t tick_of(double quarters) {
  return static_cast<std::int64_t>(std::llround(quarters * kTicksPerQuarter));
}

inline LineNote note_q(const music::Score& score, double onset_q, double offset_q, int written = 72,
                       int velocity = 80, bool playable = true) {
  LineNote n;
  n.onset_beats = onset_q;
  n.offset_beats = offset_q;
  n.onset_s = score.tempo_map.seconds_at_beats(onset_q);
  n.offset_s = score.tempo_map.seconds_at_beats(offset_q);
  n.written = written;
  n.sounding = written;
  n.velocity = velocity;
  n.playable = playable;
  return n;
}

inline BrassLine line_of(std::vector<LineNote> notes) {
  BrassLine line;
  line.part_name = "test";
  line.part = 0;
  line.notes = std::move(notes);
  return line;
}

// The largest |d air / dt| anywhere in the plan (an inhale's minimum-jerk ease peaks at 1.875
// times its mean slope).
inline double max_air_slope(const BreathPlan& plan) {
  double slope = 0.0;
  for (const AirSegment& s : plan.air) {
    slope =
        std::max(slope, std::abs(s.to - s.from) / (s.end_s - s.start_s) * (s.inhale ? 1.875 : 1.0));
  }
  return slope;
}

// Air, inhale and preparing change by at most what their slopes allow between close samples,
// and never leave [0, 1].
inline void expect_continuous(const BreathPlan& plan, double from_s, double to_s) {
  const double dt = 1e-4;
  const double air_limit = max_air_slope(plan) * dt * 1.001 + 1e-12;
  double shortest = 1e9;
  for (const BreathEvent& e : plan.events) {
    if (e.end_s > e.start_s) shortest = std::min(shortest, e.end_s - e.start_s);
    if (e.start_s > e.prepare_start_s) shortest = std::min(shortest, e.start_s - e.prepare_start_s);
  }
  const double bump_limit = 3.1416 / shortest * dt * 1.001 + 1e-12;  // max slope of sin²(πu)
  BreathState before = evaluate_breath(plan, from_s);
  int failures = 0;
  for (double t = from_s + dt; t <= to_s && failures < 5; t += dt) {
    const BreathState now = evaluate_breath(plan, t);
    const bool ok = std::abs(now.air - before.air) <= air_limit &&
                    std::abs(now.inhale - before.inhale) <= bump_limit &&
                    std::abs(now.preparing - before.preparing) <= bump_limit && now.air >= 0.0 &&
                    now.air <= 1.0 && now.strain >= 0.0 && now.strain <= 1.0;
    if (!ok) {
      ++failures;
      ADD_FAILURE() << "jump at t = " << t << ": air " << before.air << " -> " << now.air
                    << ", inhale " << before.inhale << " -> " << now.inhale << ", preparing "
                    << before.preparing << " -> " << now.preparing;
    }
    before = now;
  }
}

}  // namespace tutti::brass_motion::test
