// SPDX-License-Identifier: MIT
#include <tutti/piano/piano_stops.hpp>

#include <algorithm>
#include <array>

#include <tutti/components/finger.hpp>
#include <tutti/components/foot.hpp>
#include <tutti/components/hand.hpp>

namespace tutti::piano {
namespace {

constexpr stage::StopKind kKeyDown{"key_down", "key bottom", true};
constexpr stage::StopKind kKeyUp{"key_up", "", true};
constexpr stage::StopKind kPedalDown{"pedal_down", "pedal down", true};
constexpr stage::StopKind kPedalUp{"pedal_up", "", true};
constexpr std::array<const stage::StopKind*, 4> kKinds{&kKeyDown, &kKeyUp, &kPedalDown, &kPedalUp};

class KeyboardStopTracker final : public stage::StopTracker {
 public:
  KeyboardStopTracker(std::vector<stage::PressTrack> fingers, std::vector<stage::PressTrack> feet)
      : fingers_(std::move(fingers)), feet_(std::move(feet)) {}

  void sample(const ecs::World& world, const stage::StopSample& sample,
              std::vector<stage::Stop>& stops) override {
    for (stage::PressTrack& track : fingers_) {
      if (const auto* finger = world.try_get<components::Finger>(track.entity)) {
        stage::track_press(track, finger->press_depth, finger->key, sample, kKeyDown, kKeyUp,
                           stops);
      }
    }
    for (stage::PressTrack& track : feet_) {
      if (const auto* foot = world.try_get<components::Foot>(track.entity)) {
        stage::track_press(track, foot->press_depth, foot->key, sample, kPedalDown, kPedalUp,
                           stops);
      }
    }
  }

 private:
  std::vector<stage::PressTrack> fingers_;
  std::vector<stage::PressTrack> feet_;
};

void sort_by_spawn(std::vector<stage::PressTrack>& tracks) {
  std::sort(tracks.begin(), tracks.end(), [](const stage::PressTrack& a, const stage::PressTrack& b) {
    return a.entity.index < b.entity.index;
  });
}

}  // namespace

std::span<const stage::StopKind* const> keyboard_stop_kinds() { return kKinds; }

std::unique_ptr<stage::StopTracker> track_keyboard_stops(ecs::World& world) {
  std::vector<stage::PressTrack> fingers;
  world.view<const components::Finger>().each([&](ecs::Entity e, const components::Finger& f) {
    const auto* hand = world.try_get<components::Hand>(f.hand);
    fingers.push_back({e, hand != nullptr ? hand->performer : ecs::Entity::null});
  });
  std::vector<stage::PressTrack> feet;  // a foot holds its pedal as a finger its key
  world.view<const components::Foot>().each([&](ecs::Entity e, const components::Foot& f) {
    feet.push_back({e, f.performer});
  });
  if (fingers.empty() && feet.empty()) return nullptr;
  // Spawn order: the same on every run of the same scene.
  sort_by_spawn(fingers);
  sort_by_spawn(feet);
  return std::make_unique<KeyboardStopTracker>(std::move(fingers), std::move(feet));
}

}  // namespace tutti::piano
