// SPDX-License-Identifier: MIT
#pragma once
// Shared test inputs: the real content files, constant hand paths and tiny hand-made scores.

#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include <tutti/finger_motion/finger_motion_params.hpp>
#include <tutti/finger_motion/plan_finger_motion.hpp>
#include <tutti/fingering_planner/plan_score.hpp>
#include <tutti/music/score.hpp>
#include <tutti/piano_model/hand_model.hpp>
#include <tutti/piano_model/keyboard.hpp>
#include <tutti/spline_motion/hand_path.hpp>

namespace tutti::finger_motion::test {

inline std::filesystem::path content_dir() { return TUTTI_CONTENT_DIR; }

struct Models {
  piano_model::Keyboard keyboard;
  piano_model::HandModel hand;
  FingerMotionParams params;
};

inline const Models& models() {
  static const Models m = [] {
    auto keyboard = piano_model::Keyboard::load(content_dir() / "piano" / "keyboard.json");
    EXPECT_TRUE(keyboard.ok());
    auto hand = piano_model::HandModel::load(content_dir() / "piano" / "hands.json", "",
                                             keyboard->white_key_width_mm());
    EXPECT_TRUE(hand.ok());
    auto params = load_finger_motion_params(finger_motion_params_path(content_dir()));
    EXPECT_TRUE(params.ok()) << (params.ok() ? "" : params.error().message);
    return Models{*keyboard, *hand, *params};
  }();
  return m;
}

// A hand that stays at x_mm for 1000 s.
inline spline_motion::HandPath constant_path(double x_mm) {
  spline_motion::Poly5 piece;
  piece.c[0] = x_mm;
  return spline_motion::HandPath(spline_motion::SmoothingMode::none, {0.0, 1000.0}, {piece}, x_mm, true);
}

struct TestNote {
  int key = 60;
  double onset_s = 0.0;
  double offset_s = 0.0;
  int finger = 1;
  music::Hand hand = music::Hand::right;
};

struct TestScore {
  music::Score score;
  fingering_planner::ScorePlan plan;
};

inline TestScore make_score(const std::vector<TestNote>& notes) {
  TestScore out;
  for (const TestNote& n : notes) {
    music::Note note;
    note.pitch = n.key;
    note.onset_s = n.onset_s;
    note.offset_s = n.offset_s;
    out.score.notes.push_back(note);
    out.plan.fingers.push_back(n.finger);
    out.plan.hands.push_back(n.hand);
  }
  return out;
}

inline FingerMotionPlan plan_notes(const std::vector<TestNote>& notes, double right_x_mm,
                                   double left_x_mm, const FingerMotionParams& params) {
  const TestScore s = make_score(notes);
  const Models& m = models();
  auto plan = plan_finger_motion(s.score, s.plan, constant_path(right_x_mm),
                                 constant_path(left_x_mm), m.keyboard, m.hand, params);
  EXPECT_TRUE(plan.ok()) << (plan.ok() ? "" : plan.error().message);
  return *plan;
}

inline FingerMotionPlan plan_notes(const std::vector<TestNote>& notes, double right_x_mm,
                                   double left_x_mm) {
  const TestScore s = make_score(notes);
  const Models& m = models();
  auto plan = plan_finger_motion(s.score, s.plan, constant_path(right_x_mm),
                                 constant_path(left_x_mm), m.keyboard, m.hand, m.params);
  EXPECT_TRUE(plan.ok()) << (plan.ok() ? "" : plan.error().message);
  return *plan;
}

}  // namespace tutti::finger_motion::test

namespace tutti::finger_motion {
using Models = test::Models;
}  // namespace tutti::finger_motion
