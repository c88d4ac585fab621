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

#include "fingering_planner/fingering_model.hpp"
#include "music/score.hpp"

namespace tutti::piano {

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
// The same plus fingers.thumb_on_tonic when the thumb strikes the tonic (pitch class `tonic`,
// -1 = unknown: no term).
double strike_cost(const EventFingering& event, const FingeringModel& model, int tonic);

// Area term alone: 1 - Δd/max(d) when the areas overlap by Δd >= 0; otherwise
// gap_base + gap_speed × (gap in white keys) / dt, infinite when dt <= 0.
double area_transition_cost(double lo_a, double hi_a, double lo_b, double hi_b, double dt_s,
                            const FingeringModel& model);

// Full cost of moving from event `a` to event `b`: area term, same-finger rules, spacing and
// crossing terms (between the keys struck at a and at b, when at most spacing_max_distance
// white keys apart: beyond, the hand jumps and the fingers start afresh). `dt_s` is the
// release-to-attack time (already raised by release_fraction × inter-onset interval, see
// effective_dt).
double transition_cost(const EventFingering& a, const EventFingering& b, double dt_s,
                       music::Hand side, const FingeringModel& model);

// Δt the cost model uses: max(release_to_attack_s, release_fraction × inter_onset_s), >= 0.
double effective_dt(double release_to_attack_s, double inter_onset_s, const CostWeights& weights);

}  // namespace tutti::piano
