// SPDX-License-Identifier: MIT
// Whole pieces through fingering + repair + path: every note fingered, the path never leaves the
// corridors it was planned through, deterministic.
#include <tutti/piano_performance/performance_plan.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include <tutti/music/load_score.hpp>
#include "testdata.hpp"

namespace tutti::piano_performance {
namespace {

const fingering_planner::FingeringModel& default_model() {
  static const fingering_planner::FingeringModel m = [] {
    auto loaded = fingering_planner::load_fingering_model("default");
    EXPECT_TRUE(loaded.ok()) << (loaded.ok() ? "" : loaded.error().message);
    return loaded.ok() ? std::move(*loaded) : fingering_planner::FingeringModel{};
  }();
  return m;
}

void expect_hand_sound(const HandReport& hand, const char* name) {
  SCOPED_TRACE(name);
  EXPECT_TRUE(hand.path_error.empty()) << hand.path_error;
  EXPECT_EQ(hand.against_used.violating_corridors, 0u)
      << "worst " << hand.against_used.worst_violation_mm << " mm at "
      << hand.against_used.worst_t_s << " s";
  // Every original corridor violation is a repaired moment.
  if (hand.repair.total() == 0) {
    EXPECT_EQ(hand.against_original.violating_corridors, 0u);
  }
}

PianoPerformancePlan check_piece(const std::filesystem::path& file) {
  SCOPED_TRACE(file.string());
  auto score = music::load_score(file);
  EXPECT_TRUE(score.ok()) << (score.ok() ? "" : score.error().message);
  if (!score) return {};
  auto plan = plan_performance(*score, default_model());
  EXPECT_TRUE(plan.ok()) << (plan.ok() ? "" : plan.error().message);
  if (!plan) return {};
  for (std::size_t i = 0; i < score->notes.size(); ++i) {
    if (score->parts[score->notes[i].part].percussion) continue;
    EXPECT_GE(plan->fingering.fingers[i], 1) << "note " << i;
    EXPECT_LE(plan->fingering.fingers[i], 5) << "note " << i;
  }
  expect_hand_sound(plan->report.right, "right");
  expect_hand_sound(plan->report.left, "left");
  EXPECT_EQ(plan->report.right.notes + plan->report.left.notes, score->notes.size());
  std::printf(
      "%-40s notes %5zu  jumps R %3d L %3d  violations(original) R %zu L %zu  peak %.0f/%.0f "
      "mm/s\n",
      file.filename().string().c_str(), score->notes.size(), plan->report.right.repair.jumps,
      plan->report.left.repair.jumps, plan->report.right.against_original.violating_corridors,
      plan->report.left.against_original.violating_corridors,
      plan->report.right.against_used.peak_speed_mm_per_s,
      plan->report.left.against_used.peak_speed_mm_per_s);
  return std::move(*plan);
}

TEST(PerformancePlan, OdeToJoy) {
  const auto plan = check_piece(tutti::test::source_dir() / "content/music/ode_to_joy.musicxml");
  EXPECT_FALSE(plan.right_path.empty());
}

TEST(PerformancePlan, PianoplayerPieces) {
  TUTTI_REQUIRE_TESTDATA();
  const auto dir = tutti::test::testdata("musicxml/pianoplayer");
  int pieces = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const auto ext = entry.path().extension();
    if (ext != ".xml" && ext != ".mxl") continue;
    check_piece(entry.path());
    ++pieces;
  }
  EXPECT_GE(pieces, 8);
}

TEST(PerformancePlan, Bach846HasRepairsAndStaysInside) {
  TUTTI_REQUIRE_TESTDATA();
  const auto plan = check_piece(tutti::test::testdata("midi/tonejs/bach_846.mid"));
  EXPECT_FALSE(plan.right_path.empty());
  EXPECT_FALSE(plan.left_path.empty());
}

TEST(PerformancePlan, Deterministic) {
  const auto file = tutti::test::source_dir() / "content/music/ode_to_joy.musicxml";
  auto score = music::load_score(file);
  ASSERT_TRUE(score.ok());
  auto a = plan_performance(*score, default_model());
  auto b = plan_performance(*score, default_model());
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(a->fingering.fingers, b->fingering.fingers);
  ASSERT_EQ(a->right_path.knot_times().size(), b->right_path.knot_times().size());
  for (double t = 0.0; t < score->end_s; t += 0.01) {
    EXPECT_EQ(spline_motion::evaluate(a->right_path, t).x_mm, spline_motion::evaluate(b->right_path, t).x_mm);
  }
}

}  // namespace
}  // namespace tutti::piano_performance
