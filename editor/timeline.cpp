#include <tutti/editor/timeline.hpp>

#include <algorithm>
#include <cmath>

#include <tutti/brass_motion/plan_brass_player.hpp>
#include <tutti/ensemble_variation/ensemble_plan.hpp>
#include <tutti/finger_motion/finger_pose_system.hpp>
#include <tutti/music/meter.hpp>

namespace tutti::editor {
namespace {

// Bar lines and beats of the first score over [start, end].
void add_grid(const music::Score& score, double end_s, Timeline& out) {
  double beats = 0.0;
  int bar = music::bar_at_beats(score, 0.0);
  for (int guard = 0; guard < 100000; ++guard) {
    const double t = score.tempo_map.seconds_at_beats(beats);
    if (t > end_s) break;
    const int bar_here = music::bar_at_beats(score, beats + 1e-9);
    if (guard == 0 || bar_here != bar) out.bars_s.push_back(t);
    bar = bar_here;
    out.beats_s.push_back(t);
    beats += std::max(0.25, music::beat_length_at(score, beats + 1e-9));
  }
}

TimelineLane brass_lane(const stage::Stage& stage, std::size_t i) {
  const stage::BrassSeat& seat = stage.brass[i];
  TimelineLane lane;
  lane.name = seat.name;
  lane.performer = i;
  for (const stage::LineNoteTime& note : seat.line) {
    TimelineNote n;
    n.start_s = note.onset_s;
    n.end_s = note.offset_s;
    n.key = note.pitch;
    n.playable = note.playable;
    lane.notes.push_back(n);
    lane.lowest_key = std::min(lane.lowest_key, note.pitch);
    lane.highest_key = std::max(lane.highest_key, note.pitch);
  }
  if (i < stage.ensemble_players.size() && stage.ensemble_players[i]) {
    for (const brass::BreathEvent& event : stage.ensemble_players[i]->breaths.events) {
      TimelineBreath b;
      b.prepare_s = event.prepare_start_s;
      b.start_s = event.start_s;
      b.end_s = event.end_s;
      b.catch_breath = event.kind == brass::BreathKind::catch_breath;
      b.marked = event.marked;
      b.boundary_s =
          event.before_note >= 0 && static_cast<std::size_t>(event.before_note) < seat.line.size()
              ? seat.line[static_cast<std::size_t>(event.before_note)].onset_s
              : event.end_s;
      lane.breaths.push_back(b);
    }
  }
  if (i < stage.scene.performers.size()) {
    const scene::Performer& performer = stage.scene.performers[i];
    lane.expressions = performer.expressions;
  }
  return lane;
}

TimelineLane pianist_lane(const stage::Stage& stage) {
  const stage::PianistSeat& seat = *stage.pianist;
  TimelineLane lane;
  lane.name = "Pianist";
  lane.pianist = true;
  for (std::size_t i = 0; i < seat.score.notes.size(); ++i) {
    const music::Note& note = seat.score.notes[i];
    TimelineNote n;
    n.start_s = note.onset_s;
    n.end_s = note.offset_s;
    n.key = note.pitch;
    n.finger = i < seat.fingering.fingers.size() ? seat.fingering.fingers[i] : 0;
    n.right_hand = i >= seat.fingering.hands.size() || seat.fingering.hands[i] != music::Hand::left;
    lane.notes.push_back(n);
    lane.lowest_key = std::min(lane.lowest_key, note.pitch);
    lane.highest_key = std::max(lane.highest_key, note.pitch);
  }
  if (stage.scene.pianist) {
    for (const scene::FingerPin& pin : stage.scene.pianist->pins) {
      for (TimelineNote& n : lane.notes) {
        if (n.key == pin.key && std::abs(n.start_s - pin.time_s) < 1e-3) n.pinned = true;
      }
    }
  }
  return lane;
}

}  // namespace

Timeline build_timeline(const stage::Stage& stage) {
  Timeline out;
  out.start_s = stage.start_s;
  out.end_s = stage.end_s;
  if (!stage.scores.empty()) add_grid(stage.scores.front(), out.end_s, out);
  for (std::size_t i = 0; i < stage.brass.size(); ++i) out.lanes.push_back(brass_lane(stage, i));
  if (stage.pianist) {
    out.lanes.push_back(pianist_lane(stage));
    const piano::HandPlan* hands[2] = {&stage.pianist->fingering.right,
                                       &stage.pianist->fingering.left};
    for (std::size_t side = 0; side < 2; ++side) {
      for (const piano::HandCorridor& c : hands[side]->corridors) {
        out.corridors[side].push_back({c.start_s, c.end_s, c.lo_mm, c.hi_mm});
      }
    }
    if (const auto& motion = stage.pianist->motion) {
      const motion::HandPath* paths[2] = {&motion->right_path, &motion->left_path};
      for (std::size_t side = 0; side < 2; ++side) {
        if (paths[side]->empty()) continue;
        for (double t = paths[side]->start_s(); t <= paths[side]->end_s() + 1e-9;
             t += kHandPathStep_s) {
          out.hand_path[side].push_back({t, motion::evaluate(*paths[side], t).x_mm});
        }
      }
    }
  }
  out.cues_automatic = !stage.scene.cues_s.has_value();
  if (stage.ensemble) out.cues_s = stage.ensemble->cue_entrances_s;
  for (const scene::Shot& shot : stage.scene.shots) {
    out.shots.push_back({shot.start_s, stage.scene.cameras[shot.camera].name});
  }
  return out;
}

double snap_to_beat(const Timeline& timeline, double t, double tolerance_s) {
  const auto it = std::lower_bound(timeline.beats_s.begin(), timeline.beats_s.end(), t);
  double best = t;
  double best_distance = tolerance_s;
  for (auto candidate : {it, it == timeline.beats_s.begin() ? it : it - 1}) {
    if (candidate == timeline.beats_s.end()) continue;
    const double d = std::abs(*candidate - t);
    if (d <= best_distance) {
      best = *candidate;
      best_distance = d;
    }
  }
  return best;
}

}  // namespace tutti::editor
