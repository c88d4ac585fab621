// SPDX-License-Identifier: MIT
#pragma once
// The ECS side of ensemble variation: every performer entity in the plan carries an
// EnsembleMotionHandle (the shared, immutable plan and its index in it) and a
// components::BodyMotion, which ensemble_variation_system rewrites every frame (Phase::express)
// from the plan and the frame time only.

#include <cstddef>
#include <memory>

#include <tutti/ecs/schedule.hpp>
#include <tutti/ecs/world.hpp>
#include <tutti/ensemble_variation/ensemble_plan.hpp>

namespace tutti::ensemble_variation {

struct EnsembleMotionHandle {
  std::shared_ptr<const EnsemblePlan> plan;
  std::size_t performer = 0;  // index into plan->performers
};

// Allocation-free per frame.
void ensemble_variation_system(ecs::World& world, const ecs::FrameTime& frame);

inline constexpr const char* kEnsembleVariationSystemName = "ensemble_variation";
void register_ensemble_variation(ecs::Schedule& schedule);

}  // namespace tutti::ensemble_variation
