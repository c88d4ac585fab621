// SPDX-License-Identifier: MIT
#include <tutti/finger_motion/plan_finger_motion.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <tutti/finger_motion/plan_pass_over.hpp>

namespace tutti::finger_motion {
namespace {

using components::HandSide;

Error note_error(const music::Score& score, std::size_t index, const std::string& reason) {
  const std::string file = score.source.empty() ? std::string("score") : score.source;
  return Error{file + ": note " + std::to_string(index) + ": " + reason};
}

// 1 / span, or 0 for a span that is not positive (only absurd times: the spans evaluate divides
// by are positive by the KeyContact invariants).
double reciprocal(double span) { return span > 0.0 ? 1.0 / span : 0.0; }

// The values evaluate would otherwise recompute on every call (KeyContact's last fields).
void precompute_for_evaluate(KeyContact& c, const StrokeTiming& timing) {
  c.inv_move_s = reciprocal(c.onset_s - c.move_start_s);
  c.inv_shape_s = reciprocal(c.stroke_start_s - c.shape_start_s);
  c.inv_stroke_s = reciprocal(c.onset_s - c.stroke_start_s);
  c.inv_release_s = reciprocal(c.release_end_s - c.offset_s);
  c.release_decay_scale = std::exp((c.release_end_s - c.offset_s) / timing.relax_time_constant_s);
}

// How far past the ends of its range (piano_model::FingerRange) a finger still holds a key as the
// hand moves on. Half a white key (12 mm) left pads up to 12 mm beside their keys on 11 third-party
// pieces; 0, 2 and 4 mm all put them on: 4 keeps a little of the spread's give.
constexpr double kHoldBeyondRangeMm = 4.0;
constexpr double kDepartureStepS = 0.005;

// The first time in [onset, offset] at which the hand has moved so far that the key at key_x
// lies outside the finger's reach: there the finger lets the key go (a pianist leaving a held
// note for the next position, the pedal or nothing holding it), else `offset_s`.
double hand_departure_s(const KeyContact& c, const piano_model::FingerRange& range,
                        const spline_motion::HandPath& path) {
  if (path.empty()) return c.offset_s;
  // A key the hand already struck from outside the range (a stretch the path allowed) is let
  // go only when the hand takes it further out still.
  const double at_onset = c.x_mm - spline_motion::evaluate(path, c.onset_s).x_mm;
  const double lo = std::min(range.lo_mm, at_onset) - kHoldBeyondRangeMm;
  const double hi = std::max(range.hi_mm, at_onset) + kHoldBeyondRangeMm;
  for (double t = c.onset_s + kDepartureStepS; t < c.offset_s; t += kDepartureStepS) {
    const double offset = c.x_mm - spline_motion::evaluate(path, t).x_mm;
    if (offset < lo || offset > hi) {
      return t - kDepartureStepS;
    }
  }
  return c.offset_s;
}

// Sorts, merges same-onset contacts and trims offsets: to the same finger's next stroke and to
// the hand's departure. `preset_strokes`: each contact's stroke_start_s is already the one
// wanted (a NoteStroke's).
void order_contacts(std::vector<KeyContact>& contacts, const piano_model::FingerRange& range,
                    const spline_motion::HandPath& path, const StrokeTiming& timing,
                    bool preset_strokes) {
  std::sort(contacts.begin(), contacts.end(), [](const KeyContact& a, const KeyContact& b) {
    return a.onset_s != b.onset_s ? a.onset_s < b.onset_s : a.key < b.key;
  });
  std::vector<KeyContact> merged;
  merged.reserve(contacts.size());
  for (const KeyContact& c : contacts) {
    if (!merged.empty() && merged.back().onset_s == c.onset_s) {
      merged.back().offset_s = std::max(merged.back().offset_s, c.offset_s);
      continue;
    }
    merged.push_back(c);
  }
  // Pass 1: stroke starts, and offsets trimmed to the next stroke of the same finger.
  for (std::size_t j = 0; j < merged.size(); ++j) {
    KeyContact& c = merged[j];
    if (!preset_strokes) c.stroke_start_s = c.onset_s - timing.press_lead_s;
    if (j > 0) {
      KeyContact& prev = merged[j - 1];
      c.stroke_start_s = std::max(c.stroke_start_s, prev.onset_s);
      prev.offset_s = std::min(prev.offset_s, c.stroke_start_s);
    }
  }
  // A key is held only while the hand keeps it in the finger's reach.
  for (KeyContact& c : merged) c.offset_s = std::max(c.onset_s, hand_departure_s(c, range, path));
  contacts = std::move(merged);
}

// The most a key is let go early for the other hand: its stroke's lead and the key's rise.
double most_early_let_go_s(const StrokeTiming& timing) {
  return timing.press_lead_s + timing.release_s;
}

// A pianist lets a key go before the other hand strikes right beside it or beyond it (a thumb
// under the other thumb, one hand taking over the other's key): the finger is up and out of the
// way when the other finger comes down, instead of rising through it. A contact whose offset
// falls within `most_early_let_go_s` before such a stroke ends that long before the stroke
// starts (never before its own onset). "Beside or beyond": the struck key is at most a whole
// tone from the held one on the held hand's own side or anywhere on the other side.
void let_go_before_the_other_hand(HandFingerPlan& held, const HandFingerPlan& striking,
                                  const StrokeTiming& timing) {
  constexpr int kBesideSemitones = 2;
  const double early = most_early_let_go_s(timing);
  // Times (struck key - held key): > 0 where the struck key lies toward the held hand's own side
  // (the right hand's is up the keyboard).
  const int toward_own_side = held.side == HandSide::right ? 1 : -1;
  for (std::vector<KeyContact>& finger : held.fingers) {
    for (KeyContact& c : finger) {
      double let_go = c.offset_s;
      for (const std::vector<KeyContact>& other : striking.fingers) {
        // Strokes starting from `early` before the offset to the end of the key's rise.
        auto n = std::lower_bound(other.begin(), other.end(), c.offset_s - early,
                                  [](const KeyContact& k, double t) { return k.stroke_start_s < t; });
        for (; n != other.end() && n->stroke_start_s < c.offset_s + timing.release_s; ++n) {
          if (n->onset_s <= c.onset_s) continue;
          if (toward_own_side * (n->key - c.key) < -kBesideSemitones) continue;
          let_go = std::min(let_go, n->stroke_start_s - timing.release_s);
        }
      }
      c.offset_s = std::max(c.onset_s, let_go);
    }
  }
}

// Fills the moves, shaping and releases of a finger's ordered contacts (order_contacts).
void time_contacts(std::vector<KeyContact>& merged, double rest_offset_mm,
                   const spline_motion::HandPath& path, const StrokeTiming& timing) {
  for (std::size_t j = 0; j < merged.size(); ++j) {
    KeyContact& c = merged[j];
    const KeyContact* prev = j > 0 ? &merged[j - 1] : nullptr;
    const double from_x =
        prev != nullptr ? prev->x_mm : spline_motion::evaluate(path, c.onset_s).x_mm + rest_offset_mm;
    const double duration =
        std::clamp(timing.move_min_s + timing.move_s_per_mm * std::abs(c.x_mm - from_x),
                   timing.move_min_s, timing.move_max_s);
    c.move_start_s = c.onset_s - duration;
    c.shape_start_s = c.stroke_start_s - timing.shape_s;
    if (prev != nullptr) {
      c.move_start_s = std::max(c.move_start_s, prev->offset_s);
      c.shape_start_s = std::max(c.shape_start_s, prev->offset_s);
    }
    // Where the tip is when it leaves: on the previous key, relaxing from it, or at rest.
    const double rest_at_move = spline_motion::evaluate(path, c.move_start_s).x_mm + rest_offset_mm;
    if (prev == nullptr) {
      c.move_from_x_mm = rest_at_move;
    } else if (c.move_start_s <= prev->offset_s) {
      c.move_from_x_mm = prev->x_mm;
    } else {
      c.move_from_x_mm =
          rest_at_move + prev->release_offset_mm * std::exp(-(c.move_start_s - prev->offset_s) /
                                                            timing.relax_time_constant_s);
    }
    c.release_end_s = c.offset_s + timing.release_s;
    c.release_offset_mm = c.x_mm - (spline_motion::evaluate(path, c.offset_s).x_mm + rest_offset_mm);
    precompute_for_evaluate(c, timing);
  }
}

// Where a contact's pad lands (y, into the keys) with the hand at its rest line.
double lands_y_mm(const FingerMotionPlan& plan, std::size_t f, const KeyContact& c) {
  const FingerGeometry& g = plan.geometry[f];
  const ChainShape& shape = c.black ? plan.black_shape[f] : plan.white_shape[f];
  // The pad lies under the tip (the thumb's, pad_drop_mm under it): where the tip is.
  return g.root_y_mm + solve_stroke(shape, g.root_z_mm - (c.bottom_z_mm + g.pad_drop_mm)).reach_y_mm;
}

// How far the hand sits in toward the fallboard, beyond its rest line, over time. A short finger
// (the little finger, the thumb) cannot reach a black key from where it strikes the white keys:
// the black keys begin about 55 mm behind the white keys' front edge. Pianists move the whole
// hand in while such a key is struck and held, and back out when it is let go. Each contact
// needs the hand in far enough that the finger's pad, bent for its key and at the key bottom,
// lands on the key: press_in behind its front edge (a black key's begins black_front_y_mm in).
tutti::spline_motion::PlateauEnvelope plan_hand_reach_in(const HandFingerPlan& side,
                                                  const FingerMotionPlan& plan) {
  std::vector<tutti::spline_motion::EnvelopeNeed> needs;
  const KeyHeights& keys = plan.keys;
  for (std::size_t f = 0; f < 5; ++f) {
    for (const KeyContact& c : side.fingers[f]) {
      const double target_y =
          c.black ? keys.black_front_y_mm + keys.black_press_in_mm : keys.white_press_in_mm;
      needs.push_back({c.shape_start_s, c.release_end_s, target_y - lands_y_mm(plan, f, c)});
    }
  }
  return tutti::spline_motion::plan_plateau_envelope(std::move(needs), plan.timing.reach_in_s,
                                              plan.timing.reach_in_bridge_s);
}

// The key bed under each contact where its pad meets the key, the hand moved in: a lever's key
// travels less nearer its pivot. The drop and the reach depend on each other; a few rounds
// settle it (as key_action's contact geometry does). A contact's planned travel is the travel at
// the key's front edge, or with `strokes_travel_at_rest` (NoteStroke's, from key_action) the
// travel where the pad lands with the hand at its rest line.
void settle_key_beds(HandFingerPlan& side, const FingerMotionPlan& plan,
                     bool strokes_travel_at_rest) {
  const KeyHeights& keys = plan.keys;
  if (keys.pivot_y_mm <= 0.0) return;
  for (std::size_t f = 0; f < 5; ++f) {
    const FingerGeometry& g = plan.geometry[f];
    for (KeyContact& c : side.fingers[f]) {
      const double top = c.black ? keys.black_top_z_mm : keys.white_top_z_mm;
      const double front = c.black ? keys.black_front_y_mm : 0.0;
      const double planned = top - c.bottom_z_mm;
      const double planned_at =
          strokes_travel_at_rest ? std::clamp(lands_y_mm(plan, f, c), front, keys.pivot_y_mm - 1.0)
                                 : front;
      const double travel_at_front = planned * (keys.pivot_y_mm - front) / (keys.pivot_y_mm - planned_at);
      const double hand_in = tutti::spline_motion::evaluate_plateau_envelope(side.reach_in, c.onset_s);
      // Starting from the planned travel: where the hand is at its rest line that is already
      // the answer (exactly, not to the last rounding of the rounds below).
      double travel = planned;
      for (int round = 0; round < 4; ++round) {
        const ChainShape& shape = c.black ? plan.black_shape[f] : plan.white_shape[f];
        const double y = std::clamp(
            g.root_y_mm + hand_in +
                solve_stroke(shape, g.root_z_mm - (top - travel + g.pad_drop_mm)).reach_y_mm,
            front, keys.pivot_y_mm);
        travel = travel_at_front * (keys.pivot_y_mm - y) / (keys.pivot_y_mm - front);
      }
      c.bottom_z_mm = top - travel;
      c.inv_travel_per_mm = 1.0 / travel;
    }
  }
}

}  // namespace

Result<FingerMotionPlan> plan_finger_motion(
    const music::Score& score, const fingering_planner::ScorePlan& score_plan,
    const spline_motion::HandPath& right_path, const spline_motion::HandPath& left_path,
    const piano_model::Keyboard& keyboard, const piano_model::HandModel& hand_model,
    const FingerMotionParams& params, std::span<const NoteStroke> strokes) {
  const std::size_t count = score.notes.size();
  if (!strokes.empty() && strokes.size() != count) {
    return Error{(score.source.empty() ? std::string("score") : score.source) + ": " +
                 std::to_string(strokes.size()) + " note strokes for " + std::to_string(count) +
                 " notes"};
  }
  if (score_plan.fingers.size() != count || score_plan.hands.size() != count) {
    return Error{(score.source.empty() ? std::string("score") : score.source) +
                 ": fingering plan has " + std::to_string(score_plan.fingers.size()) +
                 " fingers and " + std::to_string(score_plan.hands.size()) + " hands for " +
                 std::to_string(count) + " notes"};
  }
  FingerMotionPlan plan;
  plan.keys = params.keys;
  plan.timing = params.timing;
  plan.relax_rate_per_s = 1.0 / params.timing.relax_time_constant_s;
  plan.neutral_z_mm = params.keys.white_top_z_mm + params.keys.hover_lift_mm;
  plan.geometry = scaled_geometry(params, hand_model);
  for (std::size_t f = 0; f < 5; ++f) {
    const FingerGeometry& g = plan.geometry[f];
    plan.neutral_shape[f] = chain_shape(g, g.neutral_bend_rad);
    plan.white_shape[f] = chain_shape(g, g.white_bend_rad);
    plan.black_shape[f] = chain_shape(g, g.black_bend_rad);
    const int finger = static_cast<int>(f) + 1;
    const piano_model::FingerRange right = hand_model.range(music::Hand::right, finger);
    const piano_model::FingerRange left = hand_model.range(music::Hand::left, finger);
    plan.right.rest_offset_mm[f] = 0.5 * (right.lo_mm + right.hi_mm);
    plan.left.rest_offset_mm[f] = 0.5 * (left.lo_mm + left.hi_mm);
  }

  for (std::size_t i = 0; i < count; ++i) {
    const music::Note& note = score.notes[i];
    const int finger = score_plan.fingers[i];
    if (finger < 0 || finger > 5) return note_error(score, i, "finger outside 0..5");
    const music::Hand hand = score_plan.hands[i];
    if (finger == 0 || hand == music::Hand::unknown) continue;  // not played (percussion)
    if (!std::isfinite(note.onset_s) || !std::isfinite(note.offset_s)) {
      return note_error(score, i, "non-finite time");
    }
    if (note.offset_s < note.onset_s) return note_error(score, i, "offset before onset");
    KeyContact c;
    c.key = std::clamp(note.pitch, keyboard.lowest_key(), keyboard.highest_key());
    c.x_mm = keyboard.x_mm(c.key);
    c.black = keyboard.is_black(c.key);
    c.onset_s = note.onset_s;
    c.offset_s = note.offset_s;
    double travel = params.keys.dip_mm;
    if (!strokes.empty()) {
      const NoteStroke& stroke = strokes[i];
      if (!std::isfinite(stroke.stroke_start_s) || !std::isfinite(stroke.bottom_s) ||
          !std::isfinite(stroke.release_s) || !(stroke.stroke_start_s < stroke.bottom_s) ||
          !(stroke.travel_mm > 0.0)) {
        return note_error(score, i, "invalid stroke (start before bottom, travel > 0)");
      }
      c.onset_s = stroke.bottom_s;
      c.stroke_start_s = stroke.stroke_start_s;
      c.offset_s = std::max(stroke.release_s, stroke.bottom_s);
      travel = stroke.travel_mm;
    }
    const double top = c.black ? params.keys.black_top_z_mm : params.keys.white_top_z_mm;
    c.bottom_z_mm = top - travel;
    c.inv_travel_per_mm = 1.0 / travel;
    c.note = static_cast<int>(i);
    HandFingerPlan& side = hand == music::Hand::left ? plan.left : plan.right;
    side.fingers[static_cast<std::size_t>(finger - 1)].push_back(c);
  }
  for (HandFingerPlan* side : {&plan.right, &plan.left}) {
    const spline_motion::HandPath& path = side->side == HandSide::left ? left_path : right_path;
    const music::Hand hand = side->side == HandSide::left ? music::Hand::left : music::Hand::right;
    for (std::size_t f = 0; f < 5; ++f) {
      order_contacts(side->fingers[f], hand_model.range(hand, static_cast<int>(f) + 1), path,
                     plan.timing, !strokes.empty());
    }
  }
  // Both hands' strokes are known: each lets go where the other strikes beside it.
  let_go_before_the_other_hand(plan.right, plan.left, plan.timing);
  let_go_before_the_other_hand(plan.left, plan.right, plan.timing);
  for (HandFingerPlan* side : {&plan.right, &plan.left}) {
    const spline_motion::HandPath& path = side->side == HandSide::left ? left_path : right_path;
    for (std::size_t f = 0; f < 5; ++f) {
      time_contacts(side->fingers[f], side->rest_offset_mm[f], path, plan.timing);
      side->onsets_s[f].reserve(side->fingers[f].size());
      for (const KeyContact& c : side->fingers[f]) side->onsets_s[f].push_back(c.onset_s);
    }
    side->reach_in = plan_hand_reach_in(*side, plan);
    settle_key_beds(*side, plan, !strokes.empty());
  }
  plan_pass_over(plan, right_path, left_path, params.pass_over);
  return plan;
}

std::array<FingerGeometry, 5> scaled_geometry(const FingerMotionParams& params,
                                              const piano_model::HandModel& hand_model) {
  const double scale = hand_model.scale();
  std::array<FingerGeometry, 5> geometry = params.fingers;
  for (FingerGeometry& g : geometry) {
    for (double& length : g.phalanges_mm) length *= scale;
    g.root_y_mm *= scale;
    g.root_z_mm *= scale;
    g.pad_drop_mm *= scale;
  }
  return geometry;
}

}  // namespace tutti::finger_motion
