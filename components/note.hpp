// SPDX-License-Identifier: MIT
#pragma once
// A note of the piece as an entity: what sounds, when, who plays it with which finger, and whether
// it sounds at the current frame. The stage makes one per note of every score, as written; the
// performer's family claims it (performer, hand, finger, playable) and moves onset_s / offset_s /
// velocity to what is actually heard (a catch breath's early release, the simulated keys'
// timing). `sounding` is rewritten every frame by systems/note_sounding (Phase::evaluate); the
// sound and the editor read these entities.

#include <cstdint>

#include <tutti/components/hand_side.hpp>
#include <tutti/ecs/entity.hpp>

namespace tutti::components {

struct Note {
  int pitch = 60;                             // sounding MIDI key, 0..127
  double onset_s = 0.0;                       // the sound starts (seconds from the start)
  double offset_s = 0.0;                      // the sound stops; >= onset_s
  double onset_beats = 0.0;                   // the same in quarter notes from the start
  double offset_beats = 0.0;                  // >= onset_beats
  int velocity = 64;                          // MIDI velocity 1..127
  double written_onset_s = 0.0;               // as the score has it (pins and marks refer to it)
  double written_offset_s = 0.0;              // >= written_onset_s
  ecs::Entity performer = ecs::Entity::null;  // who plays it; null = nobody on stage
  HandSide hand = HandSide::right;            // which hand (piano)
  int finger = 0;                             // 1 = thumb .. 5 = little, 0 = not assigned
  std::int32_t score = -1;                    // which of the stage's scores, -1 = none
  std::int32_t score_index = -1;              // index into Score::notes, -1 = none
  bool playable = true;                       // within the performer's instrument's range
  bool silent = false;                        // the performer missed it: it never sounds
  bool sounding = false;                      // onset_s <= t < offset_s at the current frame
};

}  // namespace tutti::components
