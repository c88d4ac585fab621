// SPDX-License-Identifier: MIT
#pragma once
// Helpers shared by the fingering planner tests.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <tutti/fingering_planner/fingering_model.hpp>
#include <tutti/fingering_planner/hand_plan.hpp>

namespace tutti::fingering_planner::test {

inline const FingeringModel& model(const std::string& weights) {
  static const FingeringModel paper = [] {
    auto m = load_fingering_model("paper");
    if (!m) ADD_FAILURE() << m.error().message;
    return m ? *m : FingeringModel{};
  }();
  static const FingeringModel defaults = [] {
    auto m = load_fingering_model("default");
    if (!m) ADD_FAILURE() << m.error().message;
    return m ? *m : FingeringModel{};
  }();
  return weights == "paper" ? paper : defaults;
}

// A legato melody: one note every `step_s` seconds, each held until the next.
inline std::vector<PlanNote> melody(const std::vector<int>& keys, double step_s = 0.25) {
  std::vector<PlanNote> notes;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    notes.push_back({keys[i], double(i) * step_s, double(i + 1) * step_s, 0});
  }
  return notes;
}

inline std::string fingers_text(const std::vector<int>& fingers) {
  std::string text;
  for (int f : fingers) text += std::to_string(f);
  return text;
}

}  // namespace tutti::fingering_planner::test
