// SPDX-License-Identifier: MIT
#include <tutti/brass_motion/brass_pose_system.hpp>

#include <algorithm>

#include <tutti/brass_motion/evaluate_brass_pose.hpp>
#include <tutti/components/breath.hpp>
#include <tutti/components/instrument.hpp>
#include <tutti/components/mouth.hpp>
#include <tutti/components/slide.hpp>
#include <tutti/components/valve.hpp>

namespace tutti::brass_motion {
namespace {

const BrassPlayerMotion* motion_of(const ecs::World& world, ecs::Entity performer) {
  const auto* handle = world.try_get<BrassPlayerMotionHandle>(performer);
  return handle != nullptr ? handle->motion.get() : nullptr;
}

}  // namespace

void brass_pose_system(ecs::World& world, const ecs::FrameTime& frame) {
  const double t_s = frame.t_s;
  world.view<BrassPlayerMotionHandle, components::Mouth>().each(
      [&](ecs::Entity performer, const BrassPlayerMotionHandle& handle, components::Mouth& mouth) {
        if (handle.motion == nullptr) return;
        const BrassPose pose = evaluate_brass_pose(handle.motion->motion, t_s);
        const BreathState breath = evaluate_breath(handle.motion->breaths, t_s);
        mouth.tension = pose.tension;
        mouth.corner_pull = pose.corner_pull;
        mouth.open = breath.inhale;
        mouth.buzzing = pose.buzzing;
        if (auto* b = world.try_get<components::Breath>(performer)) {
          b->air = breath.air;
          b->inhale = breath.inhale;
          b->preparing = breath.preparing;
          b->strain = breath.strain;
          b->breath_index = breath.breath_index;
        }
      });
  world.view<components::Instrument>().each([&](ecs::Entity entity,
                                                const components::Instrument& instrument) {
    const BrassPlayerMotion* motion = motion_of(world, instrument.performer);
    if (motion == nullptr) return;
    const BrassPose pose = evaluate_brass_pose(motion->motion, t_s);
    if (auto* valve = world.try_get<components::Valve>(entity)) {
      valve->count = static_cast<std::uint8_t>(
          std::min<int>(motion->motion.valve_count, components::Valve::kMax));
      for (int v = 0; v < components::Valve::kMax; ++v) {
        valve->press[static_cast<std::size_t>(v)] =
            v < motion->motion.valve_count ? pose.valve_press[static_cast<std::size_t>(v)] : 0.0f;
      }
    }
    if (auto* slide = world.try_get<components::Slide>(entity)) {
      slide->extension_mm = pose.slide_mm;
      slide->position = pose.slide_position;
      slide->speed_mm_per_s = pose.slide_speed_mm_per_s;
    }
  });
}

void register_brass_motion(ecs::Schedule& schedule) {
  schedule.add(ecs::Phase::evaluate, kBrassMotionSystemName, brass_pose_system,
               ecs::access(ecs::Reads<BrassPlayerMotionHandle, components::Instrument>{},
                           ecs::Writes<components::Mouth, components::Breath, components::Valve,
                                       components::Slide>{}));
}

}  // namespace tutti::brass_motion
