// SPDX-License-Identifier: MIT
#include <tutti/editor/timeline.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

#include <tutti/components/breath_schedule.hpp>
#include <tutti/components/note.hpp>
#include <tutti/components/performer.hpp>
#include <tutti/ensemble_variation/ensemble_variation_system.hpp>
#include <tutti/music/meter.hpp>
#include <tutti/stage/family_plugin.hpp>

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

// The family that plays `performer` (nullptr: none of the stage's).
const stage::FamilyPlugin* family_of(const stage::Stage& stage, const stage::Seat& seat) {
  for (const stage::FamilyPlugin* family : stage.families()) {
    if (family->name() == seat.family) return family;
  }
  return nullptr;
}

// The family's marking of note `note` of score `score`, or nullptr (`markings` sorted by
// (score, note), as PlayerView::notes is: a re-plan builds every lane, so no linear scan per note).
const stage::NoteMarking* find_marking(const std::vector<stage::NoteMarking>& markings,
                                       std::size_t score, std::size_t note) {
  const auto it =
      std::lower_bound(markings.begin(), markings.end(), std::make_pair(score, note),
                       [](const stage::NoteMarking& m, std::pair<std::size_t, std::size_t> key) {
                         return std::make_pair(m.score, m.note) < key;
                       });
  return it != markings.end() && it->score == score && it->note == note ? &*it : nullptr;
}

// A performer's lane: their notes (as written), their planned breaths, and what their family
// shows of them (a fingered player's fingers, hands and pins; expressions; the inspector's
// summary).
TimelineLane performer_lane(const stage::Stage& stage, ecs::Entity performer) {
  const ecs::World& world = stage.world();
  const auto& seat = world.get<stage::Seat>(performer);
  TimelineLane lane;
  lane.family = seat.family;
  lane.index = seat.index;
  lane.player = seat.player;
  lane.breathes = world.has<components::BreathSchedule>(performer);
  const auto* about = world.try_get<components::Performer>(performer);
  lane.name = about != nullptr ? about->name : std::string();
  stage::PlayerView view;
  if (const stage::FamilyPlugin* family = family_of(stage, seat)) {
    family->describe_player(stage, performer, view);
  }
  lane.fingered = view.fingered;
  lane.expressive = view.expressive;
  lane.summary = std::move(view.summary);
  lane.variation = view.variation;
  lane.seed = about != nullptr ? about->seed : 0;
  lane.pins = std::move(view.pins);
  lane.expressions = std::move(view.expressions);
  lane.corridors = std::move(view.hand_bands);
  lane.hand_path = std::move(view.hand_path);
  if (!view.lane_name.empty()) lane.name = view.lane_name;
  for (std::size_t s = 0; s < stage.scores().size(); ++s) {
    for (std::size_t i = 0; i < stage.scores()[s].notes.size(); ++i) {
      const auto* note = world.try_get<components::Note>(stage.note_entity(s, i));
      if (note == nullptr || note->performer != performer) continue;
      TimelineNote n;
      n.start_s = note->written_onset_s;
      n.end_s = note->written_offset_s;
      n.key = note->pitch;
      n.playable = note->playable;
      if (const stage::NoteMarking* marking = find_marking(view.notes, s, i)) {
        n.finger = marking->finger;
        n.right_hand = marking->right_hand;
        n.foot = marking->foot;
        n.pinned = marking->pinned;
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
  return lane;
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
