// SPDX-License-Identifier: MIT
#include <tutti/piano/plan_pianist.hpp>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include <tutti/finger_motion/finger_motion_params.hpp>
#include <tutti/finger_motion/plan_finger_motion.hpp>
#include <tutti/fingering_planner/chord_roll.hpp>
#include <tutti/fingering_planner/fingering_model.hpp>
#include <tutti/key_action/humane_performance.hpp>
#include <tutti/piano/keyboard_players.hpp>
#include <tutti/piano/pedal_feet.hpp>
#include <tutti/piano_model/keyboard_instruments.hpp>
#include <tutti/piano_performance/performance_plan.hpp>
#include <tutti/scene/load_scene.hpp>

namespace tutti::piano {
namespace {

// A key outside the instrument's compass, moved by octaves onto it.
int fold_onto(int key, const piano_model::KeyboardInstrument& instrument) {
  while (key < instrument.lowest_key) key += 12;
  while (key > instrument.highest_key) key -= 12;
  return key;
}

// What the pianist's fingering without the scene's pins depends on.
std::string pianist_base_key(const scene::Scene& scene, const KeyboardPlayer& pianist) {
  std::string key = scene.music[pianist.music_file].string() + "|" + pianist.instrument + "|" +
                    pianist.hand_size + "|";
  for (const std::string& part : pianist.parts) key += part + ",";
  return key;
}

// Everything the pianist's plan depends on.
std::string pianist_plan_key(const scene::Scene& scene, const KeyboardPlayer& pianist) {
  std::string key = pianist_base_key(scene, pianist);
  if (!pianist.style.empty() || pianist.sound_from_keys) {
    key += "|style " + pianist.style + (pianist.sound_from_keys ? " keys " : " score ") +
           std::to_string(pianist.seed);
  }
  char text[64];
  for (const FingerPin& pin : pianist.pins) {
    std::snprintf(text, sizeof text, "|%.17g:%d:%d", pin.time_s, pin.key, pin.finger);
    key += text;
  }
  return key;
}

// The editor's pins become the planner's pins (Note::finger, plan_score's pins_from_marks). A
// pin names its note by key and onset; one that matches no note is an error, not ignored.
Status apply_finger_pins(const scene::Scene& scene, const KeyboardPlayer& pianist,
                         const piano_model::KeyboardInstrument& instrument, music::Score& score) {
  constexpr double kSameOnset_s = 1e-3;
  for (std::size_t i = 0; i < pianist.pins.size(); ++i) {
    const FingerPin& pin = pianist.pins[i];
    music::Note* pinned = nullptr;
    for (music::Note& note : score.notes) {
      if (note.pitch == fold_onto(pin.key, instrument) &&
          std::abs(note.onset_s - pin.time_s) < kSameOnset_s) {
        pinned = &note;
        break;
      }
    }
    if (pinned == nullptr) {
      char time[32];
      std::snprintf(time, sizeof time, "%.3f", pin.time_s);
      return Error{scene.source + ": " + pianist.pointer + "/pins/" + std::to_string(i) +
                   ": no note of key " +
                   std::to_string(pin.key) + " starts at " + time +
                   " s in the pianist's parts of " +
                   scene.music[pianist.music_file].filename().string()};
    }
    pinned->finger = pin.finger;
  }
  return Status::success();
}

// The pianist's motion in the scene's performance style, and what the keys make of it.
Result<key_action::HumanePerformance> perform_in_style(
    const scene::Scene& scene, const KeyboardPlayer& pianist, const music::Score& score,
    const piano_performance::PianoPerformancePlan& paths,
    const fingering_planner::FingeringModel& model,
    const piano_model::KeyboardInstrument& instrument,
    const finger_motion::FingerMotionParams& params, const std::filesystem::path& content_dir) {
  auto styles = key_action::load_styles(key_action::styles_path(content_dir));
  if (!styles) return styles.error();
  auto style = styles->find(pianist.style.empty() ? "precise" : pianist.style);
  if (!style) {
    return Error{scene.source + ": " + pianist.pointer + "/style: " + style.error().message};
  }
  auto action = key_action::load_key_action(
      key_action::key_action_path(content_dir), instrument.touch_or_piano(),
      "instruments.json /instruments/" + instrument.id + "/touch");
  if (!action) return action.error();
  key_action::HumaneInputs in;
  in.score = &score;
  in.fingering = &paths.fingering;
  in.right_path = &paths.right_path;
  in.left_path = &paths.left_path;
  in.keyboard = &model.keyboard;
  in.hand_model = &model.hand;
  in.params = &params;
  in.action = &*action;
  in.style = &*style;
  in.seed = pianist.seed;
  return key_action::perform(in);
}

// The fingering of `unpinned`; chords a hand cannot span with it are rolled (chord_roll.hpp)
// and the rolled score planned again with the same fingers, so hand paths and strokes follow.
Result<fingering_planner::ScorePlan> plan_rolling_wide_chords(
    const music::Score& unpinned, const fingering_planner::FingeringModel& model,
    fingering_planner::ChordRolls& rolls) {
  auto planned = fingering_planner::plan_score(unpinned, model);
  if (!planned) return planned.error();
  rolls = fingering_planner::plan_chord_rolls(unpinned, *planned, model);
  if (rolls.empty()) return planned;
  music::Score rolled = unpinned;
  fingering_planner::apply_chord_rolls(rolls, rolled);
  for (std::size_t i = 0; i < rolled.notes.size() && i < planned->fingers.size(); ++i) {
    rolled.notes[i].finger = planned->fingers[i];
  }
  return fingering_planner::plan_score(rolled, model);
}

}  // namespace

Result<PianistPlan> plan_pianist(stage::StageBuilder& builder, std::size_t index) {
  const scene::Scene& scene = builder.scene();
  const KeyboardPlayer& pianist = keyboard_players(scene).at(index);
  const std::filesystem::path& content_dir = builder.content_dir();
  const music::Score& full = builder.scores()[pianist.music_file];
  PianistPlan plan;
  // Only the parts the pianist plays.
  music::Score score = full;
  std::vector<bool> played(full.parts.size(), false);
  for (const std::string& name : pianist.parts) {
    const int part = scene::find_part(full, name);
    if (part < 0) {
      return Error{scene.source + ": " + pianist.name + ": no part \"" + name + "\" in " +
                   scene.music[pianist.music_file].filename().string()};
    }
    played[static_cast<std::size_t>(part)] = true;
  }
  score.notes.clear();
  for (std::size_t i = 0; i < full.notes.size(); ++i) {
    if (played[static_cast<std::size_t>(full.notes[i].part)]) {
      score.notes.push_back(full.notes[i]);
      plan.full_index.push_back(i);
    }
  }
  // The instrument's compass: notes beyond it are played an octave (or more) in.
  auto instruments =
      piano_model::KeyboardInstruments::load(piano_model::keyboard_instruments_path(content_dir));
  if (!instruments) return instruments.error();
  const piano_model::KeyboardInstrument* instrument = instruments->find(pianist.instrument);
  if (instrument == nullptr) {
    return Error{scene.source + ": " + pianist.pointer + "/instrument: no keyboard instrument \"" +
                 pianist.instrument + "\""};
  }
  // An organ's pedal notes go to the feet (pedal_feet.hpp); the hands play the rest.
  if (instrument->pedalboard) {
    const std::vector<bool> pedal = choose_pedal_notes(score, *instrument->pedalboard);
    auto feet = std::make_shared<FeetPlan>(plan_feet(score, pedal, *instrument->pedalboard));
    for (PedalPress& press : feet->presses) press.note = plan.full_index[press.note];
    std::vector<music::Note> hands_notes;
    std::vector<std::size_t> hands_index;
    for (std::size_t i = 0; i < score.notes.size(); ++i) {
      if (pedal[i]) continue;
      hands_notes.push_back(score.notes[i]);
      hands_index.push_back(plan.full_index[i]);
    }
    score.notes = std::move(hands_notes);
    plan.full_index = std::move(hands_index);
    if (!feet->empty()) {
      plan.plan_notes.push_back(
          pianist.name + ": " + std::to_string(feet->presses.size()) +
          (feet->presses.size() == 1 ? " note" : " notes") + " on the pedals (" +
          std::to_string(feet->by_foot[kLeftFoot].size()) + " left foot, " +
          std::to_string(feet->by_foot[kRightFoot].size()) + " right foot" +
          (feet->folded > 0 ? ", " + std::to_string(feet->folded) + " moved by octaves onto them"
                            : std::string()) +
          ")");
    }
    plan.feet = std::move(feet);
  }
  std::size_t folded = 0;
  for (music::Note& note : score.notes) {
    const int key = fold_onto(note.pitch, *instrument);
    folded += key != note.pitch ? 1 : 0;
    note.pitch = key;
  }
  if (folded > 0) {
    plan.plan_notes.push_back(pianist.name + ": " + std::to_string(folded) +
                              (folded == 1 ? " note" : " notes") + " beyond the " +
                              instrument->id + "'s keys played an octave in");
  }
  // The editor's pins act locally: the fingering without them (the file's own marks are pins
  // there too) is planned once, then only the span around the pinned notes is searched again
  // (fingering_planner::replan_score_locally). A pure function of the score and the pins, so the
  // editor and `tutti render` get the same fingering whatever order the pins were placed in.
  const music::Score unpinned = score;
  if (Status s = apply_finger_pins(scene, pianist, *instrument, score); !s) return s.error();
  std::vector<int> pinned_notes;
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    if (score.notes[i].finger != unpinned.notes[i].finger)
      pinned_notes.push_back(static_cast<int>(i));
  }
  auto model = fingering_planner::load_fingering_model("default", pianist.hand_size, content_dir,
                                                       instrument);
  if (!model) return model.error();
  plan.base_key = pianist_base_key(scene, pianist);
  plan.plan_key = pianist_plan_key(scene, pianist);
  const stage::Stage* reuse = builder.previous();
  const ecs::Entity previous_entity =
      reuse != nullptr ? reuse->find_performer("piano", index) : ecs::Entity::null;
  const PianistPlan* previous =
      previous_entity.is_null() ? nullptr : reuse->world().try_get<PianistPlan>(previous_entity);
  if (previous != nullptr && previous->plan_key == plan.plan_key && previous->motion) {
    plan.motion = previous->motion;
    plan.fingering = previous->fingering;
    plan.base_fingering = previous->base_fingering;
    plan.plan_notes = previous->plan_notes;
    plan.played = previous->played;
    plan.performance = previous->performance;
    plan.rolls = previous->rolls;
    fingering_planner::apply_chord_rolls(plan.rolls, score);
  } else {
    if (previous != nullptr && previous->base_key == plan.base_key) {
      plan.base_fingering = previous->base_fingering;
      plan.rolls = previous->rolls;
    } else {
      auto planned = plan_rolling_wide_chords(unpinned, *model, plan.rolls);
      if (!planned) return planned.error();
      plan.base_fingering = std::move(*planned);
      builder.replanned(pianist.name + " fingering");
    }
    if (plan.rolls.chords > 0) {
      plan.plan_notes.push_back(pianist.name + ": " + std::to_string(plan.rolls.chords) +
                                (plan.rolls.chords == 1 ? " chord" : " chords") +
                                " too wide for the hand rolled");
    }
    fingering_planner::apply_chord_rolls(plan.rolls, score);
    plan.fingering = plan.base_fingering;
    if (!pinned_notes.empty()) {
      fingering_planner::ScoreReplanSpan span;
      auto replanned = fingering_planner::replan_score_locally(
          score, *model, {}, plan.base_fingering, pinned_notes, &span);
      if (!replanned) return replanned.error();
      plan.fingering = std::move(*replanned);
      builder.replanned(pianist.name + " fingering around the pins (" +
                        std::to_string(span.searched_events) + " of " +
                        std::to_string(span.event_count) + " events)");
    }
    piano_performance::PianoPerformancePlan performance =
        piano_performance::plan_performance_paths(plan.fingering);
    for (const piano_performance::HandReport* hand :
         {&performance.report.right, &performance.report.left}) {
      if (!hand->path_error.empty()) plan.plan_notes.push_back(pianist.name + ": " + hand->path_error);
    }
    auto params = finger_motion::load_finger_motion_params(
        finger_motion::finger_motion_params_path(content_dir));
    if (!params) return params.error();
    if (!pianist.style.empty() || pianist.sound_from_keys) {
      auto humane =
          perform_in_style(scene, pianist, score, performance, *model, *instrument, *params,
                           content_dir);
      if (!humane) return humane.error();
      plan.motion = std::move(humane->motion);
      plan.performance = humane->report;
      plan.played =
          std::make_shared<const std::vector<key_action::PlayedNote>>(std::move(humane->played));
    } else {
      auto fingers = finger_motion::plan_finger_motion(
          score, performance.fingering, performance.right_path, performance.left_path,
          model->keyboard, model->hand, *params);
      if (!fingers) return fingers.error();
      auto planned_motion = std::make_shared<finger_motion::PianistMotion>();
      planned_motion->fingers = std::move(*fingers);
      planned_motion->right_path = std::move(performance.right_path);
      planned_motion->left_path = std::move(performance.left_path);
      plan.motion = std::move(planned_motion);
    }
    builder.replanned(pianist.name + " motion");
  }
  plan.score = std::move(score);
  return plan;
}

}  // namespace tutti::piano
