// SPDX-License-Identifier: MIT
#pragma once
// Planning the pianist: their parts of the music, the fingering (the scene's pins re-plan only
// the span around them), the hand paths and finger motion, and with a performance style what the
// simulated keys make of it. A previous stage's plan is shared when its key is the same.

#include <tutti/core/result.hpp>
#include <tutti/piano/piano_components.hpp>
#include <tutti/stage/stage_builder.hpp>

namespace tutti::piano {

// The plan of keyboard_players(builder.scene())[index]. Adds what it planned afresh to
// builder.replanned().
Result<PianistPlan> plan_pianist(stage::StageBuilder& builder, std::size_t index);

}  // namespace tutti::piano
