// SPDX-License-Identifier: MIT
#include <tutti/editor/timeline.hpp>

#include <algorithm>
#include <cmath>

#include <tutti/brass/brass_players.hpp>
#include <tutti/brass_motion/brass_pose_system.hpp>
#include <tutti/components/breath_schedule.hpp>
#include <tutti/components/note.hpp>
#include <tutti/components/performer.hpp>
#include <tutti/ensemble_variation/ensemble_variation_system.hpp>
#include <tutti/finger_motion/finger_pose_system.hpp>
#include <tutti/music/meter.hpp>
#include <tutti/piano/keyboard_players.hpp>
#include <tutti/piano/piano_components.hpp>

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

// A performer's lane: their notes (as written; a keyboard player's with the planned or pinned
// finger and hand), their planned breaths, their expressions.
TimelineLane performer_lane(const stage::Stage& stage, ecs::Entity performer) {
  const ecs::World& world = stage.world();
  const auto& seat = world.get<stage::Seat>(performer);
  TimelineLane lane;
  lane.family = seat.family;
  lane.index = seat.index;
  lane.player = seat.player;
  const bool keyboard = world.has<piano_family::PianistPlan>(performer);
  lane.fingered = keyboard;
  lane.breathes = world.has<components::BreathSchedule>(performer);
  const auto* about = world.try_get<components::Performer>(performer);
  lane.name = about != nullptr ? about->name : std::string();
  // The first pianist's lane reads "Pianist", as before a scene could have two.
  if (keyboard && lane.name == "pianist") lane.name = "Pianist";
  for (std::size_t s = 0; s < stage.scores().size(); ++s) {
    for (std::size_t i = 0; i < stage.scores()[s].notes.size(); ++i) {
      const auto* note = world.try_get<components::Note>(stage.note_entity(s, i));
      if (note == nullptr || note->performer != performer) continue;
      TimelineNote n;
      n.start_s = note->written_onset_s;
      n.end_s = note->written_offset_s;
      n.key = note->pitch;
      n.playable = note->playable;
      if (lane.fingered) {
        n.finger = note->finger;
        n.right_hand = note->hand != components::HandSide::left;
      }
      lane.notes.push_back(n);
      lane.lowest_key = std::min(lane.lowest_key, note->pitch);
      lane.highest_key = std::max(lane.highest_key, note->pitch);
    }
  }
  if (const auto* schedule = world.try_get<components::BreathSchedule>(performer)) {
    for (const components::BreathSpan& span : schedule->breaths) {
      TimelineBreath b;
      b.prepare_s = span.prepare_s;
      b.start_s = span.start_s;
      b.end_s = span.end_s;
      b.catch_breath = span.catch_breath;
      b.marked = span.marked;
      b.boundary_s = span.boundary_s;
      lane.breaths.push_back(b);
    }
  }
  const scene::Scene& scene = stage.scene();
  const auto& brass_players = brass_family::brass_players(scene);
  const auto& keyboard_players = piano_family::keyboard_players(scene);
  const bool brass_player = world.has<brass::BrassPlayerMotionHandle>(performer);
  if (brass_player && seat.index < brass_players.size()) {
    lane.expressive = true;
    lane.expressions = brass_players[seat.index].expressions;
  }
  // An organist's pedal notes: the foot that plays each (pins are for fingers only).
  if (const auto* plan = world.try_get<piano_family::PianistPlan>(performer);
      plan != nullptr && plan->feet && seat.index < keyboard_players.size()) {
    const std::size_t music = keyboard_players[seat.index].music_file;
    for (const piano_family::PedalPress& press : plan->feet->presses) {
      const auto* note = world.try_get<components::Note>(stage.note_entity(music, press.note));
      if (note == nullptr) continue;
      for (TimelineNote& n : lane.notes) {
        if (n.key == note->pitch && n.start_s == note->written_onset_s) n.foot = press.foot;
      }
    }
  }
  if (keyboard && seat.index < keyboard_players.size()) {
    for (const piano_family::FingerPin& pin : keyboard_players[seat.index].pins) {
      for (TimelineNote& n : lane.notes) {
        if (n.key == pin.key && std::abs(n.start_s - pin.time_s) < 1e-3) n.pinned = true;
      }
    }
  }
  return lane;
}

// The pianist's allowed hand areas and the hand paths planned through them.
void add_hand_paths(const stage::Stage& stage, ecs::Entity pianist, TimelineLane& out) {
  const ecs::World& world = stage.world();
  if (const auto* plan = world.try_get<piano_family::PianistPlan>(pianist)) {
    const piano::HandPlan* hands[2] = {&plan->fingering.right, &plan->fingering.left};
    for (std::size_t side = 0; side < 2; ++side) {
      for (const piano::HandCorridor& c : hands[side]->corridors) {
        out.corridors[side].push_back({c.start_s, c.end_s, c.lo_mm, c.hi_mm});
      }
    }
  }
  const auto* handle = world.try_get<finger_motion::PianistMotionHandle>(pianist);
  if (handle == nullptr || !handle->motion) return;
  const spline_motion::HandPath* paths[2] = {&handle->motion->right_path, &handle->motion->left_path};
  for (std::size_t side = 0; side < 2; ++side) {
    if (paths[side]->empty()) continue;
    for (double t = paths[side]->start_s(); t <= paths[side]->end_s() + 1e-9;
         t += kHandPathStep_s) {
      out.hand_path[side].push_back({t, spline_motion::evaluate(*paths[side], t).x_mm});
    }
  }
}

}  // namespace

Timeline build_timeline(const stage::Stage& stage) {
  Timeline out;
  out.start_s = stage.start_s();
  out.end_s = stage.end_s();
  if (!stage.scores().empty()) add_grid(stage.scores().front(), out.end_s, out);
  const ecs::World& world = stage.world();
  for (ecs::Entity performer : stage.performers()) {
    out.lanes.push_back(performer_lane(stage, performer));
    if (out.lanes.back().fingered) add_hand_paths(stage, performer, out.lanes.back());
    if (const auto* ensemble = world.try_get<ensemble_variation::EnsembleMotionHandle>(performer);
        ensemble != nullptr && ensemble->plan && out.cues_s.empty()) {
      out.cues_s = ensemble->plan->cue_entrances_s;
    }
  }
  const scene::Scene& scene = stage.scene();
  out.cues_automatic = !scene.cues_s.has_value();
  for (const scene::Shot& shot : scene.shots) {
    out.shots.push_back({shot.start_s, scene.cameras[shot.camera].name});
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
