#pragma once
// A note of the piece as an entity: what sounds, when, who plays it with which finger, and whether
// it sounds at the current frame. Timing fields are copied from the Score when the piece is
// loaded; `sounding` is rewritten every frame by systems/note_sounding (Phase::evaluate).

#include <cstdint>

#include <tutti/components/hand_side.hpp>
#include <tutti/ecs/entity.hpp>

namespace tutti::components {

struct Note {
  int pitch = 60;                             // sounding MIDI key, 0..127
  double onset_s = 0.0;                       // key goes down (seconds from the start of the piece)
  double offset_s = 0.0;                      // key is released; >= onset_s
  double onset_beats = 0.0;                   // the same in quarter notes from the start
  double offset_beats = 0.0;                  // >= onset_beats
  int velocity = 64;                          // MIDI velocity 1..127
  ecs::Entity performer = ecs::Entity::null;  // who plays it
  HandSide hand = HandSide::right;            // which hand (piano)
  int finger = 0;                             // 1 = thumb .. 5 = little, 0 = not assigned
  std::int32_t score_index = -1;              // index into Score::notes, -1 = none
  bool sounding = false;                      // onset_s <= t < offset_s at the current frame
};

}  // namespace tutti::components
