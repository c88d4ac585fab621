// SPDX-License-Identifier: MIT
#pragma once
// The pianist playing what arrives live: note events are fingered by the streaming planner
// (fingering_planner/streaming_piano.hpp: live hand split, lookahead 0 by default, decided in
// the frame they arrive), turned into key contacts and hand moves, and handed out as a new
// immutable finger_motion::PianistMotion whenever something changed. The pose at t is the
// existing pure evaluation (evaluate_hand_pose) of that motion, so it is a function of the
// events that have arrived by t and when they were seen.
//
// A live note has no warning, so its stroke cannot be seen coming: a note whose event is at
// t_e and is seen at the frame of time now (>= t_e) reaches the key bottom at `now` itself when
// now > t_e (the key is down in the very frame that saw the event), else 1 ms after t_e (the
// next frame). The finger leaves its previous key then, and the hand follows over
// `hand_move_s` (LiveHandPath); the fingertip is on the key at once.
//
// Bounded: the planner's window, the last `contacts_per_finger` contacts of each finger and the
// hand paths' last `moves_per_hand` moves. Allocates when a note arrives or ends, never per frame
// otherwise.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/finger_motion/finger_motion_params.hpp>
#include <tutti/finger_motion/finger_pose_system.hpp>
#include <tutti/fingering_planner/fingering_model.hpp>
#include <tutti/fingering_planner/streaming_piano.hpp>
#include <tutti/live/live_hand_path.hpp>
#include <tutti/live/live_note_event.hpp>

namespace tutti::live {

struct LivePianistOptions {
  fingering_planner::StreamingOptions planner = default_planner();
  double hand_move_s = 0.08;
  std::size_t contacts_per_finger = 8;
  std::size_t moves_per_hand = 16;  // hand path moves kept

  static fingering_planner::StreamingOptions default_planner() {
    fingering_planner::StreamingOptions o;
    o.lookahead = 0;
    o.max_wait_s = 0.0;
    o.chord_window_s = 0.03;  // a chord played by hand arrives over a few tens of milliseconds
    return o;
  }
};

// What became of one note-on.
struct LivePlayed {
  std::int64_t id = 0;
  int key = 60;  // on the keyboard (clamped)
  music::Hand hand = music::Hand::right;
  int finger = 1;
  double event_s = 0.0;
  double contact_s = 0.0;  // key bottom (press depth 1)
};

class LivePianist {
 public:
  // Errors: invalid planner options; the finger-motion template cannot be made.
  static Result<std::unique_ptr<LivePianist>> create(
      fingering_planner::FingeringModel model, const finger_motion::FingerMotionParams& params,
      const LivePianistOptions& options = {});

  // This frame's events (from any sources, times <= now_s), seen at now_s. Returns true when
  // the motion changed (motion() is then a new object).
  bool update(std::span<const LiveNoteEvent> events, double now_s);
  const std::shared_ptr<const finger_motion::PianistMotion>& motion() const { return motion_; }

  // The notes played so far, oldest first (the last 256).
  const std::vector<LivePlayed>& played() const { return played_; }
  int ignored_notes() const { return ignored_; }  // off the keyboard, or the planner refused

 private:
  LivePianist(std::unique_ptr<fingering_planner::FingeringModel> model,
              fingering_planner::StreamingPianoPlanner planner,
              finger_motion::FingerMotionPlan templ, const LivePianistOptions& options);
  void add_contact(const fingering_planner::StreamedFinger& decided, double now_s);
  void end_contact(std::int64_t id, double t_s);
  void rebuild();

  struct Sounding {
    std::int64_t id = 0;
    int key = 60;
    double event_s = 0.0;
    std::optional<double> released_s;  // note-off before the fingers were given
  };
  struct Contact {
    std::int64_t id = 0;
    finger_motion::KeyContact contact;
    bool open = true;  // no note-off yet
  };

  std::unique_ptr<fingering_planner::FingeringModel> model_;  // the planner points into it
  fingering_planner::StreamingPianoPlanner planner_;
  finger_motion::FingerMotionPlan template_;
  LivePianistOptions options_;
  std::array<LiveHandPath, 2> paths_;                            // right, left
  std::array<std::array<std::vector<Contact>, 5>, 2> contacts_;  // [hand][finger]
  std::array<std::int64_t, 128> key_id_{};                       // sounding note per key, 0 = none
  std::vector<Sounding> sounding_;
  std::vector<fingering_planner::StreamedFinger> decided_;
  std::vector<LivePlayed> played_;
  std::shared_ptr<const finger_motion::PianistMotion> motion_;
  std::int64_t next_id_ = 1;
  int ignored_ = 0;
};

}  // namespace tutti::live
