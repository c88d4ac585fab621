// SPDX-License-Identifier: MIT
#pragma once
// The cost model (Sekiguchi & Eiho 1999 plus the optional terms of CostWeights), on one event's
// fingering and between two consecutive events of one hand. Pure functions; the planners call
// exactly these, and the tests check the paper's rules through them.
//
// Units: x and hand areas in millimetres (keyboard x), times in seconds, costs dimensionless.
// An impossible transition costs +infinity (kInfiniteCost).

#include <array>
#include <cstdint>
#include <optional>
#include <span>

#include <tutti/fingering_planner/fingering_model.hpp>
#include <tutti/music/score.hpp>

namespace tutti::fingering_planner {

// One event's keys with their fingers, as the cost model sees them. Finger f is index f-1.
struct EventFingering {
  double lo_mm = 0.0;  // hand area (reference point); lo_mm > hi_mm when out of reach
  double hi_mm = 0.0;
  std::uint8_t down = 0;    // bit f-1: finger f is on a key during this event
  std::uint8_t struck = 0;  // bit f-1: finger f strikes its key at this event
  std::array<std::int16_t, 5> key{-1, -1, -1, -1, -1};  // MIDI key under each finger
  std::array<float, 5> x_mm{};                          // that key's x
};

struct FingeredKey {
  int key = 60;       // MIDI key (must be on the keyboard)
  int finger = 1;     // 1..5
  bool held = false;  // still held from an earlier event (not struck now)
};

// Builds the fingering of an event; the area is the intersection of every key's area.
// Precondition: keys on the keyboard, fingers 1..5 and distinct.
EventFingering make_event_fingering(std::span<const FingeredKey> keys, music::Hand side,
                                    const FingeringModel& model);

// Per-strike cost: finger use and black-key terms of the struck fingers.
double strike_cost(const EventFingering& event, const FingeringModel& model);
// The same plus, when the thumb strikes a white key (pitch class `tonic` of the key, -1 =
// unknown: no term), fingers.thumb_on_tonic on the tonic and fingers.thumb_on_fourth on the
// fourth from the tonic towards the little finger (a perfect fourth above it for the right hand,
// below it for the left). `side` = the hand; nullopt = read it from the event (hand_of).
double strike_cost(const EventFingering& event, const FingeringModel& model, int tonic,
                   std::optional<music::Hand> side = std::nullopt);

// The hand an event's fingering belongs to, when its area tells: the area lies inside the
// thumb's area of its own hand, and the two hands' thumb areas are mirror images around the
// thumb's key. nullopt when the thumb is not down, the area is empty, or it fits both hands.
std::optional<music::Hand> hand_of(const EventFingering& event, const FingeringModel& model);

// Area term alone: area_overlap × (1 - Δd/max(d)) when the areas overlap by Δd >= 0; otherwise
// max(gap_base, area_overlap) + gap_speed × s, with s = (gap in white keys) / dt the hand's mean
// speed, plus over_speed × (s - speed_limit) above the speed limit; infinite when dt <= 0. (A gap
// never costs less than the worst overlap; in the paper both are 1.)
double area_transition_cost(double lo_a, double hi_a, double lo_b, double hi_b, double dt_s,
                            const FingeringModel& model);

// Full cost of moving from event `a` to event `b`: area term, same-finger rules, spacing and
// crossing terms (between the keys struck at a and at b, when at most spacing_max_distance
// white keys apart: beyond, the hand jumps and the fingers start afresh). `dt_s` is the
// release-to-attack time (already raised by release_fraction × inter-onset interval, see
// effective_dt).
double transition_cost(const EventFingering& a, const EventFingering& b, double dt_s,
                       music::Hand side, const FingeringModel& model);

// Δt the cost model uses (and the time the hand path gets for a shift between disjoint areas):
// max(release_to_attack_s, release_fraction × inter_onset_s,
//     min(shift_time_s, (1 - shift_hold_fraction) × inter_onset_s)), >= 0.
double effective_dt(double release_to_attack_s, double inter_onset_s, const CostWeights& weights);

}  // namespace tutti::fingering_planner
