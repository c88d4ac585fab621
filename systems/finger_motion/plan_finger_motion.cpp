#include <tutti/finger_motion/plan_finger_motion.hpp>

#include <algorithm>
#include <cmath>
#include <string>

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

// Sorts, merges same-onset contacts, trims offsets and fills the timing fields.
// `preset_strokes`: each contact's stroke_start_s is already the one wanted (a NoteStroke's).
void schedule_contacts(std::vector<KeyContact>& contacts, double rest_offset_mm,
                       const motion::HandPath& path, const StrokeTiming& timing,
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
  // Pass 2: moves, shaping, releases.
  for (std::size_t j = 0; j < merged.size(); ++j) {
    KeyContact& c = merged[j];
    const KeyContact* prev = j > 0 ? &merged[j - 1] : nullptr;
    const double from_x =
        prev != nullptr ? prev->x_mm : motion::evaluate(path, c.onset_s).x_mm + rest_offset_mm;
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
    const double rest_at_move = motion::evaluate(path, c.move_start_s).x_mm + rest_offset_mm;
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
    c.release_offset_mm = c.x_mm - (motion::evaluate(path, c.offset_s).x_mm + rest_offset_mm);
    precompute_for_evaluate(c, timing);
  }
  contacts = std::move(merged);
}

}  // namespace

Result<FingerMotionPlan> plan_finger_motion(
    const music::Score& score, const piano::ScorePlan& score_plan,
    const motion::HandPath& right_path, const motion::HandPath& left_path,
    const piano::Keyboard& keyboard, const piano::HandModel& hand_model,
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
    const piano::FingerRange right = hand_model.range(music::Hand::right, finger);
    const piano::FingerRange left = hand_model.range(music::Hand::left, finger);
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
    const motion::HandPath& path = side->side == HandSide::left ? left_path : right_path;
    for (std::size_t f = 0; f < 5; ++f) {
      schedule_contacts(side->fingers[f], side->rest_offset_mm[f], path, plan.timing,
                        !strokes.empty());
      side->onsets_s[f].reserve(side->fingers[f].size());
      for (const KeyContact& c : side->fingers[f]) side->onsets_s[f].push_back(c.onset_s);
    }
  }
  return plan;
}

std::array<FingerGeometry, 5> scaled_geometry(const FingerMotionParams& params,
                                              const piano::HandModel& hand_model) {
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
