#include "ensemble_variation/ensemble_variation_system.hpp"

#include "components/body_motion.hpp"
#include "ensemble_variation/evaluate_body_motion.hpp"

namespace tutti::ensemble {

void ensemble_variation_system(ecs::World& world, const ecs::FrameTime& frame) {
  const double t_s = frame.t_s;
  world.view<EnsembleMotionHandle, components::BodyMotion>().each(
      [t_s](const EnsembleMotionHandle& handle, components::BodyMotion& motion) {
        if (!handle.plan || handle.performer >= handle.plan->performers.size()) return;
        motion = evaluate_body_motion(handle.plan->performers[handle.performer], t_s);
      });
}

void register_ensemble_variation(ecs::Schedule& schedule) {
  schedule.add(ecs::Phase::express, kEnsembleVariationSystemName, ensemble_variation_system);
}

}  // namespace tutti::ensemble
