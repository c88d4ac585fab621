// SPDX-License-Identifier: MIT
// What the editor shows of a keyboard player (stage/player_view.hpp): their hand size, pins,
// each note's planned finger and hand (or the foot that plays a pedal note), and the hands'
// allowed bands and paths.
#include <algorithm>
#include <cmath>
#include <utility>

#include <tutti/components/note.hpp>
#include <tutti/finger_motion/finger_pose_system.hpp>
#include <tutti/piano/keyboard_players.hpp>
#include <tutti/piano/piano_components.hpp>
#include <tutti/piano/piano_plugin.hpp>
#include <tutti/stage/player_view.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::piano {
namespace {

// The hands' allowed areas per event and the paths planned through them.
void add_hands(const ecs::World& world, ecs::Entity performer, stage::PlayerView& out) {
  if (const auto* plan = world.try_get<PianistPlan>(performer)) {
    const fingering_planner::HandPlan* hands[2] = {&plan->fingering.right, &plan->fingering.left};
    for (std::size_t side = 0; side < 2; ++side) {
      for (const piano_model::HandCorridor& c : hands[side]->corridors) {
        out.hand_bands[side].push_back({c.start_s, c.end_s, c.lo_mm, c.hi_mm});
      }
    }
  }
  const auto* handle = world.try_get<finger_motion::PianistMotionHandle>(performer);
  if (handle == nullptr || !handle->motion) return;
  const spline_motion::HandPath* paths[2] = {&handle->motion->right_path,
                                             &handle->motion->left_path};
  for (std::size_t side = 0; side < 2; ++side) {
    if (paths[side]->empty()) continue;
    for (double t = paths[side]->start_s(); t <= paths[side]->end_s() + 1e-9;
         t += stage::kHandPathStep_s) {
      out.hand_path[side].push_back({t, spline_motion::evaluate(*paths[side], t).x_mm});
    }
  }
}

}  // namespace

void PianoPlugin::describe_player(const stage::Stage& stage, ecs::Entity performer,
                                  stage::PlayerView& out) const {
  const ecs::World& world = stage.world();
  const auto* seat = world.try_get<stage::Seat>(performer);
  const auto& players = keyboard_players(stage.scene());
  if (seat == nullptr || seat->index >= players.size()) return;
  const KeyboardPlayer& player = players[seat->index];
  // The first keyboard player's lane reads "Pianist", as before a scene could have two.
  if (player.name == "pianist") out.lane_name = "Pianist";
  out.summary = player.hand_size + " hands";
  out.variation = player.variation;
  out.fingered = true;
  for (const FingerPin& pin : player.pins) out.pins.push_back({pin.time_s, pin.key, pin.finger});

  // Each of their notes: the planned finger and hand, pinned or not.
  for (std::size_t s = 0; s < stage.scores().size(); ++s) {
    for (std::size_t i = 0; i < stage.scores()[s].notes.size(); ++i) {
      const auto* note = world.try_get<components::Note>(stage.note_entity(s, i));
      if (note == nullptr || note->performer != performer) continue;
      stage::NoteMarking marking;
      marking.score = s;
      marking.note = i;
      marking.finger = note->finger;
      marking.right_hand = note->hand != components::HandSide::left;
      for (const FingerPin& pin : player.pins) {
        if (pin.key == note->pitch && std::abs(note->written_onset_s - pin.time_s) < 1e-3) {
          marking.pinned = true;
        }
      }
      out.notes.push_back(marking);
    }
  }
  // An organist's pedal notes: the foot that plays each (pins are for fingers only).
  if (const auto* plan = world.try_get<PianistPlan>(performer); plan != nullptr && plan->feet) {
    // out.notes is in (score, note) order, as built above.
    for (const PedalPress& press : plan->feet->presses) {
      const auto it = std::lower_bound(
          out.notes.begin(), out.notes.end(), std::make_pair(player.music_file, press.note),
          [](const stage::NoteMarking& m, std::pair<std::size_t, std::size_t> key) {
            return std::make_pair(m.score, m.note) < key;
          });
      if (it != out.notes.end() && it->score == player.music_file && it->note == press.note) {
        it->foot = press.foot;
      }
    }
  }
  add_hands(world, performer, out);
}

}  // namespace tutti::piano
