// SPDX-License-Identifier: MIT
// evaluate_finger_pose reads values plan_finger_motion precomputed (reciprocals of the contact's
// spans, the release decay scale, the contiguous onsets), skips the relaxation once the next
// stroke decides the pose, and solves the stroke with one atan2. This checks it against the
// motion model written out directly from the KeyContact timing fields (divisions and two
// exponentials on every call, a search over the contacts themselves, the chain as R and alpha,
// asin(drop / R) - alpha): the same pose within rounding, at every kind of moment.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <tutti/finger_motion/evaluate_hand_pose.hpp>
#include "finger_motion_fixture.hpp"

namespace tutti::finger_motion {
namespace {

using components::HandSide;

// The model as README.md states it, from the timing fields only.
FingerPose reference_finger_pose(const FingerMotionPlan& plan, HandSide side, std::size_t f,
                                 double hand_x_mm, double t) {
  const HandFingerPlan& hand = plan.hand(side);
  const FingerGeometry& g = plan.geometry[f];
  const KeyHeights& keys = plan.keys;
  const double tau = plan.timing.relax_time_constant_s;
  const std::vector<KeyContact>& contacts = hand.fingers[f];
  const double rest_x = hand_x_mm + hand.rest_offset_mm[f];
  const auto top_of = [&](bool black) { return black ? keys.black_top_z_mm : keys.white_top_z_mm; };
  const auto bend_of = [&](bool black) { return black ? g.black_bend_rad : g.white_bend_rad; };
  const KeyContact* prev = nullptr;
  const KeyContact* next = nullptr;
  for (const KeyContact& c : contacts) {
    if (c.onset_s <= t) {
      prev = &c;
    } else {
      next = &c;
      break;
    }
  }
  const double neutral_z = keys.white_top_z_mm + keys.hover_lift_mm;
  double x = rest_x;
  double bend = g.neutral_bend_rad;
  double z = neutral_z;
  const KeyContact* touching = nullptr;
  double depth = 0.0;
  if (prev != nullptr) {
    touching = prev;
    const double top = top_of(prev->black);
    if (t <= prev->offset_s) {
      x = prev->x_mm;
      bend = bend_of(prev->black);
      z = prev->bottom_z_mm;
    } else {
      const double decay = std::exp(-(t - prev->offset_s) / tau);
      x = rest_x + prev->release_offset_mm * decay;
      bend = g.neutral_bend_rad + (bend_of(prev->black) - g.neutral_bend_rad) * decay;
      if (t < prev->release_end_s) {
        const double u = (t - prev->offset_s) / (prev->release_end_s - prev->offset_s);
        z = prev->bottom_z_mm + (top + keys.hover_lift_mm - prev->bottom_z_mm) * min_jerk(u);
      } else {
        const double hover = top + keys.hover_lift_mm;
        // Settling toward the rest height, never below the top of the key it left.
        z = std::max(neutral_z + (hover - neutral_z) * std::exp(-(t - prev->release_end_s) / tau),
                     top);
      }
    }
    depth = t <= prev->offset_s ? 1.0 : std::clamp((top - z) / (top - prev->bottom_z_mm), 0.0, 1.0);
  }
  if (next != nullptr) {
    if (t >= next->move_start_s) {
      x = blend(next->move_from_x_mm, next->x_mm,
                min_jerk((t - next->move_start_s) / (next->onset_s - next->move_start_s)));
    }
    if (t >= next->shape_start_s) {
      const double top = top_of(next->black);
      const double span = next->stroke_start_s - next->shape_start_s;
      const double u = span > 0 ? min_jerk((t - next->shape_start_s) / span) : 1.0;
      bend = blend(bend, bend_of(next->black), u);
      z = blend(z, top + keys.hover_lift_mm, u);
      if (t >= next->stroke_start_s) {
        const double w = (t - next->stroke_start_s) / (next->onset_s - next->stroke_start_s);
        z = blend(z, next->bottom_z_mm, w * w);
        touching = next;
        depth = std::clamp((top - z) / (top - next->bottom_z_mm), 0.0, 1.0);
      } else if (touching != nullptr && t < touching->release_end_s) {
        const double top_touching = top_of(touching->black);
        depth = std::clamp((top_touching - z) / (top_touching - touching->bottom_z_mm), 0.0, 1.0);
      }
    }
  }
  // The chain past joint 1 as length R at angle alpha; the stroke angle asin(drop / R) - alpha.
  const auto chain_r = [&g](double bend_rad) {
    const double j = g.coupling * bend_rad;
    return std::hypot(g.phalanges_mm[0] + g.phalanges_mm[1] * std::cos(bend_rad) +
                          g.phalanges_mm[2] * std::cos(bend_rad + j),
                      g.phalanges_mm[1] * std::sin(bend_rad) + g.phalanges_mm[2] * std::sin(bend_rad + j));
  };
  const double drop_wanted = g.root_z_mm - (z + g.pad_drop_mm);
  const auto reach_y_of = [&](double bend_rad) {
    const double r = chain_r(bend_rad);
    const double d = std::clamp(drop_wanted, -r, r);
    return std::sqrt(std::max(r * r - d * d, 0.0));
  };
  // A finger (not the thumb) holding its key takes up the hand's move in since the key went
  // down, up to 10 mm and keeping 80 % of its reach, by bending (bisection, 16 halvings of
  // 0..1.6 rad); it lets that go as the key rises (minimum jerk over the release).
  if (touching != nullptr && f != 0 && t > touching->onset_s && t < touching->release_end_s) {
    const double letting_go =
        t <= touching->offset_s
            ? 0.0
            : min_jerk((t - touching->offset_s) / (touching->release_end_s - touching->offset_s));
    const double moved_in = (1.0 - letting_go) *
                            (tutti::spline_motion::evaluate_plateau_envelope(hand.reach_in, t) -
                             tutti::spline_motion::evaluate_plateau_envelope(hand.reach_in, touching->onset_s));
    if (moved_in != 0.0) {
      const double own = reach_y_of(bend);
      const double wanted = std::max(own - std::clamp(moved_in, -10.0, 10.0), 0.8 * own);
      double lo = 0.0, hi = 1.6;
      for (int i = 0; i < 16; ++i) {
        const double mid = 0.5 * (lo + hi);
        (reach_y_of(mid) > wanted ? lo : hi) = mid;
      }
      bend = 0.5 * (lo + hi);
    }
  }
  const double j3 = g.coupling * bend;
  const double a = g.phalanges_mm[0] + g.phalanges_mm[1] * std::cos(bend) +
                   g.phalanges_mm[2] * std::cos(bend + j3);
  const double b = g.phalanges_mm[1] * std::sin(bend) + g.phalanges_mm[2] * std::sin(bend + j3);
  const double reach = std::hypot(a, b);
  const double drop = std::clamp(drop_wanted, -reach, reach);
  const double joint1 = std::asin(drop / reach) - std::atan2(b, a);
  const double reach_y = std::sqrt(std::max(reach * reach - drop * drop, 0.0));
  FingerPose out;
  out.spread_rad =
      std::atan((side == HandSide::left ? -1.0 : 1.0) * (x - rest_x) / std::max(reach_y, 1.0));
  out.abduction_rad = f == 0 ? joint1 : 0.0;
  out.mcp_flexion_rad = f == 0 ? bend : joint1;
  out.pip_flexion_rad = f == 0 ? j3 : bend;
  out.dip_flexion_rad = f == 0 ? 0.0 : j3;
  out.press_depth = depth;
  out.key = depth > 0.0 && touching != nullptr ? touching->key : -1;
  out.tip_x_mm = x;
  // The hand in toward the fallboard for black keys a short finger cannot reach otherwise.
  const double hand_in = tutti::spline_motion::evaluate_plateau_envelope(hand.reach_in, t);
  out.tip_y_mm = g.root_y_mm + hand_in + reach_y;
  out.tip_z_mm = z + g.pad_drop_mm;
  out.contact_z_mm = z;
  out.contact_y_mm = out.tip_y_mm;
  if (g.pad_drop_mm > 0.0) {
    const double contact_drop = std::clamp(g.root_z_mm - z, -reach, reach);
    out.contact_y_mm = g.root_y_mm + hand_in + std::sqrt(std::max(reach * reach - contact_drop * contact_drop, 0.0));
  }
  return out;
}

void expect_close(const FingerPose& got, const FingerPose& want, double t, std::size_t f) {
  SCOPED_TRACE(::testing::Message() << "finger " << f + 1 << " at t=" << t);
  constexpr double kTol = 1e-9;
  EXPECT_NEAR(got.spread_rad, want.spread_rad, kTol);
  EXPECT_NEAR(got.abduction_rad, want.abduction_rad, kTol);
  EXPECT_NEAR(got.mcp_flexion_rad, want.mcp_flexion_rad, kTol);
  EXPECT_NEAR(got.pip_flexion_rad, want.pip_flexion_rad, kTol);
  EXPECT_NEAR(got.dip_flexion_rad, want.dip_flexion_rad, kTol);
  EXPECT_NEAR(got.press_depth, want.press_depth, kTol);
  EXPECT_NEAR(got.tip_x_mm, want.tip_x_mm, kTol);
  EXPECT_NEAR(got.tip_y_mm, want.tip_y_mm, kTol);
  EXPECT_NEAR(got.tip_z_mm, want.tip_z_mm, kTol);
  EXPECT_NEAR(got.contact_y_mm, want.contact_y_mm, kTol);
  EXPECT_NEAR(got.contact_z_mm, want.contact_z_mm, kTol);
  // The key is reported while pressed; right at depth 0 rounding may decide either way.
  if (want.press_depth > kTol) {
    EXPECT_EQ(got.key, want.key);
  }
}

TEST(EvaluateHandPoseReference, PrecomputedPlanGivesTheModelsPose) {
  // Both hands, every finger; white and black keys; chords merging on one finger; gaps from
  // 10 ms to several seconds (short and long relaxations); zero-length notes.
  std::mt19937_64 rng(11);
  std::vector<test::TestNote> notes;
  double t = 0.3;
  for (int i = 0; i < 600; ++i) {
    const double gap = (rng() % 10 == 0) ? 1.0 + double(rng() % 4000) / 1000.0
                                         : 0.01 + double(rng() % 300) / 1000.0;
    t += gap;
    const double length = (rng() % 12 == 0) ? 0.0 : 0.02 + double(rng() % 600) / 1000.0;
    const bool left = rng() % 3 == 0;
    notes.push_back({(left ? 36 : 55) + static_cast<int>(rng() % 30), t, t + length,
                     1 + static_cast<int>(rng() % 5),
                     left ? music::Hand::left : music::Hand::right});
  }
  const double end_s = t + 3.0;
  // A hand that drifts, so rest lines and release offsets move.
  spline_motion::Poly5 piece;
  piece.c[0] = 650.0;
  piece.c[1] = 0.2;
  const spline_motion::HandPath right(spline_motion::SmoothingMode::none, {0.0, end_s}, {piece},
                               650.0 + 0.2 * end_s, true);
  const spline_motion::HandPath left = test::constant_path(350.0);
  const test::TestScore s = test::make_score(notes);
  const Models& m = test::models();
  auto plan = plan_finger_motion(s.score, s.plan, right, left, m.keyboard, m.hand, m.params);
  ASSERT_TRUE(plan.ok()) << plan.error().message;

  std::vector<double> times;
  for (double frame = -0.5; frame < end_s + 1.0; frame += 1.0 / 60) times.push_back(frame);
  for (const HandFingerPlan* hand : {&plan->right, &plan->left}) {
    for (const auto& contacts : hand->fingers) {
      for (const KeyContact& c : contacts) {
        for (double edge : {c.move_start_s, c.shape_start_s, c.stroke_start_s, c.onset_s,
                            c.offset_s, c.release_end_s}) {
          times.insert(times.end(), {std::nextafter(edge, -INFINITY), edge,
                                     std::nextafter(edge, INFINITY), edge + 0.01});
        }
      }
    }
  }
  std::size_t compared = 0;
  HandPose pose;
  for (const HandFingerPlan* hand : {&plan->right, &plan->left}) {
    const spline_motion::HandPath& path = hand->side == HandSide::left ? left : right;
    for (const double time : times) {
      evaluate_hand_pose(*plan, path, hand->side, time, pose);
      for (std::size_t f = 0; f < 5; ++f) {
        expect_close(pose.fingers[f], reference_finger_pose(*plan, hand->side, f, pose.x_mm, time),
                     time, f);
        ++compared;
        if (::testing::Test::HasFailure()) return;  // one report, not thousands
      }
    }
  }
  EXPECT_GT(compared, 100000u);
}

}  // namespace
}  // namespace tutti::finger_motion
