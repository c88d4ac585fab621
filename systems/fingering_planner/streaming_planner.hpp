// SPDX-License-Identifier: MIT
#pragma once
// The streaming fingering planner: notes are pushed one at a time as they arrive (live MIDI, or a
// score fed in onset order) and each event (notes starting together) is given its fingers as soon
// as it may be: when `lookahead` later events have arrived, or when `max_wait_s` has passed since
// its onset, whichever comes first (lookahead 0: at arrival). The search is the paper's
// (Sekiguchi & Eiho 1999), with the same cost model as plan_hand_exact: every fingering of the
// event and of the future events it waited for is evaluated from the fingers already given, and
// only the event's own fingers are kept. So lookahead L matches plan_hand_lookahead with
// lookahead L + 1 (which counts the current event) wherever the windows see the same notes.
//
// Offsets: known (a score) or not (live: the note-off comes later, note_off()). A key still down
// is taken as held through every event that has arrived, so it keeps its finger and constrains
// the hand; a key released since is not.
//
// Chords: a note whose onset is within `chord_window_s` of its event's first onset joins that
// event (its onset is taken as the event's). Live chords arrive over a few milliseconds; when an
// event was already given its fingers (lookahead 0), a late note is fingered around them (the
// fingers given stay: they are pinned).
//
// Bounded: the window holds the events not yet given fingers plus `context_events` given ones
// (and keys still down, at most 32 notes); every decision plans at most context + 1 + lookahead
// events. Deterministic: the same pushes and times give the same fingers.

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/fingering_planner/fingering_model.hpp>
#include <tutti/fingering_planner/hand_plan.hpp>

namespace tutti::fingering_planner {

struct StreamingOptions {
  int lookahead = 0;  // future events an event waits for (>= 0)
  // An event is decided at the latest this long after its onset, whatever has arrived (>= 0;
  // infinity = wait for the lookahead only, as when a whole score is fed).
  double max_wait_s = std::numeric_limits<double>::infinity();
  int context_events = 4;      // decided events kept as the fixed past (>= 1)
  double chord_window_s = 0.0;  // 0 = the model's chord_tolerance_s; live: ~0.03
};

// Errors: lookahead < 0, context_events < 1, a negative or NaN max_wait_s or chord_window_s.
Status validate(const StreamingOptions& options);

// One note's decision.
struct StreamedFinger {
  std::int64_t id = 0;  // the caller's note id
  music::Hand hand = music::Hand::right;
  int key = 60;
  double onset_s = 0.0;    // as planned (a chord's notes share their event's onset)
  int finger = 1;          // 1..5
  double decided_s = 0.0;  // the `now` at which it was decided
  int future_events = 0;   // how many later events the decision saw
};

class StreamingHandPlanner {
 public:
  // `model` must outlive the planner. Errors: invalid options.
  static Result<StreamingHandPlanner> create(const FingeringModel& model, music::Hand side,
                                             const StreamingOptions& options);

  // A note arrives. `note.offset_s` is used when `offset` is given (a score), else the key is
  // down until note_off(id). note.pin and note.tonic are honoured. Errors (the note is not
  // taken): key off the keyboard, non-finite time, onset before the previous event's, offset <
  // onset, an id already in use.
  Status push(std::int64_t id, const PlanNote& note, std::optional<double> offset);
  // The key was released at t_s (ignored for unknown or already released ids).
  void note_off(std::int64_t id, double t_s);
  // Decides every event that may be decided at now_s; appends the decisions in event order.
  void advance(double now_s, std::vector<StreamedFinger>& out);
  // No more notes: decides everything still waiting.
  void flush(double now_s, std::vector<StreamedFinger>& out);

  music::Hand side() const { return side_; }
  std::size_t window_size() const { return window_.size(); }  // notes held in memory
  std::size_t pending_notes() const;

 private:
  struct WindowNote {
    std::int64_t id = 0;
    PlanNote note;
    bool offset_known = false;
    std::int64_t event = 0;  // sequence number of its event
    int finger = 0;          // 0 = not decided yet
  };

  StreamingHandPlanner(const FingeringModel& model, music::Hand side,
                       const StreamingOptions& options);
  void decide(std::int64_t event, double now_s, std::vector<StreamedFinger>& out);
  void prune();

  const FingeringModel* model_ = nullptr;
  music::Hand side_ = music::Hand::right;
  StreamingOptions options_;
  double chord_window_s_ = 0.001;
  std::vector<WindowNote> window_;  // in arrival order (events non-decreasing)
  std::int64_t newest_event_ = -1;
  double newest_onset_s_ = -std::numeric_limits<double>::infinity();
  std::vector<PlanNote> scratch_notes_;
  std::vector<std::size_t> scratch_index_;
};

}  // namespace tutti::fingering_planner
