// SPDX-License-Identifier: MIT
#include <tutti/fingering_planner/streaming_piano.hpp>

#include <algorithm>

namespace tutti::fingering_planner {

StreamingPianoPlanner::StreamingPianoPlanner(const FingeringModel& model,
                                             StreamingHandPlanner right, StreamingHandPlanner left)
    : split_(model), right_(std::move(right)), left_(std::move(left)) {}

Result<StreamingPianoPlanner> StreamingPianoPlanner::create(const FingeringModel& model,
                                                            const StreamingOptions& options) {
  auto right = StreamingHandPlanner::create(model, music::Hand::right, options);
  if (!right) return right.error();
  auto left = StreamingHandPlanner::create(model, music::Hand::left, options);
  if (!left) return left.error();
  return StreamingPianoPlanner(model, std::move(*right), std::move(*left));
}

Result<music::Hand> StreamingPianoPlanner::push(std::int64_t id, const PlanNote& note,
                                                std::optional<double> offset, music::Hand hand) {
  // Keys a score releases by now no longer hold the split's hands.
  std::erase_if(releases_, [&](const KnownRelease& r) {
    if (r.offset_s > note.onset_s) return false;
    split_.release(r.id);
    return true;
  });
  music::Hand side = hand;
  if (side == music::Hand::left || side == music::Hand::right) {
    split_.hold(id, note.key, side);  // the caller chose; the split's own choices avoid it
  } else {
    side = split_.assign(id, note.key);
  }
  StreamingHandPlanner& planner = side == music::Hand::left ? left_ : right_;
  if (Status s = planner.push(id, note, offset); !s) {
    split_.release(id);
    return s.error();
  }
  if (offset) {
    releases_.push_back({id, *offset});
  } else {
    owners_.push_back({id, side});
  }
  return side;
}

void StreamingPianoPlanner::note_off(std::int64_t id, double t_s) {
  split_.release(id);
  for (const Owner& o : owners_) {
    if (o.id == id) (o.hand == music::Hand::left ? left_ : right_).note_off(id, t_s);
  }
  std::erase_if(owners_, [&](const Owner& o) { return o.id == id; });
}

void StreamingPianoPlanner::advance(double now_s, std::vector<StreamedFinger>& out) {
  right_.advance(now_s, out);
  left_.advance(now_s, out);
}

void StreamingPianoPlanner::flush(double now_s, std::vector<StreamedFinger>& out) {
  right_.flush(now_s, out);
  left_.flush(now_s, out);
}

}  // namespace tutti::fingering_planner
