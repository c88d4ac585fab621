// SPDX-License-Identifier: MIT
// Live input costs: the streaming planner per pushed note on the piano demo's notes (both hands,
// in arrival order; the decisions included) for lookahead 0, 3, 6, and the live pianist's
// update per note-on (planner, contacts, hand paths, a new PianistMotion).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

#include <tutti/finger_motion/finger_motion_params.hpp>
#include <tutti/fingering_planner/plan_score.hpp>
#include <tutti/fingering_planner/streaming_piano.hpp>
#include <tutti/live/live_pianist.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/piano_model/content_dir.hpp>

namespace {

using namespace tutti;

struct Fixture {
  fingering_planner::FingeringModel model;
  finger_motion::FingerMotionParams params;
  std::vector<fingering_planner::PlanNote> notes;  // arrival order
  std::vector<music::Hand> hands;
};

const Fixture& fixture() {
  static const Fixture f = [] {
    Fixture out;
    auto model = fingering_planner::load_fingering_model();
    auto params = finger_motion::load_finger_motion_params(
        finger_motion::finger_motion_params_path(piano_model::default_content_dir()));
    auto score = music::load_score(std::filesystem::path(TUTTI_SOURCE_DIR) /
                                   "content/music/ode_to_joy.musicxml");
    if (!model || !params || !score) std::abort();
    auto plan = fingering_planner::plan_score(*score, *model);
    if (!plan) std::abort();
    std::vector<std::size_t> order(score->notes.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return score->notes[a].onset_s < score->notes[b].onset_s;
    });
    for (std::size_t i : order) {
      const music::Note& n = score->notes[i];
      out.notes.push_back({n.pitch, n.onset_s, std::max(n.offset_s, n.onset_s), 0});
      out.hands.push_back(plan->hands[i]);
    }
    out.model = std::move(*model);
    out.params = *params;
    return out;
  }();
  return f;
}

void BM_StreamingPlannerPerNote(benchmark::State& state) {
  const Fixture& f = fixture();
  fingering_planner::StreamingOptions options;
  options.lookahead = static_cast<int>(state.range(0));
  std::vector<fingering_planner::StreamedFinger> out;
  out.reserve(f.notes.size());
  for (auto _ : state) {
    auto planner = fingering_planner::StreamingPianoPlanner::create(f.model, options);
    out.clear();
    double last = -1.0;
    for (std::size_t i = 0; i < f.notes.size(); ++i) {
      if (f.notes[i].onset_s > last) planner->advance(f.notes[i].onset_s, out);
      last = f.notes[i].onset_s;
      (void)planner->push(static_cast<std::int64_t>(i), f.notes[i], f.notes[i].offset_s,
                          f.hands[i]);
    }
    planner->flush(1e9, out);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(f.notes.size()));
}
BENCHMARK(BM_StreamingPlannerPerNote)->Arg(0)->Arg(3)->Arg(6)->Unit(benchmark::kMicrosecond);

void BM_LivePianistUpdatePerNote(benchmark::State& state) {
  const Fixture& f = fixture();
  // The demo's notes as live events (note-ons and note-offs), one frame each.
  std::vector<live::LiveNoteEvent> events;
  for (const fingering_planner::PlanNote& n : f.notes) {
    events.push_back({n.onset_s, n.key, 90, true});
    events.push_back({n.offset_s, n.key, 0, false});
  }
  std::stable_sort(events.begin(), events.end(),
                   [](const auto& a, const auto& b) { return a.time_s < b.time_s; });
  for (auto _ : state) {
    auto pianist = live::LivePianist::create(f.model, f.params);
    for (const live::LiveNoteEvent& e : events) {
      (*pianist)->update(std::span<const live::LiveNoteEvent>(&e, 1), e.time_s + 0.004);
    }
    benchmark::DoNotOptimize((*pianist)->motion().get());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(f.notes.size()));
}
BENCHMARK(BM_LivePianistUpdatePerNote)->Unit(benchmark::kMillisecond);

}  // namespace
