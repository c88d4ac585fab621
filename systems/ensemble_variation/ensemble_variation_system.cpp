// SPDX-License-Identifier: MIT
#include <tutti/ensemble_variation/ensemble_variation_system.hpp>

#include <tutti/components/body_motion.hpp>
#include <tutti/components/breath.hpp>
#include <tutti/ensemble_variation/evaluate_body_motion.hpp>

namespace tutti::ensemble_variation {

void ensemble_variation_system(ecs::World& world, const ecs::FrameTime& frame) {
  const double t_s = frame.t_s;
  // Breath is written in Phase::evaluate, before this phase: the shown strain starts from it.
  world.view<EnsembleMotionHandle, components::BodyMotion>().each(
      [&world, t_s](ecs::Entity performer, const EnsembleMotionHandle& handle,
                    components::BodyMotion& motion) {
        if (!handle.plan || handle.performer >= handle.plan->performers.size()) return;
        const auto* breath = world.try_get<components::Breath>(performer);
        motion = evaluate_body_motion(handle.plan->performers[handle.performer], t_s,
                                      breath != nullptr ? breath->strain : 0.0);
      });
}

void register_ensemble_variation(ecs::Schedule& schedule) {
  schedule.add(ecs::Phase::express, kEnsembleVariationSystemName, ensemble_variation_system,
               ecs::access(ecs::Reads<EnsembleMotionHandle, components::Breath>{},
                           ecs::Writes<components::BodyMotion>{}));
}

}  // namespace tutti::ensemble_variation
