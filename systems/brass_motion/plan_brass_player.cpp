// SPDX-License-Identifier: MIT
#include <tutti/brass_motion/plan_brass_player.hpp>

#include <algorithm>

#include <tutti/brass_motion/plan_brass_motion.hpp>

namespace tutti::brass_motion {

// The brass planner's names used here (systems/fingering_planner).
using fingering_planner::BrassPlanSummary;
using fingering_planner::plan_line;
using fingering_planner::PlannerWeights;

// The brass model's names used here (systems/brass_model).
using brass_model::BrassLine;
using brass_model::ChangeWindow;
using brass_model::LineNote;

BrassLine as_played(const BrassLine& line, const BreathPlan& breaths) {
  BrassLine played = line;
  for (const ShortenedNote& s : breaths.shortened) {
    if (s.note < 0 || static_cast<std::size_t>(s.note) >= played.notes.size()) continue;
    LineNote& note = played.notes[static_cast<std::size_t>(s.note)];
    if (s.offset_s < note.offset_s) {
      note.offset_s = std::max(s.offset_s, note.onset_s);
      note.offset_beats = std::max(s.offset_beats, note.onset_beats);
    }
  }
  return played;
}

BrassPlanSummary plan_line_around_breaths(BrassLine& line, const music::Score& score,
                                          const PlannerWeights& weights, const BreathParams& breath,
                                          const BreathMarks& marks) {
  BrassLine played = as_played(line, plan_breaths(line, score, breath, marks));
  BrassPlanSummary summary = plan_line(played, weights, &score);
  for (std::size_t i = 0; i < line.notes.size(); ++i) {
    LineNote& note = line.notes[i];
    const double offset_s = note.offset_s, offset_beats = note.offset_beats;
    note = played.notes[i];
    note.offset_s = offset_s;
    note.offset_beats = offset_beats;
  }
  return summary;
}

BrassPlayerMotion plan_brass_player(const BrassLine& line, const music::Score& score,
                                    const BrassMotionParams& motion, const BreathParams& breath,
                                    const ChangeWindow& window, const BreathMarks& marks) {
  BrassPlayerMotion out;
  out.breaths = plan_breaths(line, score, breath, marks);
  out.motion = plan_brass_motion(as_played(line, out.breaths), motion, window);
  return out;
}

}  // namespace tutti::brass_motion
