// SPDX-License-Identifier: MIT
#include <tutti/live/live_pianist.hpp>

#include <algorithm>
#include <cmath>

#include <tutti/finger_motion/evaluate_hand_pose.hpp>
#include <tutti/finger_motion/plan_finger_motion.hpp>

namespace tutti::live {
namespace {

// The shortest stroke: a contact needs a stroke of non-zero length (evaluate divides by it).
constexpr double kMinStrokeS = 0.001;
// An open contact (no note-off yet) is held until then.
constexpr double kOpenOffsetS = 1.0e9;
constexpr std::size_t kPlayedKept = 256;

std::size_t side_index(music::Hand hand) { return hand == music::Hand::left ? 1 : 0; }
components::HandSide hand_side(music::Hand hand) {
  return hand == music::Hand::left ? components::HandSide::left : components::HandSide::right;
}

// The rest position of a hand: its reference point where the middle finger rests on `key`.
double rest_x(const fingering_planner::FingeringModel& model, int key) {
  return model.keyboard.x_mm(key);
}

}  // namespace

LivePianist::LivePianist(std::unique_ptr<fingering_planner::FingeringModel> model,
                         fingering_planner::StreamingPianoPlanner planner,
                         finger_motion::FingerMotionPlan templ, const LivePianistOptions& options)
    : model_(std::move(model)),
      planner_(std::move(planner)),
      template_(std::move(templ)),
      options_(options),
      paths_{LiveHandPath(rest_x(*model_, 67), options.hand_move_s, options.moves_per_hand),
             LiveHandPath(rest_x(*model_, 48), options.hand_move_s, options.moves_per_hand)} {}

Result<std::unique_ptr<LivePianist>> LivePianist::create(
    fingering_planner::FingeringModel model, const finger_motion::FingerMotionParams& params,
    const LivePianistOptions& options) {
  if (!(options.hand_move_s > 0.0) || std::isinf(options.hand_move_s)) {
    return Error{"live pianist: hand_move_s must be > 0"};
  }
  // The template: geometry, bends, heights and timing as plan_finger_motion derives them, with
  // no contacts (an empty score).
  const music::Score empty;
  const fingering_planner::ScorePlan no_plan;
  auto templ =
      finger_motion::plan_finger_motion(empty, no_plan, {}, {}, model.keyboard, model.hand, params);
  if (!templ) return templ.error();
  // The planner points into the model: on the heap, it stays put when the pianist moves.
  auto owned = std::make_unique<fingering_planner::FingeringModel>(std::move(model));
  auto planner = fingering_planner::StreamingPianoPlanner::create(*owned, options.planner);
  if (!planner) return planner.error();
  auto pianist = std::unique_ptr<LivePianist>(
      new LivePianist(std::move(owned), std::move(*planner), std::move(*templ), options));
  pianist->rebuild();
  return pianist;
}

bool LivePianist::update(std::span<const LiveNoteEvent> events, double now_s) {
  bool changed = false;
  for (const LiveNoteEvent& e : events) {
    if (e.key < 0 || e.key > 127) {
      ++ignored_;
      continue;
    }
    std::int64_t& current = key_id_[static_cast<std::size_t>(e.key)];
    if (current != 0) {  // a note-off, or a key struck again before its note-off arrived
      planner_.note_off(current, e.time_s);
      end_contact(current, e.time_s);
      for (Sounding& s : sounding_) {
        if (s.id == current && !s.released_s) s.released_s = e.time_s;
      }
      current = 0;
      changed = true;
    }
    if (!e.on) continue;
    const int key =
        std::clamp(e.key, model_->keyboard.lowest_key(), model_->keyboard.highest_key());
    fingering_planner::PlanNote note;
    note.key = key;
    note.onset_s = e.time_s;
    note.offset_s = e.time_s;
    const std::int64_t id = next_id_++;
    if (!planner_.push(id, note, std::nullopt)) {
      ++ignored_;
      continue;
    }
    current = id;
    sounding_.push_back({id, key, e.time_s, std::nullopt});
  }
  decided_.clear();
  planner_.advance(now_s, decided_);
  for (const fingering_planner::StreamedFinger& d : decided_) add_contact(d, now_s);
  changed = changed || !decided_.empty();
  if (changed) rebuild();
  return changed;
}

void LivePianist::add_contact(const fingering_planner::StreamedFinger& decided, double now_s) {
  const auto sounding = std::find_if(sounding_.begin(), sounding_.end(),
                                     [&](const Sounding& s) { return s.id == decided.id; });
  const double event_s = sounding != sounding_.end() ? sounding->event_s : decided.onset_s;
  const std::optional<double> released =
      sounding != sounding_.end() ? sounding->released_s : std::nullopt;
  if (sounding != sounding_.end()) sounding_.erase(sounding);

  const std::size_t h = side_index(decided.hand);
  const auto f = static_cast<std::size_t>(decided.finger - 1);
  const components::HandSide side = hand_side(decided.hand);
  const finger_motion::StrokeTiming& timing = template_.timing;
  std::vector<Contact>& list = contacts_[h][f];

  // Where the tip is when it leaves for the new key (the motion so far).
  finger_motion::FingerPose pose;
  finger_motion::evaluate_finger_pose(motion_->fingers, side, decided.finger,
                                      paths_[h].state(event_s).x_mm, event_s, pose);
  double stroke_start = event_s;
  if (!list.empty()) {
    finger_motion::KeyContact& previous = list.back().contact;
    // The finger leaves its previous key now (a live player re-uses a finger at once).
    if (previous.offset_s > stroke_start) {
      previous.offset_s = std::max(previous.onset_s, stroke_start);
      previous.release_end_s = previous.offset_s + timing.release_s;
      list.back().open = false;
    }
    stroke_start = std::max(stroke_start, previous.offset_s);
  }
  finger_motion::KeyContact c;
  c.key = decided.key;
  c.x_mm = model_->keyboard.x_mm(decided.key);
  c.black = model_->keyboard.is_black(decided.key);
  c.onset_s = now_s > stroke_start ? now_s : stroke_start + kMinStrokeS;
  c.stroke_start_s = stroke_start;
  c.shape_start_s = stroke_start;
  c.move_start_s = stroke_start;
  c.move_from_x_mm = pose.tip_x_mm;
  c.offset_s = released ? std::max(*released, c.onset_s) : kOpenOffsetS;
  c.release_end_s = c.offset_s + timing.release_s;
  c.note = -1;
  c.inv_move_s = 1.0 / (c.onset_s - c.move_start_s);
  c.inv_shape_s = 0.0;
  c.inv_stroke_s = 1.0 / (c.onset_s - c.stroke_start_s);
  c.inv_release_s = 1.0 / timing.release_s;
  c.release_decay_scale = std::exp(timing.release_s / timing.relax_time_constant_s);
  list.push_back({decided.id, c, !released});
  if (list.size() > options_.contacts_per_finger) list.erase(list.begin());

  // The hand goes where its keys down now are comfortable: each key under its finger's rest
  // line, averaged.
  double sum = 0.0;
  int count = 0;
  const auto& rest = template_.hand(side).rest_offset_mm;
  for (std::size_t g = 0; g < 5; ++g) {
    for (const Contact& other : contacts_[h][g]) {
      if (other.contact.offset_s > event_s || other.id == decided.id) {
        sum += other.contact.x_mm - rest[g];
        ++count;
      }
    }
  }
  if (count > 0) paths_[h].move_to(stroke_start, sum / count);

  played_.push_back({decided.id, decided.key, decided.hand, decided.finger, event_s, c.onset_s});
  if (played_.size() > kPlayedKept) played_.erase(played_.begin());
}

void LivePianist::end_contact(std::int64_t id, double t_s) {
  for (std::size_t h = 0; h < 2; ++h) {
    const components::HandSide side =
        h == 0 ? components::HandSide::right : components::HandSide::left;
    for (std::size_t f = 0; f < 5; ++f) {
      for (Contact& c : contacts_[h][f]) {
        if (c.id != id || !c.open) continue;
        c.open = false;
        finger_motion::KeyContact& k = c.contact;
        k.offset_s = std::max(t_s, k.onset_s);
        k.release_end_s = k.offset_s + template_.timing.release_s;
        // The relaxation starts from where the tip is off its rest line (keyboard x).
        const double hand_x = paths_[h].state(k.offset_s).x_mm;
        k.release_offset_mm = k.x_mm - (hand_x + template_.hand(side).rest_offset_mm[f]);
      }
    }
  }
}

void LivePianist::rebuild() {
  auto motion = std::make_shared<finger_motion::PianistMotion>();
  motion->fingers = template_;
  for (std::size_t h = 0; h < 2; ++h) {
    finger_motion::HandFingerPlan& hand = h == 0 ? motion->fingers.right : motion->fingers.left;
    for (std::size_t f = 0; f < 5; ++f) {
      hand.fingers[f].clear();
      hand.onsets_s[f].clear();
      for (const Contact& c : contacts_[h][f]) {
        hand.fingers[f].push_back(c.contact);
        hand.onsets_s[f].push_back(c.contact.onset_s);
      }
    }
  }
  motion->right_path = paths_[0].build();
  motion->left_path = paths_[1].build();
  motion_ = std::move(motion);
}

}  // namespace tutti::live
