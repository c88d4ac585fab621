// SPDX-License-Identifier: MIT
#include <tutti/key_action/note_strokes.hpp>

#include <gtest/gtest.h>

#include <cmath>

#include "key_action_fixture.hpp"

namespace tutti::key_action {
namespace {

NoteStrokes strokes_for(const music::Score& score, const PerformanceStyle& style,
                        std::uint64_t seed, fingering_planner::ScorePlan* fingering_out = nullptr) {
  auto plan = piano_performance::plan_performance(score, test::content().model);
  EXPECT_TRUE(plan.ok());
  if (fingering_out != nullptr) *fingering_out = plan->fingering;
  return plan_note_strokes(score, plan->fingering, test::content().model.keyboard,
                           test::content().model.hand, apply_style(test::content().params, style),
                           test::content().action, style, seed);
}

TEST(NoteStrokes, LouderNotesAreFasterStrokes) {
  const music::Score score = test::simple_score({{60, 0.5, 0.3, 30}, {62, 1.0, 0.3, 100}});
  const NoteStrokes s = strokes_for(score, test::style("precise"), 1);
  ASSERT_EQ(s.strokes.size(), 2u);
  const double soft = s.strokes[0].bottom_s - s.strokes[0].stroke_start_s;
  const double loud = s.strokes[1].bottom_s - s.strokes[1].stroke_start_s;
  EXPECT_GT(soft, loud);
  EXPECT_GT(s.intents[1].key_speed_mm_s, s.intents[0].key_speed_mm_s);
  // The stroke is aimed so that escapement, not the key bed, falls on the written onset.
  EXPECT_LT(s.strokes[0].stroke_start_s, 0.5);
  EXPECT_GT(s.strokes[0].bottom_s, 0.5);
  EXPECT_DOUBLE_EQ(s.intents[0].sound_s, 0.5);  // precise: no motor noise
}

TEST(NoteStrokes, TheKeyTravelIsTheLeversAtTheContactPoint) {
  const music::Score score = test::simple_score({{60, 0.5, 0.3, 80}, {61, 1.0, 0.3, 80}});
  const NoteStrokes s = strokes_for(score, test::style("precise"), 1);
  const KeyAction& action = test::content().action;
  EXPECT_NEAR(s.strokes[0].travel_mm, action.white.travel_at_mm(s.intents[0].contact_y_mm), 0.05);
  EXPECT_NEAR(s.strokes[1].travel_mm, action.black.travel_at_mm(s.intents[1].contact_y_mm), 0.05);
  // A fingertip somewhere on the key, in front of the pivot: less travel than at the front edge.
  EXPECT_LT(s.strokes[0].travel_mm, action.white.front_dip_mm);
  EXPECT_GT(s.strokes[0].travel_mm, 0.5 * action.white.front_dip_mm);
}

TEST(NoteStrokes, FlatterFingersPressFurtherIn) {
  const music::Score score = test::simple_score({{64, 0.5, 0.3, 80}});
  PerformanceStyle flat = test::style("precise");
  flat.bend_scale = 0.4;
  const NoteStrokes curved = strokes_for(score, test::style("precise"), 1);
  const NoteStrokes flatter = strokes_for(score, flat, 1);
  EXPECT_GT(flatter.intents[0].contact_y_mm, curved.intents[0].contact_y_mm + 2.0);
  EXPECT_LT(flatter.strokes[0].travel_mm, curved.strokes[0].travel_mm);
}

TEST(NoteStrokes, TheSeedMovesOnlyANoisyStyle) {
  const music::Score score = test::scale_score();
  const NoteStrokes a = strokes_for(score, test::style("beginner"), 1);
  const NoteStrokes b = strokes_for(score, test::style("beginner"), 2);
  const NoteStrokes a_again = strokes_for(score, test::style("beginner"), 1);
  int differ = 0;
  for (std::size_t i = 0; i < a.strokes.size(); ++i) {
    differ += a.strokes[i].stroke_start_s != b.strokes[i].stroke_start_s;
    EXPECT_EQ(a.strokes[i].stroke_start_s, a_again.strokes[i].stroke_start_s);
    EXPECT_EQ(a.strokes[i].bottom_s, a_again.strokes[i].bottom_s);
  }
  EXPECT_GT(differ, 10);
  const NoteStrokes p1 = strokes_for(score, test::style("precise"), 1);
  const NoteStrokes p2 = strokes_for(score, test::style("precise"), 2);
  for (std::size_t i = 0; i < p1.strokes.size(); ++i) {
    EXPECT_EQ(p1.strokes[i].stroke_start_s, p2.strokes[i].stroke_start_s);
  }
}

TEST(NoteStrokes, ARepeatedKeyIsLetGoBeforeItsNextStroke) {
  const music::Score score = test::simple_score({{67, 0.5, 0.5, 80}, {67, 1.0, 0.5, 80}});
  const PerformanceStyle precise = test::style("precise");
  const NoteStrokes s = strokes_for(score, precise, 1);
  EXPECT_LE(s.strokes[0].release_s,
            s.strokes[1].stroke_start_s - precise.release_anticipation * precise.release_s + 1e-12);
  EXPECT_GT(s.strokes[0].release_s, s.strokes[0].bottom_s);
}

}  // namespace
}  // namespace tutti::key_action
