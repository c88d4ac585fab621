// SPDX-License-Identifier: MIT
#include <tutti/fingering_planner/transition_cost.hpp>

#include <algorithm>
#include <bit>
#include <cmath>

#include <tutti/music/pitch.hpp>

namespace tutti::fingering_planner {

// The piano model's names this planner uses (systems/piano_model).
using piano_model::FingerRange;

namespace {

// Pair term between a key struck by f0 at the previous event and one struck by f1 now
// (f0 != f1): natural spacing or crossing. `u` is the signed distance in white keys in the
// hand's direction (towards the little finger).
double pair_cost(int f0, int key0, int f1, int key1, double u, const CostWeights& w) {
  if (key0 == key1) return w.repeat_finger_change;
  const int df = f1 - f0;
  if ((u > 0) == (df > 0)) {
    const double deviation = std::abs(u) - std::abs(df) * w.spacing_per_finger;
    const double factor = (f0 == 1 || f1 == 1) ? w.spacing_thumb_factor : 1.0;
    return factor *
           (deviation > 0 ? w.spacing_stretch * deviation : w.spacing_compress * -deviation);
  }
  const int lo = std::min(f0, f1);
  const int hi = std::max(f0, f1);
  if (lo != 1) return w.cross_other;
  if (hi == 5) return w.cross_little;
  const int thumb_key = f0 == 1 ? key0 : key1;
  double cost = w.cross_thumb + w.cross_thumb_finger[static_cast<std::size_t>(hi - 1)] +
                w.cross_thumb_distance * std::max(0.0, std::abs(u) - 1.0);
  if (music::is_black_key(thumb_key)) cost += w.cross_thumb_black;
  return cost;
}

}  // namespace

double effective_dt(double release_to_attack_s, double inter_onset_s, const CostWeights& weights) {
  const double shift =
      std::min(weights.shift_time_s, (1.0 - weights.shift_hold_fraction) * inter_onset_s);
  return std::max({release_to_attack_s, weights.release_fraction * inter_onset_s, shift, 0.0});
}

std::optional<music::Hand> hand_of(const EventFingering& event, const FingeringModel& model) {
  if ((event.down & 1u) == 0 || event.lo_mm > event.hi_mm) return std::nullopt;
  // The area lies within the thumb's area of its own hand; the two hands' thumb areas are
  // mirror images around the thumb's key, so the part outside the other hand's area decides.
  // (x_mm is stored as float: compare within 0.01 mm.)
  constexpr double kTolerance_mm = 0.01;
  const double x = event.x_mm[0];
  auto fits = [&](music::Hand side) {
    const FingerRange& r = model.hand.range(side, 1);
    return event.lo_mm >= x - r.hi_mm - kTolerance_mm && event.hi_mm <= x - r.lo_mm + kTolerance_mm;
  };
  const bool right = fits(music::Hand::right);
  if (right == fits(music::Hand::left)) return std::nullopt;
  return right ? music::Hand::right : music::Hand::left;
}

EventFingering make_event_fingering(std::span<const FingeredKey> keys, music::Hand side,
                                    const FingeringModel& model) {
  EventFingering event;
  event.lo_mm = -1e300;
  event.hi_mm = 1e300;
  for (const FingeredKey& k : keys) {
    const auto index = static_cast<std::size_t>(k.finger - 1);
    const double x = model.keyboard.x_mm(k.key);
    const FingerRange& range = model.hand.range(side, k.finger);
    event.lo_mm = std::max(event.lo_mm, x - range.hi_mm);
    event.hi_mm = std::min(event.hi_mm, x - range.lo_mm);
    event.down = static_cast<std::uint8_t>(event.down | (1u << index));
    if (!k.held) event.struck = static_cast<std::uint8_t>(event.struck | (1u << index));
    event.key[index] = static_cast<std::int16_t>(k.key);
    event.x_mm[index] = static_cast<float>(x);
  }
  if (keys.empty()) event.lo_mm = event.hi_mm = 0.0;
  return event;
}

double strike_cost(const EventFingering& event, const FingeringModel& model) {
  const CostWeights& w = model.weights;
  double cost = 0.0;
  for (unsigned bits = event.struck; bits != 0; bits &= bits - 1) {
    const auto index = static_cast<std::size_t>(std::countr_zero(bits));
    cost += w.finger_use[index];
    if (music::is_black_key(event.key[index])) cost += w.black_key[index];
  }
  return cost;
}

double strike_cost(const EventFingering& event, const FingeringModel& model, int tonic,
                   std::optional<music::Hand> side) {
  double cost = strike_cost(event, model);
  if (tonic < 0 || (event.struck & 1u) == 0 || event.key[0] < 0 ||
      music::is_black_key(event.key[0])) {
    return cost;
  }
  const CostWeights& w = model.weights;
  const int pitch_class = event.key[0] % 12;
  if (pitch_class == tonic) return cost + w.thumb_on_tonic;
  if (w.thumb_on_fourth != 0.0) {
    if (!side) side = hand_of(event, model);
    // A perfect fourth (5 semitones) towards the little finger: up for the right hand.
    if (side && pitch_class == (tonic + (*side == music::Hand::left ? 7 : 5)) % 12) {
      cost += w.thumb_on_fourth;
    }
  }
  return cost;
}

double area_transition_cost(double lo_a, double hi_a, double lo_b, double hi_b, double dt_s,
                            const FingeringModel& model) {
  const CostWeights& w = model.weights;
  const double overlap = std::min(hi_a, hi_b) - std::max(lo_a, lo_b);
  if (overlap >= 0) {
    const double widest = std::max({hi_a - lo_a, hi_b - lo_b, 0.0});
    return widest > 0 ? w.area_overlap * (1.0 - overlap / widest) : 0.0;
  }
  if (dt_s <= 0) return kInfiniteCost;
  const double speed = (-overlap / model.keyboard.white_key_width_mm()) / dt_s;
  // Never cheaper than the worst overlap (areas that only touch): moving apart must not pay less.
  const double cost = std::max(w.gap_base, w.area_overlap) + w.gap_speed * speed;
  return speed > w.speed_limit ? cost + w.over_speed * (speed - w.speed_limit) : cost;
}

double transition_cost(const EventFingering& a, const EventFingering& b, double dt_s,
                       music::Hand side, const FingeringModel& model) {
  const CostWeights& w = model.weights;
  double cost = area_transition_cost(a.lo_mm, a.hi_mm, b.lo_mm, b.hi_mm, dt_s, model);

  // Same finger again: on the same key (a repeated note) or on another key.
  for (unsigned bits = a.down & b.struck; bits != 0; bits &= bits - 1) {
    const auto index = static_cast<std::size_t>(std::countr_zero(bits));
    if (a.key[index] == b.key[index]) {
      cost += w.same_finger_same_key;
    } else if (std::isinf(w.same_finger_other_key) || dt_s <= 0) {
      return kInfiniteCost;
    } else {
      const double distance =
          std::abs(double(b.x_mm[index]) - a.x_mm[index]) / model.keyboard.white_key_width_mm();
      cost += w.same_finger_other_key + w.same_finger_speed * distance / dt_s;
    }
  }

  // Spacing and crossing between the keys struck at a and those struck at b, for keys at most
  // spacing_max_distance white keys apart: beyond that the hand jumps and the fingers start
  // afresh.
  const unsigned from = a.struck;
  const unsigned to = b.struck;
  if (from == 0 || to == 0) return cost;
  const double direction = side == music::Hand::left ? -1.0 : 1.0;
  const double inv_white = direction / model.keyboard.white_key_width_mm();
  double pairs = 0.0;
  int count = 0;
  for (unsigned fa = from; fa != 0; fa &= fa - 1) {
    const int ia = std::countr_zero(fa);
    for (unsigned fb = to; fb != 0; fb &= fb - 1) {
      const int ib = std::countr_zero(fb);
      ++count;
      if (ia == ib) continue;
      const auto ua = static_cast<std::size_t>(ia);
      const auto ub = static_cast<std::size_t>(ib);
      const double u = (double(b.x_mm[ub]) - a.x_mm[ua]) * inv_white;
      if (std::abs(u) > w.spacing_max_distance) continue;
      pairs += pair_cost(ia + 1, a.key[ua], ib + 1, b.key[ub], u, w);
    }
  }
  return cost + pairs / count;
}

}  // namespace tutti::fingering_planner
