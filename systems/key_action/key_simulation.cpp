// SPDX-License-Identifier: MIT
#include <tutti/key_action/key_simulation.hpp>

#include <algorithm>
#include <cmath>

#include <tutti/finger_motion/evaluate_hand_pose.hpp>

namespace tutti::key_action {
namespace {

using components::HandSide;
using finger_motion::KeyContact;

// One finger's contact with a key: when it can move the key, and which finger does it.
struct Presser {
  const KeyContact* contact = nullptr;
  HandSide side = HandSide::right;
  int finger = 1;
  double from_s = 0.0;  // stroke start
  double to_s = 0.0;    // release end
};

struct KeyState {
  double angle = 0.0;
  bool armed = true;  // risen to the reset angle since the last escapement
  int sounding = -1;  // note whose damper is off
};

// The angle `presser`'s fingertip holds its key at, at t (0 when the finger is on another key).
double finger_angle(const finger_motion::FingerMotionPlan& plan, const Presser& p,
                    const KeyLever& lever, double top_z, double t) {
  finger_motion::FingerPose pose;
  // Lateral position does not change the tip's height or reach: hand x = 0 is enough here.
  finger_motion::evaluate_finger_pose(plan, p.side, p.finger, 0.0, t, pose);
  if (pose.key != p.contact->key) return 0.0;
  return lever.angle_rad(pose.contact_y_mm, top_z - pose.contact_z_mm);
}

void simulate_key(const finger_motion::FingerMotionPlan& plan, std::vector<Presser>& pressers,
                  const KeyAction& action, double step, std::vector<PlayedNote>& out) {
  std::sort(pressers.begin(), pressers.end(), [](const Presser& a, const Presser& b) {
    return a.from_s != b.from_s ? a.from_s < b.from_s : a.contact->note < b.contact->note;
  });
  const KeyContact& first = *pressers.front().contact;
  const KeyLever& lever = action.lever(first.black);
  const double top_z = first.black ? plan.keys.black_top_z_mm : plan.keys.white_top_z_mm;
  const double bed = lever.bed_angle_rad();
  const double escape = action.escapement_fraction * bed;
  const double damper = action.damper_fraction * bed;
  const double reset = action.reset_fraction * bed;
  const double fall_per_s = bed / action.return_s;
  KeyState state;
  std::vector<int> attempted(pressers.size(), 0);
  std::size_t begin = 0;  // pressers before this one are over
  while (begin < pressers.size()) {
    // A stretch of time in which some presser can move the key, plus the spring's return.
    double t = pressers[begin].from_s;
    double stretch_end = pressers[begin].to_s + action.return_s;
    std::size_t end = begin + 1;
    while (end < pressers.size() && pressers[end].from_s <= stretch_end) {
      stretch_end = std::max(stretch_end, pressers[end].to_s + action.return_s);
      ++end;
    }
    state.angle = 0.0;
    double previous_t = t;
    for (;; t = std::min(t + step, stretch_end)) {
      // Which finger holds the key deepest now (held keys at the bed need no evaluation).
      double pushed = 0.0;
      std::size_t driver = begin;
      for (std::size_t j = begin; j < end; ++j) {
        const Presser& p = pressers[j];
        if (t < p.from_s || t > p.to_s) continue;
        const double a = (t >= p.contact->onset_s && t <= p.contact->offset_s)
                             ? bed
                             : finger_angle(plan, p, lever, top_z, t);
        if (a > pushed) {
          pushed = a;
          driver = j;
        }
      }
      const double dt = t - previous_t;
      const double angle = std::max(pushed, state.angle - fall_per_s * dt);
      if (angle <= reset) state.armed = true;
      if (state.angle < escape && angle >= escape && dt > 0.0) {
        const double u = (escape - state.angle) / (angle - state.angle);
        const double when = previous_t + u * dt;
        const double speed = (angle - state.angle) / dt * lever.length_mm();
        const int note = pressers[driver].contact->note;
        PlayedNote& played = out[static_cast<std::size_t>(note)];
        attempted[driver] = 1;
        if (!state.armed) {
          if (played.outcome == KeyOutcome::not_played) played.outcome = KeyOutcome::not_reset;
        } else {
          played.key_speed_mm_s = speed;
          if (speed < action.velocity.silent_below_mm_s) {
            played.outcome = KeyOutcome::too_soft;
          } else {
            if (state.sounding >= 0) out[static_cast<std::size_t>(state.sounding)].offset_s = when;
            played.outcome = KeyOutcome::sounded;
            played.onset_s = when;
            played.velocity = action.velocity.velocity_for(speed);
            state.sounding = note;
          }
          state.armed = false;
        }
      }
      if (state.sounding >= 0 && state.angle > damper && angle <= damper && dt > 0.0) {
        const double u = (state.angle - damper) / (state.angle - angle);
        out[static_cast<std::size_t>(state.sounding)].offset_s = previous_t + u * dt;
        state.sounding = -1;
      }
      state.angle = angle;
      previous_t = t;
      if (t >= stretch_end) break;
      // Skip a hold at the bed: nothing changes until a holder lets go or another stroke starts.
      double hold_end = -1.0;
      double next_change = stretch_end;
      for (std::size_t j = begin; j < end; ++j) {
        const Presser& p = pressers[j];
        if (t >= p.contact->onset_s && t < p.contact->offset_s) {
          hold_end = std::max(hold_end, p.contact->offset_s);
        }
        if (p.from_s > t) next_change = std::min(next_change, p.from_s);
      }
      if (hold_end > t + step && angle >= bed) {
        const double resume = std::min(hold_end, next_change);
        if (resume > t + step) {
          t = resume - step;
          previous_t = t;
        }
      }
    }
    if (state.sounding >= 0 && std::isnan(out[static_cast<std::size_t>(state.sounding)].offset_s)) {
      out[static_cast<std::size_t>(state.sounding)].offset_s = stretch_end;
    }
    state.sounding = -1;
    state.armed = true;
    begin = end;
  }
  // A stroke that never reached escapement: the key was already down (held by another finger).
  for (std::size_t j = 0; j < pressers.size(); ++j) {
    PlayedNote& played = out[static_cast<std::size_t>(pressers[j].contact->note)];
    if (!attempted[j] && played.outcome == KeyOutcome::not_played) {
      played.outcome = KeyOutcome::not_reset;
    }
  }
}

}  // namespace

std::vector<PlayedNote> simulate_keys(const music::Score& score,
                                      const fingering_planner::ScorePlan& fingering,
                                      const finger_motion::PianistMotion& motion,
                                      const KeyAction& action,
                                      const KeySimulationOptions& options) {
  std::vector<PlayedNote> out(score.notes.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i].key = score.notes[i].pitch;
  const double step = options.step_s > 0.0 ? options.step_s : 0.0005;
  const finger_motion::FingerMotionPlan& plan = motion.fingers;
  std::vector<std::vector<Presser>> by_key(128);
  for (const finger_motion::HandFingerPlan* hand : {&plan.right, &plan.left}) {
    for (std::size_t f = 0; f < 5; ++f) {
      const std::vector<KeyContact>& contacts = hand->fingers[f];
      for (std::size_t j = 0; j < contacts.size(); ++j) {
        const KeyContact& c = contacts[j];
        if (c.note < 0 || static_cast<std::size_t>(c.note) >= out.size()) continue;
        // The finger moves this key until it starts its next stroke (then it is that key's).
        const double until = j + 1 < contacts.size()
                                 ? std::min(c.release_end_s, contacts[j + 1].stroke_start_s)
                                 : c.release_end_s;
        by_key[static_cast<std::size_t>(c.key)].push_back(
            {&c, hand->side, static_cast<int>(f) + 1, c.stroke_start_s, until});
      }
    }
  }
  for (std::vector<Presser>& pressers : by_key) {
    if (!pressers.empty()) simulate_key(plan, pressers, action, step, out);
  }
  // Chord notes merged into a neighbour's contact (a finger on two keys) sound with it.
  std::vector<char> covered(out.size(), 0);
  for (const finger_motion::HandFingerPlan* hand : {&plan.right, &plan.left}) {
    for (const auto& contacts : hand->fingers) {
      for (const KeyContact& c : contacts) {
        if (c.note >= 0 && static_cast<std::size_t>(c.note) < out.size()) {
          covered[static_cast<std::size_t>(c.note)] = 1;
        }
      }
    }
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (covered[i] || i >= fingering.fingers.size() || i >= fingering.hands.size()) continue;
    const int finger = fingering.fingers[i];
    const music::Hand hand = fingering.hands[i];
    if (finger < 1 || finger > 5 || hand == music::Hand::unknown) continue;
    const auto& contacts = plan.hand(hand == music::Hand::left ? HandSide::left : HandSide::right)
                               .fingers[static_cast<std::size_t>(finger - 1)];
    for (const KeyContact& c : contacts) {
      if (c.note >= 0 &&
          score.notes[static_cast<std::size_t>(c.note)].onset_ticks == score.notes[i].onset_ticks) {
        const int key = out[i].key;
        out[i] = out[static_cast<std::size_t>(c.note)];
        out[i].key = key;
        break;
      }
    }
  }
  return out;
}

const char* outcome_name(KeyOutcome outcome) {
  switch (outcome) {
    case KeyOutcome::sounded:
      return "sounded";
    case KeyOutcome::too_soft:
      return "too soft";
    case KeyOutcome::not_reset:
      return "not reset";
    case KeyOutcome::not_played:
      return "not played";
  }
  return "?";
}

}  // namespace tutti::key_action
