// SPDX-License-Identifier: MIT
#pragma once
// The weights of the fingering cost, loaded from content/piano/fingering/<preset>.json.
// "paper" reproduces Sekiguchi & Eiho (1999) exactly; "default" adds natural spacing, crossing
// rules, per-finger preferences, repeated-key rules, scale anchors for the thumb and physical
// limits on hand shifts (their time and a speed limit). Every key is documented in
// content/piano/README.md. Distances in white-key widths (δ), times in seconds.
//
// Absent keys keep the paper's value (the struct defaults below); an unknown key is an error
// naming the JSON path, e.g. "default.json: /crossing/thumb_bogus: unknown key".

#include <array>
#include <filesystem>
#include <limits>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include <tutti/core/result.hpp>

namespace tutti::fingering_planner {

inline constexpr double kInfiniteCost = std::numeric_limits<double>::infinity();

struct CostWeights {
  std::string name = "paper";

  // --- hand area (the paper) ---
  double area_overlap = 1.0;      // weight of 1 - Δd / max(d_i, d_i+1) when the areas overlap
  double gap_base = 1.0;          // cost of a non-overlapping move (>= 1; used: >= area_overlap)
  double gap_speed = 0.05;        // + per white key per second of hand travel speed
  double release_fraction = 0.0;  // Δt used >= this × inter-onset interval (0 = paper)
  // Time a shift may take (effective_dt): Δt >= min(shift_time_s, (1 - shift_hold_fraction) ×
  // inter-onset interval), i.e. before a shift the previous keys are let go up to shift_time_s
  // early but held for at least shift_hold_fraction of their interval (0 = paper: no such term).
  double shift_time_s = 0.0;
  double shift_hold_fraction = 0.0;
  // Hand speed limit of a shift (gap / Δt, white keys per second; infinite = paper): beyond it
  // the gap cost rises by over_speed per white key per second of excess.
  double speed_limit = std::numeric_limits<double>::infinity();
  double over_speed = 0.0;

  // --- fingers (the paper: thumb +0.1 per use, thumb on a black key +1.5) ---
  std::array<double, 5> finger_use{0.1, 0.0, 0.0, 0.0, 0.0};
  std::array<double, 5> black_key{1.5, 0.0, 0.0, 0.0, 0.0};
  // Per thumb strike on the tonic (a white key) (0 in the paper; negative = preferred): pianists
  // anchor scale fingerings on the tonic (thumb on C and G in C major, left hand). The tonic
  // comes from PlanNote::tonic (plan_score: key signature, else the key the notes fit best).
  double thumb_on_tonic = 0.0;
  // Per thumb strike on the white key a perfect fourth from the tonic towards the little finger
  // (above it for the right hand, below it for the left; 0 in the paper): the thumb's second
  // anchor in a scale, so the octave divides into 3 + 4 fingers from the tonic (RH C major thumb
  // on C and F, LH on C and G).
  double thumb_on_fourth = 0.0;

  // --- same finger on consecutive events ---
  double same_finger_other_key = kInfiniteCost;  // "inf" in the paper
  double same_finger_speed = 0.0;                // + per white key per second (finite base only)
  double same_finger_same_key = 0.0;             // repeated key, same finger
  double repeat_finger_change = 0.0;             // repeated key, another finger

  // --- natural spacing (0 in the paper) ---
  double spacing_per_finger = 1.0;    // white keys between neighbouring fingers at rest
  double spacing_stretch = 0.0;       // per white key wider than natural
  double spacing_compress = 0.0;      // per white key narrower than natural
  double spacing_thumb_factor = 1.0;  // multiplies both for pairs involving the thumb
  double spacing_max_distance = 1e9;  // spacing/crossing apply to keys at most this far apart

  // --- crossings: finger order opposite to key order (0 in the paper) ---
  double cross_thumb = 0.0;                    // thumb passes under / finger over thumb
  std::array<double, 5> cross_thumb_finger{};  // + by the other finger (index 0 unused)
  double cross_thumb_distance = 0.0;           // + per white key beyond one
  double cross_thumb_black = 0.0;              // + when the thumb's key is black
  double cross_little = 0.0;                   // thumb <-> little finger crossing
  double cross_other = 0.0;                    // crossing without the thumb

  // --- the other hand (0 in the paper, which plans one hand) ---
  // A fingering whose hand area centre lies nearer the other hand's corridor centre than
  // other_hand_separation white keys costs other_hand_per_white_key per white key of shortfall,
  // from other_hand_lead_s before the event's onset to its end (other_hand_cost.hpp).
  double other_hand_separation = 4.0;
  double other_hand_per_white_key = 0.0;
  double other_hand_lead_s = 0.15;

  // --- events ---
  double chord_tolerance_s = 0.001;  // onsets this close form one event
  double unreachable = 100.0;        // per white key of missing reach when no fingering fits
  double impossible = 1.0e6;         // what an infinite transition adds to the DP's total
};

// Errors: file missing/not JSON, unknown key (with its JSON path), wrong type, negative time.
Result<CostWeights> load_cost_weights(const std::filesystem::path& path);
Result<CostWeights> cost_weights_from_json(const nlohmann::json& document,
                                           const std::string& file_name);

}  // namespace tutti::fingering_planner
