// SPDX-License-Identifier: MIT
#pragma once
// The stops a brass player reaches (stage/contact_detector.hpp): a valve at its bottom (value:
// the valve's number, 1-based) and back at its top, the slide coming to rest (value: the
// position, rounded, 1..7), and the tongue releasing the air (the mouth starts to buzz; value -1;
// not a host event: the note's note_on says it). A valve let go or a slide come to rest counts as
// sounding only where the player sounds at that sample and the next.

#include <memory>
#include <span>
#include <string_view>

#include <tutti/stage/contact_detector.hpp>

namespace tutti::brass {

std::span<const stage::StopKind* const> brass_stop_kinds();
// Watches the instruments of the performers seated in `family`, in spawn order; nullptr when
// there are none.
std::unique_ptr<stage::StopTracker> track_brass_stops(ecs::World& world, std::string_view family);

}  // namespace tutti::brass
