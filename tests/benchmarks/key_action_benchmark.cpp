// SPDX-License-Identifier: MIT
// What "sound from motion" costs after the fingering and hand paths are planned: a style's
// strokes, the finger motion they make, and the key simulation that finds every note's
// escapement, velocity and release (systems/key_action), per style, on the piano demo and on a
// long third-party piece. Counters: notes per second of planning time.
#include <benchmark/benchmark.h>

#include <filesystem>

#include <tutti/finger_motion/finger_motion_params.hpp>
#include <tutti/key_action/humane_performance.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/piano_performance/performance_plan.hpp>

namespace {

using namespace tutti;

struct Piece {
  music::Score score;
  fingering_planner::FingeringModel model;
  piano_performance::PianoPerformancePlan plan;
  key_action::KeyAction action;
  key_action::StyleBook styles;
  finger_motion::FingerMotionParams params;
};

const Piece* load_piece(const std::filesystem::path& file) {
  const std::filesystem::path content = TUTTI_CONTENT_DIR;
  auto score = music::load_score(file);
  auto model = fingering_planner::load_fingering_model("default", "", content);
  auto action = key_action::load_key_action(key_action::key_action_path(content));
  auto styles = key_action::load_styles(key_action::styles_path(content));
  auto params =
      finger_motion::load_finger_motion_params(finger_motion::finger_motion_params_path(content));
  if (!score || !model || !action || !styles || !params) return nullptr;
  auto plan = piano_performance::plan_performance(*score, *model);
  if (!plan) return nullptr;
  return new Piece{std::move(*score), std::move(*model),  std::move(*plan),
                   *action,           std::move(*styles), *params};
}

void run(benchmark::State& state, const Piece* piece, const char* style_name) {
  if (piece == nullptr) {
    state.SkipWithError("inputs did not load");
    return;
  }
  auto style = piece->styles.find(style_name);
  if (!style) {
    state.SkipWithError("no such style");
    return;
  }
  key_action::HumaneInputs in;
  in.score = &piece->score;
  in.fingering = &piece->plan.fingering;
  in.right_path = &piece->plan.right_path;
  in.left_path = &piece->plan.left_path;
  in.keyboard = &piece->model.keyboard;
  in.hand_model = &piece->model.hand;
  in.params = &piece->params;
  in.action = &piece->action;
  in.style = &*style;
  in.seed = 1;
  for (auto _ : state) {
    auto performed = key_action::perform(in);
    benchmark::DoNotOptimize(performed);
  }
  state.counters["notes"] = static_cast<double>(piece->score.notes.size());
  state.counters["notes_per_s"] = benchmark::Counter(static_cast<double>(piece->score.notes.size()),
                                                     benchmark::Counter::kIsIterationInvariantRate);
}

const Piece* demo() {
  static const Piece* piece =
      load_piece(std::filesystem::path(TUTTI_CONTENT_DIR) / "music" / "ode_to_joy.musicxml");
  return piece;
}

const Piece* canon() {
  static const Piece* piece = load_piece(std::filesystem::path(TUTTI_TESTDATA_DIR) / "musicxml" /
                                         "pianoplayer" / "pachelbel_canon.xml");
  return piece;
}

void BM_PerformDemo(benchmark::State& state, const char* style) { run(state, demo(), style); }
void BM_PerformCanon(benchmark::State& state, const char* style) { run(state, canon(), style); }

BENCHMARK_CAPTURE(BM_PerformDemo, precise, "precise")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PerformDemo, beginner, "beginner")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PerformCanon, precise, "precise")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PerformCanon, beginner, "beginner")->Unit(benchmark::kMillisecond);

}  // namespace
