// SPDX-License-Identifier: MIT
#pragma once
// Hand-made inputs for the ensemble tests: a 4/4 score at 120 BPM (a beat is 0.5 s), breath
// plans from (prepare, start, end) triples, and a player on stage from 2 s to 30 s.

#include <array>
#include <cstdint>
#include <vector>

#include <tutti/ensemble_variation/ensemble_plan.hpp>
#include <tutti/music/score.hpp>

namespace tutti::ensemble_variation::test {

inline music::Score four_four() {
  music::Score score;
  score.source = "four_four";
  music::TimeSignature ts;
  ts.numerator = 4;
  ts.denominator = 4;
  score.time_signatures.push_back(ts);
  return score;
}

using Breaths = std::vector<BreathInput>;

inline Breaths breaths(std::vector<std::array<double, 3>> events) {
  Breaths plan;
  for (const auto& e : events) {
    BreathInput b;
    b.prepare_start_s = e[0];
    b.start_s = e[1];
    b.end_s = e[2];
    b.depth = 1.0;
    plan.push_back(b);
  }
  return plan;
}

inline PerformerInput player(const music::Score& score, const Breaths& plan,
                             std::uint64_t seed, bool lead) {
  PerformerInput in;
  in.seed = seed;
  in.params = draw_variation(seed);
  in.lead = lead;
  in.score = &score;
  in.breaths = plan;
  in.first_onset_s = 2.0;
  in.last_offset_s = 30.0;
  return in;
}

}  // namespace tutti::ensemble_variation::test
