// SPDX-License-Identifier: MIT
#include <tutti/fingering_planner/streaming_planner.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include <tutti/fingering_planner/exact_planner.hpp>

namespace tutti::fingering_planner {
namespace {

// A window never holds more notes than this: keys stuck down (a lost note-off) are let go of
// oldest first, so memory stays bounded whatever arrives.
constexpr std::size_t kMaxWindowNotes = 64;
// A key still down is planned as held this long past everything that has arrived: through every
// event in the window, whatever their chord tolerance.
constexpr double kHeldMarginS = 1.0;

}  // namespace

Status validate(const StreamingOptions& options) {
  if (options.lookahead < 0) {
    return Error{"streaming lookahead " + std::to_string(options.lookahead) + ": must be >= 0"};
  }
  if (options.context_events < 1) {
    return Error{"streaming context_events " + std::to_string(options.context_events) +
                 ": must be >= 1"};
  }
  if (!(options.max_wait_s >= 0.0)) return Error{"streaming max_wait_s: must be >= 0"};
  if (!(options.chord_window_s >= 0.0) || std::isinf(options.chord_window_s)) {
    return Error{"streaming chord_window_s: must be finite and >= 0"};
  }
  return {};
}

StreamingHandPlanner::StreamingHandPlanner(const FingeringModel& model, music::Hand side,
                                           const StreamingOptions& options)
    : model_(&model),
      side_(side),
      options_(options),
      chord_window_s_(std::max(options.chord_window_s, model.weights.chord_tolerance_s)) {}

Result<StreamingHandPlanner> StreamingHandPlanner::create(const FingeringModel& model,
                                                          music::Hand side,
                                                          const StreamingOptions& options) {
  if (Status s = validate(options); !s) return s.error();
  if (side != music::Hand::left && side != music::Hand::right) {
    return Error{"streaming planner: the hand must be left or right"};
  }
  return StreamingHandPlanner(model, side, options);
}

std::size_t StreamingHandPlanner::pending_notes() const {
  return static_cast<std::size_t>(std::count_if(window_.begin(), window_.end(),
                                                [](const WindowNote& n) { return n.finger == 0; }));
}

Status StreamingHandPlanner::push(std::int64_t id, const PlanNote& note,
                                  std::optional<double> offset) {
  const std::string where = "note " + std::to_string(id) + ": ";
  if (!model_->keyboard.contains(note.key)) {
    return Error{where + "key " + std::to_string(note.key) + " is not on the keyboard"};
  }
  if (!std::isfinite(note.onset_s) ||
      (offset && !(std::isfinite(*offset) && *offset >= note.onset_s))) {
    return Error{where + "times must be finite with offset >= onset"};
  }
  if (note.pin < 0 || note.pin > 5) return Error{where + "pinned finger must be 0..5"};
  for (const WindowNote& n : window_) {
    if (n.id == id) return Error{where + "id already in use"};
  }
  WindowNote added;
  added.id = id;
  added.note = note;
  added.offset_known = offset.has_value();
  added.note.offset_s = offset.value_or(note.onset_s);
  if (newest_event_ >= 0 && note.onset_s - newest_onset_s_ <= chord_window_s_) {
    if (note.onset_s < newest_onset_s_ - chord_window_s_) {
      return Error{where + "onset before the previous event's"};
    }
    // Part of the newest event (a chord arriving over a few milliseconds).
    added.note.onset_s = newest_onset_s_;
    added.note.offset_s = std::max(added.note.offset_s, newest_onset_s_);
    added.event = newest_event_;
  } else {
    added.event = ++newest_event_;
    newest_onset_s_ = note.onset_s;
  }
  if (window_.size() >= kMaxWindowNotes) {
    const auto oldest = std::find_if(window_.begin(), window_.end(),
                                     [](const WindowNote& n) { return n.finger != 0; });
    if (oldest == window_.end()) return Error{where + "more than 64 notes waiting for fingers"};
    window_.erase(oldest);
  }
  window_.push_back(added);
  return {};
}

void StreamingHandPlanner::note_off(std::int64_t id, double t_s) {
  for (WindowNote& n : window_) {
    if (n.id != id || n.offset_known) continue;
    n.offset_known = true;
    n.note.offset_s = std::isfinite(t_s) ? std::max(t_s, n.note.onset_s) : n.note.onset_s;
  }
}

void StreamingHandPlanner::advance(double now_s, std::vector<StreamedFinger>& out) {
  for (;;) {
    const auto first = std::find_if(window_.begin(), window_.end(),
                                    [](const WindowNote& n) { return n.finger == 0; });
    if (first == window_.end()) return;
    const std::int64_t event = first->event;
    const bool seen_enough = newest_event_ - event >= options_.lookahead;
    const bool deadline = now_s >= first->note.onset_s + options_.max_wait_s;
    if (!seen_enough && !deadline) return;
    decide(event, now_s, out);
  }
}

void StreamingHandPlanner::flush(double now_s, std::vector<StreamedFinger>& out) {
  for (;;) {
    const auto first = std::find_if(window_.begin(), window_.end(),
                                    [](const WindowNote& n) { return n.finger == 0; });
    if (first == window_.end()) return;
    decide(first->event, now_s, out);
  }
}

void StreamingHandPlanner::decide(std::int64_t event, double now_s,
                                  std::vector<StreamedFinger>& out) {
  const double tolerance = model_->weights.chord_tolerance_s;
  const std::int64_t first_context = event - options_.context_events;
  const std::int64_t last_future = event + options_.lookahead;
  double context_onset = std::numeric_limits<double>::infinity();
  for (const WindowNote& n : window_) {
    if (n.event >= first_context) context_onset = std::min(context_onset, n.note.onset_s);
  }
  // Keys still down are held through everything that has arrived.
  const double held_until = std::max(now_s, newest_onset_s_) + kHeldMarginS;
  scratch_notes_.clear();
  scratch_index_.clear();
  for (std::size_t i = 0; i < window_.size(); ++i) {
    const WindowNote& n = window_[i];
    if (n.event > last_future) continue;
    // The past the decision starts from: the last context events, and older keys still sounding
    // then (they shape those events' hands).
    const bool in_context =
        n.event >= first_context || !n.offset_known || n.note.offset_s > context_onset + tolerance;
    if (n.event < event && !in_context) continue;
    PlanNote p = n.note;
    if (!n.offset_known) p.offset_s = std::max(p.onset_s, held_until);
    if (n.finger != 0) p.pin = n.finger;
    scratch_notes_.push_back(p);
    scratch_index_.push_back(i);
  }
  auto plan = plan_hand_exact(scratch_notes_, side_, *model_);
  const int future = static_cast<int>(std::min(newest_event_, last_future) - event);
  // Fingers already given in this event (a chord's first notes, struck already) stay theirs:
  // when the pins could not all hold, a late note takes the nearest free finger instead. (The
  // notes of an event decided all at once may share a finger, as the planner shares one for
  // more than five keys.)
  unsigned used = 0;
  for (const WindowNote& n : window_) {
    if (n.event == event && n.finger != 0) used |= 1u << (n.finger - 1);
  }
  const bool late = used != 0;
  for (std::size_t j = 0; j < scratch_index_.size(); ++j) {
    WindowNote& n = window_[scratch_index_[j]];
    if (n.event != event || n.finger != 0) continue;
    // Every note was validated by push, so planning cannot fail; finger 1 keeps the
    // contract (every note gets a finger) should it ever.
    int finger = plan ? plan->fingers[j] : 1;
    if (finger < 1 || finger > 5) finger = 1;
    for (int step = 1; (used >> (finger - 1)) & 1u && step < 5; ++step) {
      for (int candidate : {finger - step, finger + step}) {
        if (candidate >= 1 && candidate <= 5 && !((used >> (candidate - 1)) & 1u)) {
          finger = candidate;
          break;
        }
      }
    }
    // Late notes also keep apart from each other (the first notes are down already).
    if (late) used |= 1u << (finger - 1);
    n.finger = finger;
    out.push_back({n.id, side_, n.note.key, n.note.onset_s, n.finger, now_s, future});
  }
  prune();
}

void StreamingHandPlanner::prune() {
  const auto first_pending = std::find_if(window_.begin(), window_.end(),
                                          [](const WindowNote& n) { return n.finger == 0; });
  const std::int64_t next =
      first_pending != window_.end() ? first_pending->event : newest_event_ + 1;
  const std::int64_t first_context = next - options_.context_events;
  double context_onset = std::numeric_limits<double>::infinity();
  for (const WindowNote& n : window_) {
    if (n.event >= first_context) context_onset = std::min(context_onset, n.note.onset_s);
  }
  const double tolerance = model_->weights.chord_tolerance_s;
  std::erase_if(window_, [&](const WindowNote& n) {
    return n.finger != 0 && n.event < first_context && n.offset_known &&
           n.note.offset_s <= context_onset + tolerance;
  });
}

}  // namespace tutti::fingering_planner
