// SPDX-License-Identifier: MIT
#pragma once
// Planning one brass player of the scene: their line from the part, valves or slide positions,
// breaths and motion (systems/fingering_planner, systems/brass_motion). A previous stage's plan is
// shared when everything it depends on is the same (BrassPlan::plan_key).

#include <cstddef>

#include <tutti/brass/brass_components.hpp>
#include <tutti/brass_motion/brass_motion_params.hpp>
#include <tutti/brass_motion/breath_params.hpp>
#include <tutti/core/result.hpp>
#include <tutti/fingering_planner/brass_planner.hpp>
#include <tutti/stage/stage_builder.hpp>

namespace tutti::brass {

struct BrassPlanningData {
  fingering_planner::PlannerWeights weights;
  brass_motion::BrassMotionParams motion;
  brass_motion::BreathParams breath;
};

// From content_dir/brass.
Result<BrassPlanningData> load_brass_planning_data(const std::filesystem::path& content_dir);

// The plan of brass_players(builder.scene())[seat].
Result<BrassPlan> plan_brass_seat(stage::StageBuilder& builder, std::size_t seat,
                                  const BrassPlanningData& data);

}  // namespace tutti::brass
