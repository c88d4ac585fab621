// SPDX-License-Identifier: MIT
#pragma once
// Both hands of a pianist, streaming: each arriving note is given a hand at arrival (the
// caller's, or LiveHandSplit's) and then a finger by that hand's StreamingHandPlanner. A thin
// owner of the three; see streaming_planner.hpp for the timing contract.

#include <cstdint>
#include <optional>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/fingering_planner/live_hand_split.hpp>
#include <tutti/fingering_planner/streaming_planner.hpp>

namespace tutti::fingering_planner {

class StreamingPianoPlanner {
 public:
  // `model` must outlive the planner. Errors: invalid options.
  static Result<StreamingPianoPlanner> create(const FingeringModel& model,
                                              const StreamingOptions& options);

  // A note arrives (see StreamingHandPlanner::push). `hand` unknown: the live split decides.
  // Known offsets release the key in the split once a later note arrives after them. Returns
  // the hand, or the push's error.
  Result<music::Hand> push(std::int64_t id, const PlanNote& note, std::optional<double> offset,
                           music::Hand hand = music::Hand::unknown);
  void note_off(std::int64_t id, double t_s);
  // Both hands' decisions at now_s, right hand's first.
  void advance(double now_s, std::vector<StreamedFinger>& out);
  void flush(double now_s, std::vector<StreamedFinger>& out);

  const StreamingHandPlanner& hand(music::Hand side) const {
    return side == music::Hand::left ? left_ : right_;
  }

 private:
  StreamingPianoPlanner(const FingeringModel& model, StreamingHandPlanner right,
                        StreamingHandPlanner left);
  struct KnownRelease {
    std::int64_t id = 0;
    double offset_s = 0.0;
  };
  struct Owner {
    std::int64_t id = 0;
    music::Hand hand = music::Hand::right;
  };

  LiveHandSplit split_;
  StreamingHandPlanner right_;
  StreamingHandPlanner left_;
  std::vector<KnownRelease> releases_;  // known offsets not yet passed
  std::vector<Owner> owners_;           // sounding notes' hands, for note_off
};

}  // namespace tutti::fingering_planner
