// SPDX-License-Identifier: MIT
#include <tutti/stage/contact_detector.hpp>

#include <algorithm>
#include <array>
#include <cmath>

#include <tutti/components/finger.hpp>
#include <tutti/components/foot.hpp>
#include <tutti/components/hand.hpp>
#include <tutti/components/instrument.hpp>
#include <tutti/components/mouth.hpp>
#include <tutti/components/slide.hpp>
#include <tutti/components/valve.hpp>

namespace tutti::stage {
namespace {

constexpr double kFullyDown = 0.999;
constexpr double kFullyUp = 0.001;

// Linear crossing time of `level` between (t0, v0) and (t1, v1).
double crossing(double t0, double v0, double t1, double v1, double level) {
  if (v1 == v0) return t1;
  return t0 + (t1 - t0) * std::clamp((level - v0) / (v1 - v0), 0.0, 1.0);
}

// A finger and its key, or a foot and its pedal.
struct FingerTrack {
  ecs::Entity entity = ecs::Entity::null;
  ecs::Entity performer = ecs::Entity::null;
  double depth = 0.0;
  int key_down = -1;  // the key this finger holds at its bed
};

struct InstrumentTrack {
  ecs::Entity entity = ecs::Entity::null;
  ecs::Entity performer = ecs::Entity::null;
  std::array<double, components::Valve::kMax> press{};
  bool moving = false;
  bool buzzing = false;
  std::vector<std::size_t> waiting;  // stops found last sample whose `sounding` waits for this one
};

struct Sample {
  double previous_t = 0.0;
  double t = 0.0;
  bool first = false;
};

// A finger's key or a foot's pedal at this sample: down when its depth crosses kFullyDown, up
// (the key that went down) when it falls back past kFullyUp.
void track_press(FingerTrack& track, double depth, int key, const Sample& sample, StopKind down,
                 StopKind up, std::vector<Stop>& stops) {
  if (!sample.first && track.depth < kFullyDown && depth >= kFullyDown && key >= 0) {
    stops.push_back({crossing(sample.previous_t, track.depth, sample.t, depth, kFullyDown), down,
                     track.performer, key, true});
    track.key_down = key;
  } else if (!sample.first && track.depth > kFullyUp && depth <= kFullyUp && track.key_down >= 0) {
    stops.push_back({crossing(sample.previous_t, track.depth, sample.t, depth, kFullyUp), up,
                     track.performer, track.key_down, true});
    track.key_down = -1;
  }
  track.depth = depth;
}

}  // namespace

std::vector<Stop> detect_stops(Stage& stage, const StopGrid& grid) {
  std::vector<Stop> stops;
  if (!(grid.step_s > 0.0) || !(grid.to_s >= grid.from_s)) return stops;
  ecs::World& world = stage.world();
  std::vector<FingerTrack> fingers;
  world.view<const components::Finger>().each([&](ecs::Entity e, const components::Finger& f) {
    const auto* hand = world.try_get<components::Hand>(f.hand);
    fingers.push_back({e, hand != nullptr ? hand->performer : ecs::Entity::null});
  });
  std::vector<FingerTrack> feet;  // a foot holds its pedal as a finger its key
  world.view<const components::Foot>().each([&](ecs::Entity e, const components::Foot& f) {
    feet.push_back({e, f.performer});
  });
  std::vector<InstrumentTrack> instruments;
  world.view<const components::Instrument>().each(
      [&](ecs::Entity e, const components::Instrument& instrument) {
        InstrumentTrack track;
        track.entity = e;
        track.performer = instrument.performer;
        instruments.push_back(std::move(track));
      });
  // Spawn order: the same on every run of the same scene.
  std::sort(fingers.begin(), fingers.end(),
            [](const FingerTrack& a, const FingerTrack& b) { return a.entity.index < b.entity.index; });
  std::sort(feet.begin(), feet.end(),
            [](const FingerTrack& a, const FingerTrack& b) { return a.entity.index < b.entity.index; });
  std::sort(instruments.begin(), instruments.end(),
            [](const InstrumentTrack& a, const InstrumentTrack& b) {
              return a.entity.index < b.entity.index;
            });
  if (fingers.empty() && feet.empty() && instruments.empty()) return stops;

  const double span = grid.to_s - grid.from_s;
  const auto steps =
      static_cast<std::int64_t>(std::ceil(span / grid.step_s)) + (grid.include_end ? 1 : 0);
  double previous_t = grid.from_s;
  for (std::int64_t i = 0; i < steps; ++i) {
    const double t = grid.from_s + static_cast<double>(i) * grid.step_s;
    stage.run({t, grid.step_s}, ecs::Phase::evaluate);
    const bool first = i == 0;
    for (FingerTrack& track : fingers) {
      if (const auto* finger = world.try_get<components::Finger>(track.entity)) {
        track_press(track, finger->press_depth, finger->key, {previous_t, t, first},
                    StopKind::key_down, StopKind::key_up, stops);
      }
    }
    for (FingerTrack& track : feet) {
      if (const auto* foot = world.try_get<components::Foot>(track.entity)) {
        track_press(track, foot->press_depth, foot->key, {previous_t, t, first},
                    StopKind::pedal_down, StopKind::pedal_up, stops);
      }
    }
    for (InstrumentTrack& track : instruments) {
      const auto* mouth = world.try_get<components::Mouth>(track.performer);
      const bool buzzing = mouth != nullptr && mouth->buzzing;
      // Last sample's releases and arrivals sound if the player sounded then and still does.
      for (const std::size_t k : track.waiting) stops[k].sounding = buzzing && track.buzzing;
      track.waiting.clear();
      if (!first && buzzing && !track.buzzing) {
        stops.push_back({t, StopKind::tongue, track.performer, -1, true});
      }
      if (const auto* valve = world.try_get<components::Valve>(track.entity)) {
        for (std::size_t v = 0; v < valve->count && v < track.press.size(); ++v) {
          const double now = valve->press[v];
          const double before = track.press[v];
          const auto number = static_cast<std::int32_t>(v + 1);
          if (!first && before < kFullyDown && now >= kFullyDown) {
            stops.push_back({crossing(previous_t, before, t, now, kFullyDown),
                             StopKind::valve_down, track.performer, number, true});
          } else if (!first && before > kFullyUp && now <= kFullyUp) {
            track.waiting.push_back(stops.size());
            stops.push_back({crossing(previous_t, before, t, now, kFullyUp), StopKind::valve_up,
                             track.performer, number, false});
          }
          track.press[v] = now;
        }
      }
      if (const auto* slide = world.try_get<components::Slide>(track.entity)) {
        const bool moving = slide->speed_mm_per_s != 0.0;
        if (!first && track.moving && !moving) {
          track.waiting.push_back(stops.size());
          stops.push_back({t, StopKind::slide_arrives, track.performer,
                           static_cast<std::int32_t>(std::lround(slide->position)), false});
        }
        track.moving = moving;
      }
      track.buzzing = buzzing;
    }
    previous_t = t;
  }
  return stops;
}

}  // namespace tutti::stage
