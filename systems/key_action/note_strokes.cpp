// SPDX-License-Identifier: MIT
#include <tutti/key_action/note_strokes.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <tuple>

#include <tutti/core/splitmix64.hpp>
#include <tutti/finger_motion/finger_chain.hpp>

namespace tutti::key_action {
namespace {

double unit_interval(std::uint64_t bits) {  // (0, 1)
  return (static_cast<double>(bits >> 11) + 0.5) * (1.0 / 9007199254740992.0);
}

// Two independent standard normals for one (seed, hand, finger, onset) (Box-Muller).
std::array<double, 2> motor_noise(std::uint64_t seed, music::Hand hand, int finger,
                                  std::int64_t onset_ticks) {
  std::uint64_t key = splitmix64(seed ^ 0x6B65795F616374ull);
  key = splitmix64(key ^ static_cast<std::uint64_t>(static_cast<int>(hand)));
  key = splitmix64(key ^ static_cast<std::uint64_t>(finger));
  key = splitmix64(key ^ static_cast<std::uint64_t>(onset_ticks));
  const double u1 = unit_interval(splitmix64(key ^ 1));
  const double u2 = unit_interval(splitmix64(key ^ 2));
  const double r = std::sqrt(-2.0 * std::log(u1));
  return {r * std::cos(2.0 * std::numbers::pi * u2), r * std::sin(2.0 * std::numbers::pi * u2)};
}

struct ContactGeometry {
  double travel_mm = 10.0;
  double y_mm = 0.0;
};

// Where the tip meets the key at the bottom of the stroke: the reach depends on the drop, the
// drop on the key's travel there, the travel on the reach; a few rounds settle it (the travel
// changes by well under a millimetre).
ContactGeometry contact_geometry(const finger_motion::FingerGeometry& g, bool black,
                                 const finger_motion::KeyHeights& keys, const KeyLever& lever) {
  const double bend = black ? g.black_bend_rad : g.white_bend_rad;
  const finger_motion::ChainShape shape = finger_motion::chain_shape(g, bend);
  const double top = black ? keys.black_top_z_mm : keys.white_top_z_mm;
  ContactGeometry out{lever.front_dip_mm, 0.0};
  for (int round = 0; round < 4; ++round) {
    const finger_motion::StrokeSolution s =
        finger_motion::solve_stroke(shape, g.root_z_mm - (top - out.travel_mm));
    out.y_mm = g.root_y_mm + s.reach_y_mm;
    out.travel_mm = lever.travel_at_mm(out.y_mm);
  }
  return out;
}

}  // namespace

NoteStrokes plan_note_strokes(const music::Score& score,
                              const fingering_planner::ScorePlan& fingering,
                              const piano_model::Keyboard& keyboard,
                              const piano_model::HandModel& hand_model,
                              const finger_motion::FingerMotionParams& params,
                              const KeyAction& action, const PerformanceStyle& style,
                              std::uint64_t seed) {
  const std::size_t count = score.notes.size();
  NoteStrokes out;
  out.strokes.resize(count);
  out.intents.resize(count);
  const std::array<finger_motion::FingerGeometry, 5> geometry =
      finger_motion::scaled_geometry(params, hand_model);
  const double hover = params.keys.hover_lift_mm;
  // Per key, the stroke start of each played note, to let repeated keys go in time.
  std::vector<std::vector<std::pair<double, std::size_t>>> by_key(128);
  // Chord notes on one finger (more than five keys in a hand) are one stroke: the first's.
  std::map<std::tuple<int, int, std::int64_t>, std::size_t> first_on_finger;
  for (std::size_t i = 0; i < count; ++i) {
    const music::Note& note = score.notes[i];
    finger_motion::NoteStroke& stroke = out.strokes[i];
    StrokeIntent& intent = out.intents[i];
    const int finger = i < fingering.fingers.size() ? fingering.fingers[i] : 0;
    const music::Hand hand = i < fingering.hands.size() ? fingering.hands[i] : music::Hand::unknown;
    stroke.bottom_s = note.onset_s;
    stroke.stroke_start_s = note.onset_s - params.timing.press_lead_s;
    stroke.release_s = note.offset_s;
    stroke.travel_mm = params.keys.dip_mm;
    intent.sound_s = note.onset_s;
    if (finger < 1 || finger > 5 || hand == music::Hand::unknown) continue;
    const auto [shared, inserted] = first_on_finger.try_emplace(
        std::tuple<int, int, std::int64_t>{static_cast<int>(hand), finger, note.onset_ticks}, i);
    if (!inserted) {
      stroke = out.strokes[shared->second];
      intent = out.intents[shared->second];
      continue;
    }
    const int key = std::clamp(note.pitch, keyboard.lowest_key(), keyboard.highest_key());
    const bool black = keyboard.is_black(key);
    const KeyLever& lever = action.lever(black);
    const std::size_t f = static_cast<std::size_t>(finger - 1);
    const ContactGeometry contact = contact_geometry(geometry[f], black, params.keys, lever);
    // The fingertip's w^2 stroke from hover height to the bed: distance D, escapement when the
    // tip is escapement_fraction of the travel down, at w = sqrt(fraction of D), tip speed there
    // 2 D w / T; the key's front moves lever_ratio times as fast as the tip.
    const double distance = hover + contact.travel_mm;
    const double w_escape =
        std::sqrt((hover + action.escapement_fraction * contact.travel_mm) / distance);
    const double lever_ratio = lever.length_mm() / (lever.pivot_y_mm - contact.y_mm);
    const double wanted_speed = action.velocity.speed_for(note.velocity) * style.strength;
    const double meant_s = std::clamp(2.0 * distance * w_escape * lever_ratio / wanted_speed,
                                      style.min_stroke_s, style.max_stroke_s);
    const std::array<double, 2> noise = motor_noise(seed, hand, finger, note.onset_ticks);
    intent.sound_s = note.onset_s + 1e-3 * style.timing_spread_ms * noise[0];
    intent.key_speed_mm_s = 2.0 * distance * w_escape * lever_ratio / meant_s;
    intent.lever_ratio = lever_ratio;
    intent.contact_y_mm = contact.y_mm;
    const double actual_s =
        meant_s / (style.finger_speed[f] * std::exp(style.strength_spread * noise[1]));
    stroke.stroke_start_s = intent.sound_s - w_escape * meant_s;
    stroke.bottom_s = stroke.stroke_start_s + actual_s;
    stroke.travel_mm = contact.travel_mm;
    by_key[static_cast<std::size_t>(key)].push_back({stroke.stroke_start_s, i});
  }
  const double let_go_s = style.release_anticipation * style.release_s;
  for (auto& strikes : by_key) {
    std::sort(strikes.begin(), strikes.end());
    for (std::size_t j = 0; j + 1 < strikes.size(); ++j) {
      finger_motion::NoteStroke& stroke = out.strokes[strikes[j].second];
      const double next_start = strikes[j + 1].first;
      if (next_start <= stroke.bottom_s) continue;  // a chord's shared key: not a repetition
      stroke.release_s =
          std::max(stroke.bottom_s, std::min(stroke.release_s, next_start - let_go_s));
    }
  }
  return out;
}

}  // namespace tutti::key_action
