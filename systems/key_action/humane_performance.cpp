// SPDX-License-Identifier: MIT
#include <tutti/key_action/humane_performance.hpp>

#include <algorithm>
#include <cmath>

#include <tutti/finger_motion/plan_finger_motion.hpp>

namespace tutti::key_action {

Result<HumanePerformance> perform(const HumaneInputs& in, const KeySimulationOptions& options) {
  if (in.score == nullptr || in.fingering == nullptr || in.right_path == nullptr ||
      in.left_path == nullptr || in.keyboard == nullptr || in.hand_model == nullptr ||
      in.params == nullptr || in.action == nullptr || in.style == nullptr) {
    return Error{"key_action::perform: an input is missing"};
  }
  HumanePerformance out;
  const finger_motion::FingerMotionParams params = apply_style(*in.params, *in.style);
  out.strokes = plan_note_strokes(*in.score, *in.fingering, *in.keyboard, *in.hand_model, params,
                                  *in.action, *in.style, in.seed);
  auto fingers =
      finger_motion::plan_finger_motion(*in.score, *in.fingering, *in.right_path, *in.left_path,
                                        *in.keyboard, *in.hand_model, params, out.strokes.strokes);
  if (!fingers) return fingers.error();
  out.motion = std::make_shared<finger_motion::PianistMotion>();
  out.motion->fingers = std::move(*fingers);
  out.motion->right_path = *in.right_path;
  out.motion->left_path = *in.left_path;
  out.played = simulate_keys(*in.score, *in.fingering, *out.motion, *in.action, options);
  out.report = report_performance(*in.score, out.played);
  return out;
}

music::Score performed_score(const music::Score& score, std::span<const PlayedNote> played) {
  music::Score out = score;
  out.notes.clear();
  out.notes.reserve(score.notes.size());
  const music::TempoMap& tempo = score.tempo_map;
  const auto ticks_at = [&](double s) {
    return static_cast<std::int64_t>(std::llround(tempo.ticks_at_seconds(s)));
  };
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    music::Note note = score.notes[i];
    if (i < played.size() && played[i].outcome != KeyOutcome::not_played) {
      const PlayedNote& p = played[i];
      if (p.outcome != KeyOutcome::sounded) continue;
      // Motor noise can sound a first note a little before the music starts; nothing is written
      // (or heard) before time 0.
      note.onset_s = std::max(p.onset_s, 0.0);
      note.offset_s = std::max(p.offset_s, note.onset_s);
      note.onset_ticks = std::max<std::int64_t>(0, ticks_at(note.onset_s));
      note.offset_ticks = std::max(note.onset_ticks, ticks_at(note.offset_s));
      note.onset_beats = tempo.beats_at_seconds(note.onset_s);
      note.offset_beats = tempo.beats_at_seconds(note.offset_s);
      note.velocity = std::clamp(p.velocity, 1, 127);
    }
    out.notes.push_back(note);
  }
  for (const music::Note& note : out.notes) {
    out.end_ticks = std::max(out.end_ticks, note.offset_ticks);
    out.end_s = std::max(out.end_s, note.offset_s);
  }
  return out;
}

}  // namespace tutti::key_action
