// SPDX-License-Identifier: MIT
#include <tutti/note_sounding/note_sounding_system.hpp>

#include <tutti/components/note.hpp>

namespace tutti::note_sounding {

void note_sounding_system(ecs::World& world, const ecs::FrameTime& frame) {
  const double t_s = frame.t_s;
  world.view<components::Note>().each([t_s](components::Note& note) {
    note.sounding = !note.silent && sounds_at(note.onset_s, note.offset_s, t_s);
  });
}

void register_note_sounding(ecs::Schedule& schedule) {
  schedule.add(ecs::Phase::evaluate, kNoteSoundingSystemName, note_sounding_system,
               ecs::access(ecs::Reads<>{}, ecs::Writes<components::Note>{}));
}

}  // namespace tutti::note_sounding
