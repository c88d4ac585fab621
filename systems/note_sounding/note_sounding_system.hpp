// SPDX-License-Identifier: MIT
#pragma once
// Which notes sound at the frame time: note_sounding_system sets components::Note::sounding =
// (onset_s <= t < offset_s and not silent) on every Note entity, in Phase::evaluate.
//
// A pure function of the frame time and each note's own onset/offset: nothing carries over from
// the previous frame, so seeking backwards, jumping or replaying a frame gives the same flags.
// A zero-length note (offset_s == onset_s) never sounds; a NaN time sounds nothing. Reads and
// writes only Note; allocation-free; O(number of notes) per frame.

#include <tutti/ecs/schedule.hpp>
#include <tutti/ecs/world.hpp>

namespace tutti::note_sounding {

// onset_s <= t_s < offset_s.
[[nodiscard]] constexpr bool sounds_at(double onset_s, double offset_s, double t_s) noexcept {
  return onset_s <= t_s && t_s < offset_s;
}

// Writes Note::sounding for every Note at frame.t_s.
void note_sounding_system(ecs::World& world, const ecs::FrameTime& frame);

inline constexpr const char* kNoteSoundingSystemName = "note_sounding";

// Adds note_sounding_system to Phase::evaluate under kNoteSoundingSystemName.
// (Reads and writes Note.)
void register_note_sounding(ecs::Schedule& schedule);

}  // namespace tutti::note_sounding
