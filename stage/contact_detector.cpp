// SPDX-License-Identifier: MIT
#include <tutti/stage/contact_detector.hpp>

#include <algorithm>
#include <cmath>

#include <tutti/stage/family_plugin.hpp>

namespace tutti::stage {

double stop_crossing(double t0, double v0, double t1, double v1, double level) {
  if (v1 == v0) return t1;
  return t0 + (t1 - t0) * std::clamp((level - v0) / (v1 - v0), 0.0, 1.0);
}

void track_press(PressTrack& track, double depth, std::int32_t key, const StopSample& sample,
                 const StopKind& down, const StopKind& up, std::vector<Stop>& stops) {
  if (!sample.first && track.depth < kStopFullyDown && depth >= kStopFullyDown && key >= 0) {
    stops.push_back({stop_crossing(sample.previous_t, track.depth, sample.t, depth,
                                   kStopFullyDown),
                     &down, track.performer, key, true});
    track.key_down = key;
  } else if (!sample.first && track.depth > kStopFullyUp && depth <= kStopFullyUp &&
             track.key_down >= 0) {
    stops.push_back({stop_crossing(sample.previous_t, track.depth, sample.t, depth, kStopFullyUp),
                     &up, track.performer, track.key_down, true});
    track.key_down = -1;
  }
  track.depth = depth;
}

namespace {

// The grid's frames in `world`, each run by `run_frame(frame)` up to the evaluate phase.
template <typename RunFrame>
std::vector<Stop> detect_in(std::span<const FamilyPlugin* const> families, ecs::World& world,
                            const StopGrid& grid, RunFrame run_frame) {
  std::vector<Stop> stops;
  if (!(grid.step_s > 0.0) || !(grid.to_s >= grid.from_s)) return stops;
  std::vector<std::unique_ptr<StopTracker>> trackers;
  for (const FamilyPlugin* family : families) {
    if (auto tracker = family->track_stops(world)) trackers.push_back(std::move(tracker));
  }
  if (trackers.empty()) return stops;
  const double span = grid.to_s - grid.from_s;
  const auto steps =
      static_cast<std::int64_t>(std::ceil(span / grid.step_s)) + (grid.include_end ? 1 : 0);
  double previous_t = grid.from_s;
  for (std::int64_t i = 0; i < steps; ++i) {
    const double t = grid.from_s + static_cast<double>(i) * grid.step_s;
    run_frame(ecs::FrameTime{t, grid.step_s});
    const StopSample sample{previous_t, t, i == 0};
    for (const auto& tracker : trackers) tracker->sample(world, sample, stops);
    previous_t = t;
  }
  return stops;
}

}  // namespace

std::vector<Stop> detect_stops(Stage& stage, const StopGrid& grid) {
  return detect_in(stage.families(), stage.world(), grid, [&](const ecs::FrameTime& frame) {
    stage.run(frame, ecs::Phase::evaluate);
  });
}

std::vector<Stop> detect_stops(const Stage& stage, StageContext& context, const StopGrid& grid) {
  return detect_in(stage.families(), context.world(), grid, [&](const ecs::FrameTime& frame) {
    stage.run(context, frame, ecs::Phase::evaluate);
  });
}

}  // namespace tutti::stage
