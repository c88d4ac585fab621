// SPDX-License-Identifier: MIT
#include <tutti/brass/brass_stops.hpp>

#include <algorithm>
#include <array>
#include <cmath>

#include <tutti/components/instrument.hpp>
#include <tutti/components/mouth.hpp>
#include <tutti/components/slide.hpp>
#include <tutti/components/valve.hpp>

namespace tutti::brass {
namespace {

constexpr stage::StopKind kValveDown{"valve_down", "valve down", true};
constexpr stage::StopKind kValveUp{"valve_up", "valve up", true};
constexpr stage::StopKind kSlideArrives{"slide_arrives", "slide arrives", true};
constexpr stage::StopKind kTongue{"tongue", "tongue", /*host_event=*/false};
constexpr std::array<const stage::StopKind*, 4> kKinds{&kValveDown, &kValveUp, &kSlideArrives,
                                                       &kTongue};

struct InstrumentTrack {
  ecs::Entity entity = ecs::Entity::null;
  ecs::Entity performer = ecs::Entity::null;
  std::array<double, components::Valve::kMax> press{};
  bool moving = false;
  bool buzzing = false;
  std::vector<std::size_t> waiting;  // stops found last sample whose `sounding` waits for this one
};

class BrassStopTracker final : public stage::StopTracker {
 public:
  explicit BrassStopTracker(std::vector<InstrumentTrack> instruments)
      : instruments_(std::move(instruments)) {}

  void sample(const ecs::World& world, const stage::StopSample& sample,
              std::vector<stage::Stop>& stops) override {
    const bool first = sample.first;
    const double t = sample.t;
    for (InstrumentTrack& track : instruments_) {
      const auto* mouth = world.try_get<components::Mouth>(track.performer);
      const bool buzzing = mouth != nullptr && mouth->buzzing;
      // Last sample's releases and arrivals sound if the player sounded then and still does.
      for (const std::size_t k : track.waiting) stops[k].sounding = buzzing && track.buzzing;
      track.waiting.clear();
      if (!first && buzzing && !track.buzzing) {
        stops.push_back({t, &kTongue, track.performer, -1, true});
      }
      if (const auto* valve = world.try_get<components::Valve>(track.entity)) {
        for (std::size_t v = 0; v < valve->count && v < track.press.size(); ++v) {
          const double now = valve->press[v];
          const double before = track.press[v];
          const auto number = static_cast<std::int32_t>(v + 1);
          if (!first && before < stage::kStopFullyDown && now >= stage::kStopFullyDown) {
            stops.push_back({stage::stop_crossing(sample.previous_t, before, t, now,
                                                  stage::kStopFullyDown),
                             &kValveDown, track.performer, number, true});
          } else if (!first && before > stage::kStopFullyUp && now <= stage::kStopFullyUp) {
            track.waiting.push_back(stops.size());
            stops.push_back({stage::stop_crossing(sample.previous_t, before, t, now,
                                                  stage::kStopFullyUp),
                             &kValveUp, track.performer, number, false});
          }
          track.press[v] = now;
        }
      }
      if (const auto* slide = world.try_get<components::Slide>(track.entity)) {
        const bool moving = slide->speed_mm_per_s != 0.0;
        if (!first && track.moving && !moving) {
          track.waiting.push_back(stops.size());
          stops.push_back({t, &kSlideArrives, track.performer,
                           static_cast<std::int32_t>(std::lround(slide->position)), false});
        }
        track.moving = moving;
      }
      track.buzzing = buzzing;
    }
  }

 private:
  std::vector<InstrumentTrack> instruments_;
};

}  // namespace

std::span<const stage::StopKind* const> brass_stop_kinds() { return kKinds; }

std::unique_ptr<stage::StopTracker> track_brass_stops(ecs::World& world, std::string_view family) {
  std::vector<InstrumentTrack> instruments;
  world.view<const components::Instrument>().each(
      [&](ecs::Entity e, const components::Instrument& instrument) {
        const auto* seat = world.try_get<stage::Seat>(instrument.performer);
        if (seat == nullptr || seat->family != family) return;
        InstrumentTrack track;
        track.entity = e;
        track.performer = instrument.performer;
        instruments.push_back(std::move(track));
      });
  if (instruments.empty()) return nullptr;
  // Spawn order: the same on every run of the same scene.
  std::sort(instruments.begin(), instruments.end(),
            [](const InstrumentTrack& a, const InstrumentTrack& b) {
              return a.entity.index < b.entity.index;
            });
  return std::make_unique<BrassStopTracker>(std::move(instruments));
}

}  // namespace tutti::brass
