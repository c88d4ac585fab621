// SPDX-License-Identifier: MIT
#pragma once
// The planned finger motion of one pianist: per hand, per finger, the sorted key contacts with
// every timing decision already made (when the finger leaves for the key, reshapes, strikes,
// releases). Immutable once built by plan_finger_motion; evaluate_hand_pose reads it.
//
// Ownership: a value (vectors inside); share it between entities through a shared_ptr to const.
// Times are seconds from the start of the piece, positions millimetres in the keyboard frame.

#include <array>
#include <vector>

#include <tutti/components/hand_side.hpp>
#include <tutti/finger_motion/finger_chain.hpp>
#include <tutti/finger_motion/finger_motion_params.hpp>
#include <tutti/finger_motion/pass_over.hpp>
#include <tutti/spline_motion/plateau_envelope.hpp>

namespace tutti::finger_motion {

// One key played by one finger. Invariants (plan_finger_motion guarantees them, per finger):
// contacts sorted by strictly increasing onset_s; for each contact
// move_start_s <= onset_s, shape_start_s <= stroke_start_s < onset_s <= offset_s <
// release_end_s, and the previous contact's offset_s <= this contact's shape_start_s,
// move_start_s and stroke_start_s.
struct KeyContact {
  int key = 60;               // MIDI key (clamped onto the keyboard)
  double x_mm = 0.0;          // key centre along the keyboard
  bool black = false;         // black key: higher top, flatter bend
  double onset_s = 0.0;       // key bottom reached (press depth 1)
  double offset_s = 0.0;      // key starts to rise (trimmed so the next stroke of this finger fits)
  double move_start_s = 0.0;  // lateral minimum-jerk move toward x_mm starts (ends at onset_s)
  double move_from_x_mm = 0.0;  // where the tip was at move_start_s (the move's start point)
  double shape_start_s = 0.0;   // bend (joints 2-3) and hover height start to adapt (end: stroke)
  double stroke_start_s = 0.0;  // the tip starts down from hover height
  double release_end_s = 0.0;   // the tip is back at hover height above the key
  // Tip's lateral offset from its rest line at offset_s (keyboard x, not mirrored); decays with
  // the relax time constant after the release.
  double release_offset_mm = 0.0;
  int note = -1;  // Score::notes index
  // Tip height at the key bed where this finger presses (the key's top minus its travel there:
  // keyboard dip_mm by default; less when a key lever is modelled and the tip presses further
  // in, nearer the pivot; see systems/key_action).
  double bottom_z_mm = -10.0;
  double inv_travel_per_mm = 0.1;  // 1 / (key top - bottom_z_mm): press depth per mm

  // Precomputed by plan_finger_motion from the fields above, so evaluate multiplies instead of
  // dividing and takes one exponential per finger (see README.md, "Precomputed at plan time").
  double inv_move_s = 0.0;     // 1 / (onset_s - move_start_s)
  double inv_shape_s = 0.0;    // 1 / (stroke_start_s - shape_start_s), 0 when that span is 0
  double inv_stroke_s = 0.0;   // 1 / (onset_s - stroke_start_s)
  double inv_release_s = 0.0;  // 1 / (release_end_s - offset_s)
  // exp((release_end_s - offset_s) / relax_time_constant_s): turns the relaxation decay since
  // the offset into the decay since the release end (the hover height's), without a second exp.
  double release_decay_scale = 1.0;
};

struct HandFingerPlan {
  components::HandSide side = components::HandSide::right;
  std::array<std::vector<KeyContact>, 5> fingers;  // [0] = thumb
  // Rest line of each finger relative to the hand reference point (keyboard x): the middle of
  // its reach range in the hand model (already mirrored for the left hand).
  std::array<double, 5> rest_offset_mm{};
  // onsets_s[f][j] == fingers[f][j].onset_s: the contiguous copy evaluate binary-searches (8
  // bytes per probe instead of a whole KeyContact; the onsets of a long piece stay in cache).
  std::array<std::vector<double>, 5> onsets_s{};
  // How far in toward the fallboard the hand sits beyond its rest line over time (mm), so the
  // short fingers reach the black keys they strike.
  tutti::spline_motion::PlateauEnvelope reach_in;
  // Where the hand is lifted over the other one (pass_over.hpp).
  PassOver pass_over;
};

struct FingerMotionPlan {
  HandFingerPlan right{components::HandSide::right, {}, {}, {}, {}, {}};
  HandFingerPlan left{components::HandSide::left, {}, {}, {}, {}, {}};
  std::array<FingerGeometry, 5> geometry{};  // scaled to the hand preset
  // Chain shapes for the three bends a held or resting finger has, so evaluate rarely needs trig.
  std::array<ChainShape, 5> neutral_shape{};
  std::array<ChainShape, 5> white_shape{};
  std::array<ChainShape, 5> black_shape{};
  KeyHeights keys;
  StrokeTiming timing;
  // Derived from keys and timing by plan_finger_motion.
  double relax_rate_per_s = 5.0;  // 1 / timing.relax_time_constant_s
  double neutral_z_mm = 8.0;      // keys.white_top_z_mm + keys.hover_lift_mm: tip height at rest

  const HandFingerPlan& hand(components::HandSide side) const {
    return side == components::HandSide::left ? left : right;
  }
};

}  // namespace tutti::finger_motion
