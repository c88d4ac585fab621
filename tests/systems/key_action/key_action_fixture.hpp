// SPDX-License-Identifier: MIT
#pragma once
// The real content files, and a whole performance of a score in a style (fingering, hand paths,
// strokes, finger motion, keys), for the key_action tests.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <tutti/finger_motion/finger_motion_params.hpp>
#include <tutti/fingering_planner/fingering_model.hpp>
#include <tutti/key_action/humane_performance.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/piano_performance/performance_plan.hpp>

namespace tutti::key_action::test {

inline std::filesystem::path content_dir() { return TUTTI_CONTENT_DIR; }

struct Content {
  KeyAction action;
  StyleBook styles;
  finger_motion::FingerMotionParams params;
  fingering_planner::FingeringModel model;
};

inline const Content& content() {
  static const Content c = [] {
    auto action = load_key_action(key_action_path(content_dir()));
    EXPECT_TRUE(action.ok()) << (action.ok() ? "" : action.error().message);
    auto styles = load_styles(styles_path(content_dir()));
    EXPECT_TRUE(styles.ok()) << (styles.ok() ? "" : styles.error().message);
    auto params = finger_motion::load_finger_motion_params(
        finger_motion::finger_motion_params_path(content_dir()));
    EXPECT_TRUE(params.ok());
    auto model = fingering_planner::load_fingering_model("default", "", content_dir());
    EXPECT_TRUE(model.ok());
    return Content{*action, *styles, *params, *model};
  }();
  return c;
}

inline PerformanceStyle style(const std::string& name) {
  auto found = content().styles.find(name);
  EXPECT_TRUE(found.ok()) << name;
  return found.ok() ? *found : PerformanceStyle{};
}

struct Performed {
  music::Score score;
  piano_performance::PianoPerformancePlan plan;
  HumanePerformance result;
};

// Plans `score` and performs it in `style` with `action` (default: the content's key action).
inline Performed perform_score(music::Score score, const PerformanceStyle& style,
                               std::uint64_t seed, const KeyAction* action = nullptr) {
  Performed out;
  out.score = std::move(score);
  auto plan = piano_performance::plan_performance(out.score, content().model);
  EXPECT_TRUE(plan.ok()) << (plan.ok() ? "" : plan.error().message);
  if (!plan.ok()) return out;
  out.plan = std::move(*plan);
  HumaneInputs in;
  in.score = &out.score;
  in.fingering = &out.plan.fingering;
  in.right_path = &out.plan.right_path;
  in.left_path = &out.plan.left_path;
  in.keyboard = &content().model.keyboard;
  in.hand_model = &content().model.hand;
  in.params = &content().params;
  in.action = action != nullptr ? action : &content().action;
  in.style = &style;
  in.seed = seed;
  auto performed = perform(in);
  EXPECT_TRUE(performed.ok()) << (performed.ok() ? "" : performed.error().message);
  if (performed.ok()) out.result = std::move(*performed);
  return out;
}

inline music::Score load(const std::filesystem::path& file) {
  auto score = music::load_score(file);
  EXPECT_TRUE(score.ok()) << file << ": " << (score.ok() ? "" : score.error().message);
  return score.ok() ? std::move(*score) : music::Score{};
}

// The tutti piano demo's music.
inline music::Score ode_to_joy() { return load(content_dir() / "music" / "ode_to_joy.musicxml"); }

}  // namespace tutti::key_action::test

namespace tutti::key_action::test {

struct SimpleNote {
  int key = 60;
  double onset_s = 0.0;
  double duration_s = 0.25;
  int velocity = 80;
};

// A one-part score at 120 bpm (960 ticks per second).
inline music::Score simple_score(const std::vector<SimpleNote>& notes) {
  music::Score score;
  score.source = "simple";
  score.tempo_map = music::TempoMap::with_ticks_per_quarter(480);
  score.parts.push_back(music::Part{"P1", "Piano", 0, 0, -1, 0, 1, false});
  for (const SimpleNote& n : notes) {
    music::Note note;
    note.pitch = n.key;
    note.onset_s = n.onset_s;
    note.offset_s = n.onset_s + n.duration_s;
    note.onset_ticks = static_cast<std::int64_t>(std::llround(n.onset_s * 960.0));
    note.offset_ticks = static_cast<std::int64_t>(std::llround(note.offset_s * 960.0));
    note.onset_beats = n.onset_s * 2.0;
    note.offset_beats = note.offset_s * 2.0;
    note.velocity = n.velocity;
    score.notes.push_back(note);
  }
  score.end_s = score.notes.empty() ? 0.0 : score.notes.back().offset_s;
  score.end_ticks = static_cast<std::int64_t>(std::llround(score.end_s * 960.0));
  return score;
}

// C major up and down from C4, one note every `step_s`, velocities cycling 40..110.
inline music::Score scale_score(double step_s = 0.25) {
  const int keys[] = {60, 62, 64, 65, 67, 69, 71, 72, 71, 69, 67, 65, 64, 62, 60};
  std::vector<SimpleNote> notes;
  for (int i = 0; i < 15; ++i) {
    notes.push_back({keys[i], 0.5 + i * step_s, step_s * 0.9, 40 + (i * 10) % 71});
  }
  return simple_score(notes);
}

}  // namespace tutti::key_action::test
