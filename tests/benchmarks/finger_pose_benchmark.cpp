// SPDX-License-Identifier: MIT
// evaluate_hand_pose cost per call (one hand, five fingers) at 60 fps sequential t and random t.
// Plan: 2000 right-hand notes (about 6 minutes), notes spread over all fingers.

#include <benchmark/benchmark.h>

#include <cstdio>
#include <random>
#include <vector>

#include <tutti/finger_motion/evaluate_hand_pose.hpp>
#include <tutti/finger_motion/plan_finger_motion.hpp>
#include <tutti/piano_model/hand_model.hpp>
#include <tutti/piano_model/keyboard.hpp>

namespace {

using namespace tutti;

struct Fixture {
  finger_motion::FingerMotionPlan plan;
  spline_motion::HandPath path;
  double end_s = 0.0;
};

const Fixture& fixture() {
  static const Fixture f = [] {
    const std::filesystem::path content = TUTTI_CONTENT_DIR;
    auto keyboard = piano_model::Keyboard::load(content / "piano" / "keyboard.json");
    auto hand = piano_model::HandModel::load(content / "piano" / "hands.json", "",
                                             keyboard->white_key_width_mm());
    auto params =
        finger_motion::load_finger_motion_params(finger_motion::finger_motion_params_path(content));
    if (!keyboard || !hand || !params) std::abort();
    music::Score score;
    fingering_planner::ScorePlan plan;
    std::mt19937_64 rng(7);
    for (int i = 0; i < 2000; ++i) {
      music::Note note;
      note.pitch = 55 + static_cast<int>(rng() % 24);
      note.onset_s = 0.18 * i;
      note.offset_s = note.onset_s + 0.15;
      score.notes.push_back(note);
      plan.fingers.push_back(1 + static_cast<int>(rng() % 5));
      plan.hands.push_back(music::Hand::right);
    }
    spline_motion::Poly5 piece;
    piece.c[0] = 700.0;
    piece.c[1] = 0.1;
    Fixture out;
    out.path = spline_motion::HandPath(spline_motion::SmoothingMode::none, {0.0, 400.0}, {piece}, 740.0, true);
    auto planned = finger_motion::plan_finger_motion(score, plan, out.path, out.path, *keyboard,
                                                     *hand, *params);
    if (!planned) std::abort();
    out.plan = std::move(*planned);
    out.end_s = 0.18 * 2000;
    return out;
  }();
  return f;
}

void BM_EvaluateHandPoseSequential60fps(benchmark::State& state) {
  const Fixture& f = fixture();
  finger_motion::HandPose pose;
  double t = 0.0;
  for (auto _ : state) {
    finger_motion::evaluate_hand_pose(f.plan, f.path, components::HandSide::right, t, pose);
    benchmark::DoNotOptimize(pose);
    t += 1.0 / 60;
    if (t > f.end_s) t = 0.0;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EvaluateHandPoseSequential60fps);

void BM_EvaluateHandPoseRandom(benchmark::State& state) {
  const Fixture& f = fixture();
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> time(0.0, f.end_s);
  std::vector<double> times(4096);
  for (double& t : times) t = time(rng);
  finger_motion::HandPose pose;
  std::size_t i = 0;
  for (auto _ : state) {
    finger_motion::evaluate_hand_pose(f.plan, f.path, components::HandSide::right,
                                      times[i++ & 4095U], pose);
    benchmark::DoNotOptimize(pose);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EvaluateHandPoseRandom);

}  // namespace
