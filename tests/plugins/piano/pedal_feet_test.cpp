// SPDX-License-Identifier: MIT
#include <tutti/piano/pedal_feet.hpp>

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include <tutti/piano_model/keyboard_instruments.hpp>
#include <tutti/piano_model/pedal_geometry.hpp>

namespace tutti::piano {
namespace {

// The organ's pedalboard as content/piano/instruments.json has it (AGO: C2-G4, 63.5 mm).
piano_model::Pedalboard ago_board() {
  piano_model::Pedalboard board;
  board.lowest_key = 36;
  board.highest_key = 67;
  board.natural_spacing_mm = 63.5;
  board.split_below = 48;
  board.names = {"pedal", "pédale"};
  return board;
}

music::Note note(int pitch, double onset_s, double offset_s, int part = 0, int staff = 0) {
  music::Note n;
  n.pitch = pitch;
  n.onset_s = onset_s;
  n.offset_s = offset_s;
  n.part = part;
  n.staff = staff;
  return n;
}

music::Score score_of(std::vector<music::Note> notes, std::vector<std::string> part_names = {""}) {
  music::Score score;
  for (const std::string& name : part_names) {
    music::Part part;
    part.name = name;
    score.parts.push_back(part);
  }
  score.notes = std::move(notes);
  return score;
}

TEST(PedalNotes, APartNamedAsThePedalsIsTheFeets) {
  const music::Score score = score_of(
      {note(40, 0, 1, 0), note(60, 0, 1, 0), note(38, 0, 1, 1), note(50, 1, 2, 1)},
      {"Manual", "Orgel Pédale"});
  EXPECT_EQ(choose_pedal_notes(score, ago_board()), (std::vector<bool>{false, false, true, true}))
      << "a part named so is the pedals', whatever the pitches";
}

TEST(PedalNotes, TheThirdStaffOfAnOrganPart) {
  const music::Score score =
      score_of({note(40, 0, 1, 0, 2), note(60, 0, 1, 0, 1), note(52, 0, 1, 0, 3), note(36, 1, 2, 0, 2)});
  EXPECT_EQ(choose_pedal_notes(score, ago_board()), (std::vector<bool>{false, false, true, false}));
}

TEST(PedalNotes, TheLowestOfSeveralPartsWhenItIsALineInThePedalsRegister) {
  // A bass under a tenor: the bass's every note, including those above the split.
  const music::Score chorale = score_of({note(60, 0, 1, 0), note(43, 0, 1, 1), note(62, 1, 2, 0),
                                         note(50, 1, 2, 1), note(64, 2, 3, 0), note(55, 2, 3, 1)},
                                        {"Tenor", "Bass"});
  EXPECT_EQ(choose_pedal_notes(chorale, ago_board()),
            (std::vector<bool>{false, true, false, true, false, true}));
  // A lowest part of chords is no line: the split decides.
  const music::Score chords = score_of({note(60, 0, 1, 0), note(40, 0, 1, 1), note(52, 0, 1, 1),
                                        note(62, 1, 2, 0), note(50, 1, 2, 1), note(45, 1, 2, 1)},
                                       {"Right", "Left"});
  EXPECT_EQ(choose_pedal_notes(chords, ago_board()),
            (std::vector<bool>{false, true, false, false, false, true}));
}

TEST(PedalNotes, ElseTheLowestNoteOfEachOnsetBelowTheSplit) {
  const music::Score score = score_of({note(43, 0, 1), note(31, 0, 1), note(60, 0, 1),  // G1 lowest
                                       note(48, 1, 2), note(55, 1, 2),                  // C3: not below
                                       note(47, 2, 3), note(64, 2, 3)});                // B2
  EXPECT_EQ(choose_pedal_notes(score, ago_board()),
            (std::vector<bool>{false, true, false, false, false, true, false}));
}

// A foot holds at most one pedal at a time, and between two of its presses it has the time to
// let the first up, get to the second and press it.
void expect_feet_never_in_two_places(const FeetPlan& plan) {
  for (const auto& mine : plan.by_foot) {
    for (std::size_t j = 0; j < mine.size(); ++j) {
      const PedalPress& p = plan.presses[mine[j]];
      EXPECT_GE(p.up_s, p.down_s);
      if (j == 0) continue;
      const PedalPress& before = plan.presses[mine[j - 1]];
      EXPECT_LE(before.up_s + FootTiming::release_s + FootTiming::press_s,
                p.down_s + 1e-9)
          << "foot " << p.foot << " at " << p.down_s << " s";
    }
  }
}

TEST(PlanFeet, EachFootKeepsToItsSideOfTheBoard) {
  // Slow notes, far apart in time: the left foot takes the low ones, the right the high ones.
  std::vector<music::Note> notes;
  const int keys[] = {36, 64, 38, 65, 40, 62, 41, 67};
  for (int i = 0; i < 8; ++i) notes.push_back(note(keys[i], 2.0 * i, 2.0 * i + 1.0));
  const music::Score score = score_of(notes);
  const FeetPlan plan = plan_feet(score, std::vector<bool>(notes.size(), true), ago_board());
  ASSERT_EQ(plan.presses.size(), notes.size());
  for (const PedalPress& p : plan.presses) {
    EXPECT_EQ(p.foot, p.key < 52 ? kLeftFoot : kRightFoot) << "key " << p.key;
  }
  expect_feet_never_in_two_places(plan);
}

TEST(PlanFeet, ALegatoLineIsSharedBetweenTheFeetAndOutOfRangeNotesFold) {
  // A walking bass in eighths at 120 bpm, each note held to the next: one foot cannot let a
  // pedal up and press the next in no time, so the feet take turns or cut a note a little.
  std::vector<music::Note> notes;
  const int keys[] = {45, 47, 48, 50, 52, 53, 55, 57, 55, 53, 52, 50, 48, 47, 24, 79};
  for (int i = 0; i < 14; ++i) notes.push_back(note(keys[i], 0.25 * i, 0.25 * (i + 1)));
  notes.push_back(note(keys[14], 5.0, 5.25));
  notes.push_back(note(keys[15], 7.0, 7.25));
  const music::Score score = score_of(notes);
  const FeetPlan plan = plan_feet(score, std::vector<bool>(notes.size(), true), ago_board());
  ASSERT_EQ(plan.presses.size(), notes.size());
  EXPECT_EQ(plan.folded, 2u);
  EXPECT_EQ(plan.presses[14].key, 36) << "C1 folds up to C2";
  EXPECT_EQ(plan.presses[15].key, 67) << "G5 folds down to G4";
  EXPECT_FALSE(plan.by_foot[kLeftFoot].empty());
  EXPECT_FALSE(plan.by_foot[kRightFoot].empty());
  expect_feet_never_in_two_places(plan);
  double cut = 0.0;
  for (const PedalPress& p : plan.presses) {
    const music::Note& n = score.notes[p.note];
    EXPECT_EQ(p.down_s, n.onset_s);
    cut += n.offset_s - p.up_s;
    EXPECT_LE(n.offset_s - p.up_s, 0.4 * 0.25 + 1e-9) << "a note cut by more than 40 %";
  }
  EXPECT_LT(cut, 0.25 * 16 * 0.25) << "the line stays mostly legato";
}

TEST(PlanFeet, TheBoardsEndsAreEachOneFootsWhateverTheCost) {
  // A fast legato line at the bottom of the board: the right foot does not reach past the
  // left's side, so the left foot plays it all, letting each pedal up early.
  std::vector<music::Note> notes;
  const int keys[] = {36, 38, 40, 38, 36, 67, 65, 67};
  for (int i = 0; i < 8; ++i) notes.push_back(note(keys[i], 0.25 * i, 0.25 * (i + 1)));
  const FeetPlan plan = plan_feet(score_of(notes), std::vector<bool>(notes.size(), true), ago_board());
  ASSERT_EQ(plan.presses.size(), notes.size());
  for (const PedalPress& p : plan.presses) {
    EXPECT_EQ(p.foot, p.key < 52 ? kLeftFoot : kRightFoot) << "key " << p.key;
    EXPECT_TRUE(piano_model::foot_reaches(ago_board(), p.foot == kRightFoot, p.key));
  }
  EXPECT_FALSE(piano_model::foot_reaches(ago_board(), true, 36));
  EXPECT_FALSE(piano_model::foot_reaches(ago_board(), false, 67));
  expect_feet_never_in_two_places(plan);
}

TEST(EvaluateFoot, DownThroughEachNoteAndAPureFunctionOfTime) {
  std::vector<music::Note> notes;
  const int keys[] = {36, 43, 48, 43, 36, 55, 60, 67};
  for (int i = 0; i < 8; ++i) notes.push_back(note(keys[i], 0.5 * i, 0.5 * i + 0.3));
  const FeetPlan plan =
      plan_feet(score_of(notes), std::vector<bool>(notes.size(), true), ago_board());
  for (const PedalPress& p : plan.presses) {
    for (double t : {p.down_s, 0.5 * (p.down_s + p.up_s), p.up_s}) {
      const FootState s = evaluate_foot(plan, p.foot, t);
      EXPECT_EQ(s.from_key, p.key) << t;
      EXPECT_EQ(s.to_key, p.key) << t;
      EXPECT_DOUBLE_EQ(s.depth, 1.0) << t;
      EXPECT_DOUBLE_EQ(s.lift_m, 0.0) << t;
    }
    // Up again once released; before the press, on its way or hovering.
    EXPECT_DOUBLE_EQ(evaluate_foot(plan, p.foot, p.up_s + FootTiming::release_s + 1e-6).depth, 0.0);
  }
  // The same time gives the same state, in any order of asking.
  for (double t = 4.0; t >= -0.5; t -= 0.037) {
    for (int foot : {kRightFoot, kLeftFoot}) {
      const FootState a = evaluate_foot(plan, foot, t);
      const FootState b = evaluate_foot(plan, foot, t);
      EXPECT_EQ(a.from_key, b.from_key);
      EXPECT_EQ(a.travel, b.travel);
      EXPECT_EQ(a.depth, b.depth);
      EXPECT_GE(a.lift_m, 0.0);
      EXPECT_LE(a.lift_m, FootTiming::hover_m + FootTiming::step_lift_m + 1e-12);
    }
  }
  // A foot moving to another pedal lifts over the ones between.
  bool stepped = false;
  for (double t = 0.0; t < 4.0; t += 0.005) {
    for (int foot : {kRightFoot, kLeftFoot}) {
      const FootState s = evaluate_foot(plan, foot, t);
      if (s.from_key != s.to_key && s.travel > 0.4 && s.travel < 0.6) {
        stepped = true;
        EXPECT_GT(s.lift_m, FootTiming::hover_m + 0.5 * FootTiming::step_lift_m);
      }
    }
  }
  EXPECT_TRUE(stepped);
}

TEST(PedalGeometry, NaturalsEvenlySpacedSharpsBetweenThemCentredOnMiddleE) {
  const piano_model::Pedalboard board = ago_board();
  EXPECT_NEAR(piano_model::pedal_x_m(board, 52), 0.0, 1e-12) << "E3, the board's middle natural";
  EXPECT_NEAR(piano_model::pedal_x_m(board, 53) - piano_model::pedal_x_m(board, 52), 0.0635, 1e-12);
  EXPECT_NEAR(piano_model::pedal_x_m(board, 37),
              0.5 * (piano_model::pedal_x_m(board, 36) + piano_model::pedal_x_m(board, 38)), 1e-12);
  EXPECT_NEAR(piano_model::pedal_x_m(board, 36), -piano_model::pedal_x_m(board, 67), 1e-12);
}

}  // namespace
}  // namespace tutti::piano
