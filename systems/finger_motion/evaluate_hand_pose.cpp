// SPDX-License-Identifier: MIT
#include <tutti/finger_motion/evaluate_hand_pose.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>

namespace tutti::finger_motion {
namespace {

// Where a finger is at t before the next contact takes over: lateral x, bend, tip height, and
// the key it touches (press depth measured against that key's top).
struct Baseline {
  double x_mm = 0.0;
  double bend_rad = 0.0;
  double z_mm = 0.0;
  const KeyContact* touching = nullptr;
};

double key_top(const KeyHeights& keys, bool black) {
  return black ? keys.black_top_z_mm : keys.white_top_z_mm;
}

double bend_for(const FingerGeometry& g, bool black) {
  return black ? g.black_bend_rad : g.white_bend_rad;
}

// Where the finger is after `prev`'s key (none: at rest), before the next contact takes over.
// One exponential at most: the relaxation decay since prev's offset; the hover height's decay
// since the release end is that value times the precomputed release_decay_scale.
// `lift_mm`: the hand's pass-over lift at t; a finger away from its key is that much higher.
Baseline baseline(const FingerMotionPlan& plan, const FingerGeometry& g, const KeyContact* prev,
                  double rest_x_mm, double t_s, double lift_mm) {
  const KeyHeights& keys = plan.keys;
  const double neutral_z = plan.neutral_z_mm + lift_mm;
  if (prev == nullptr) return {rest_x_mm, g.neutral_bend_rad, neutral_z, nullptr};
  const double top = key_top(keys, prev->black);
  const double bend = bend_for(g, prev->black);
  if (t_s <= prev->offset_s) return {prev->x_mm, bend, prev->bottom_z_mm, prev};
  const double decay = std::exp(-(t_s - prev->offset_s) * plan.relax_rate_per_s);
  Baseline b;
  b.x_mm = rest_x_mm + prev->release_offset_mm * decay;
  b.bend_rad = g.neutral_bend_rad + (bend - g.neutral_bend_rad) * decay;
  b.touching = prev;
  if (t_s < prev->release_end_s) {
    const double u = (t_s - prev->offset_s) * prev->inv_release_s;
    b.z_mm = prev->bottom_z_mm + (top + keys.hover_lift_mm + lift_mm - prev->bottom_z_mm) * min_jerk(u);
  } else {
    // The finger settles toward its rest height but no lower than the top of the key it left:
    // a finger resting on a key does not press it (the rest height is below a black key's top).
    const double hover = top + keys.hover_lift_mm + lift_mm;
    b.z_mm = std::max(neutral_z + (hover - neutral_z) * (decay * prev->release_decay_scale), top);
  }
  return b;
}

// The cached shape when the bend is one of the planned values, else computed.
// The most a holding finger bends to keep its pad on its spot (about 92°: past it the finger
// would stand on its nail).
constexpr double kMostHoldingBendRad = 1.6;
// How far a holding finger takes up the hand's move in or out (mm), and the least share of its
// reach into the keys it keeps doing so.
constexpr double kMostHeldInMm = 10.0;
constexpr double kLeastHeldReachShare = 0.8;

ChainShape shape_for(const FingerMotionPlan& plan, std::size_t f, double bend_rad) {
  if (bend_rad == plan.white_shape[f].bend_rad) return plan.white_shape[f];
  if (bend_rad == plan.black_shape[f].bend_rad) return plan.black_shape[f];
  if (bend_rad == plan.neutral_shape[f].bend_rad) return plan.neutral_shape[f];
  return chain_shape(plan.geometry[f], bend_rad);
}

}  // namespace

void evaluate_finger_pose(const FingerMotionPlan& plan, components::HandSide side, int finger,
                          double hand_x_mm, double t_s, FingerPose& out) noexcept {
  const std::size_t f = static_cast<std::size_t>(std::clamp(finger, 1, 5) - 1);
  const HandFingerPlan& hand = plan.hand(side);
  const FingerGeometry& g = plan.geometry[f];
  const KeyHeights& keys = plan.keys;
  const std::span<const KeyContact> contacts(hand.fingers[f]);
  const std::span<const double> onsets(hand.onsets_s[f]);
  const double rest_x = hand_x_mm + hand.rest_offset_mm[f];

  // First contact with onset > t (NaN compares false: "before everything"), searched in the
  // contiguous onsets.
  const std::size_t next_index = static_cast<std::size_t>(
      std::upper_bound(onsets.begin(), onsets.end(), t_s,
                       [](double t, double onset) { return !(onset <= t); }) -
      onsets.begin());
  const KeyContact* prev = next_index == 0 ? nullptr : &contacts[next_index - 1];
  const KeyContact* next = next_index == contacts.size() ? nullptr : &contacts[next_index];

  // Once the next stroke has started (and the lateral move with it), the next contact decides
  // everything: bend, hover height and x would be overwritten exactly (blend at u >= 1), so the
  // previous key's relaxation is not evaluated at all.
  const bool next_decides =
      next != nullptr && t_s >= next->stroke_start_s && t_s >= next->move_start_s;
  // Passing over the other hand the whole hand is higher (pass_over.hpp): a finger away from the
  // keys with it, a pressing one reaching down from it, straighter.
  const double lift = evaluate_pass_over(hand.pass_over, t_s);
  Baseline b;
  if (!next_decides) b = baseline(plan, g, prev, rest_x, t_s, lift);
  double x = b.x_mm;
  double bend = b.bend_rad;
  double z = b.z_mm;
  const KeyContact* touching = b.touching;
  double depth = 0.0;
  if (touching != nullptr) {
    depth =
        std::clamp((key_top(keys, touching->black) - z) * touching->inv_travel_per_mm, 0.0, 1.0);
    if (t_s <= touching->offset_s) depth = 1.0;
  }

  if (next != nullptr) {
    if (t_s >= next->move_start_s) {
      // A textbook minimum-jerk move: from where the finger was when it left (at rest there
      // relative to the move), so it starts and arrives with zero velocity.
      x = blend(next->move_from_x_mm, next->x_mm,
                min_jerk((t_s - next->move_start_s) * next->inv_move_s));
    }
    if (t_s >= next->shape_start_s) {
      const double top = key_top(keys, next->black);
      // At or after the stroke start the shaping is over: u = 1 exactly.
      const double u = t_s < next->stroke_start_s
                           ? min_jerk((t_s - next->shape_start_s) * next->inv_shape_s)
                           : 1.0;
      bend = blend(bend, bend_for(g, next->black), u);
      z = blend(z, top + keys.hover_lift_mm + lift, u);
      if (t_s >= next->stroke_start_s) {
        const double w = (t_s - next->stroke_start_s) * next->inv_stroke_s;
        z = blend(z, next->bottom_z_mm, w * w);
        touching = next;
        depth = std::clamp((top - z) * next->inv_travel_per_mm, 0.0, 1.0);
      } else if (touching != nullptr && t_s < touching->release_end_s) {
        // Still letting the last key up. Once that is over the finger has left it: shaping for
        // a white key after a black one lowers the finger below the black key's top, beside it.
        depth = std::clamp((key_top(keys, touching->black) - z) * touching->inv_travel_per_mm, 0.0,
                           1.0);
      }
    }
  }

  // z is where the finger meets the key (its pad); the fingertip is held pad_drop above it.
  const double root_z = g.root_z_mm + lift;
  ChainShape shape = lift > 0.0
                         ? reaching_shape(g, shape_for(plan, f, bend), root_z - (z + g.pad_drop_mm))
                         : shape_for(plan, f, bend);
  StrokeSolution stroke = solve_stroke(shape, root_z - (z + g.pad_drop_mm));
  // A finger holding its key keeps its pad where it landed: when the hand reaches in or out
  // meanwhile (for a black key under another finger), the finger straightens or flexes rather
  // than sliding along the key (it slid up to 12 mm, tests/export/check_contacts.py).
  // As the key rises the finger eases back to its own shape (minimum jerk over the release):
  // it is leaving the key, and a sudden return would snap the joints.
  // Fingers 2-5 only, and not while the hand passes over the other one (its fingers reach down
  // straighter then: reaching_shape). The thumb lies along the keys on its side: flexing its
  // MCP and IP to take up a move dips it toward the other hand's thumb.
  if (touching != nullptr && f != 0 && lift == 0.0 && t_s > touching->onset_s &&
      t_s < touching->release_end_s) {
    const double letting_go =
        t_s <= touching->offset_s ? 0.0 : min_jerk((t_s - touching->offset_s) * touching->inv_release_s);
    const double moved_in =
        (1.0 - letting_go) *
        (tutti::spline_motion::evaluate_plateau_envelope(hand.reach_in, t_s) -
         tutti::spline_motion::evaluate_plateau_envelope(hand.reach_in, touching->onset_s));
    if (moved_in != 0.0) {
      // Up to a centimetre, and never pulling the tip in under the knuckle (its spread would
      // swing as the reach shrinks): beyond that the pad slides.
      const double reach = std::max(stroke.reach_y_mm - std::clamp(moved_in, -kMostHeldInMm, kMostHeldInMm),
                                    kLeastHeldReachShare * stroke.reach_y_mm);
      shape = shape_reaching_y(g, root_z - (z + g.pad_drop_mm), reach, kMostHoldingBendRad);
      stroke = solve_stroke(shape, root_z - (z + g.pad_drop_mm));
    }
  }
  const double mirror = side == components::HandSide::left ? -1.0 : 1.0;
  out.spread_rad = spread_angle_rad(x - rest_x, stroke.reach_y_mm, mirror);
  if (f == 0) {  // thumb: strikes by abduction; the bend is its MCP and IP
    out.abduction_rad = stroke.joint1_rad;
    out.mcp_flexion_rad = shape.bend_rad;
    out.pip_flexion_rad = shape.joint3_rad;
    out.dip_flexion_rad = 0.0;
  } else {
    out.abduction_rad = 0.0;
    out.mcp_flexion_rad = stroke.joint1_rad;
    out.pip_flexion_rad = shape.bend_rad;
    out.dip_flexion_rad = shape.joint3_rad;
  }
  out.press_depth = depth;
  out.key = depth > 0.0 && touching != nullptr ? touching->key : -1;
  const double hand_in = tutti::spline_motion::evaluate_plateau_envelope(hand.reach_in, t_s) +
                         lift * hand.pass_over.in_per_lift;
  out.tip_x_mm = x;
  out.tip_y_mm = g.root_y_mm + hand_in + stroke.reach_y_mm;
  out.tip_z_mm = z + g.pad_drop_mm;
  out.contact_y_mm = g.pad_drop_mm > 0.0
                         ? g.root_y_mm + hand_in + solve_stroke(shape, root_z - z).reach_y_mm
                         : out.tip_y_mm;
  out.contact_z_mm = z;
}

void evaluate_hand_pose(const FingerMotionPlan& plan, const spline_motion::HandPath& path,
                        components::HandSide side, double t_s, HandPose& out) noexcept {
  const spline_motion::HandState state = spline_motion::evaluate(path, t_s);
  out.x_mm = state.x_mm;
  out.v_x_mm_per_s = state.v_mm_per_s;
  const HandFingerPlan& hand = plan.hand(side);
  const double lift = evaluate_pass_over(hand.pass_over, t_s);
  out.y_mm = plan.geometry[2].root_y_mm +
             tutti::spline_motion::evaluate_plateau_envelope(hand.reach_in, t_s) +
             lift * hand.pass_over.in_per_lift;
  out.z_mm = plan.geometry[2].root_z_mm + lift;
  for (int finger = 1; finger <= 5; ++finger) {
    evaluate_finger_pose(plan, side, finger, state.x_mm, t_s,
                         out.fingers[static_cast<std::size_t>(finger - 1)]);
  }
}

}  // namespace tutti::finger_motion
