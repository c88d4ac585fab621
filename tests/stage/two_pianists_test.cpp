// SPDX-License-Identifier: MIT
// Two pianists on one stage (content/scenes/piano_duo.json): each is a performer of their own at
// a piano of their own, plays the notes of their own part, and touches only their own keys.
#include <tutti/stage/stage.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include <tutti/components/note.hpp>
#include <tutti/components/performer.hpp>
#include <tutti/model/model_asset.hpp>
#include <tutti/piano/keyboard_players.hpp>
#include <tutti/piano/piano_components.hpp>
#include <tutti/piano_model/pedal_geometry.hpp>
#include <tutti/performance/families.hpp>
#include <tutti/scene/load_scene.hpp>
#include <tutti/stage/contact_recorder.hpp>
#include "bundled_stage.hpp"

namespace tutti::stage {
namespace {

using piano::PianoRig;

TEST(TwoPianists, EachPlaysTheirOwnPartAtTheirOwnPiano) {
  auto stage = test::stage_bundled_scene("piano_duo.json");
  ASSERT_NE(stage, nullptr);
  const ecs::World& world = stage->world();
  const ecs::Entity first = stage->find_performer("piano", 0);
  const ecs::Entity second = stage->find_performer("piano", 1);
  ASSERT_FALSE(first.is_null());
  ASSERT_FALSE(second.is_null());
  EXPECT_EQ(world.get<components::Performer>(first).name, "pianist");
  EXPECT_EQ(world.get<components::Performer>(second).name, "pianist 2");
  const PianoRig& rig_1 = world.get<PianoRig>(first);
  const PianoRig& rig_2 = world.get<PianoRig>(second);
  ASSERT_NE(rig_1.piano, rig_2.piano);
  // The pianos stand where their benches are: 1.7 m apart, as the scene places them.
  const auto root_of = [&](ecs::Entity piano) {
    const auto& instances = stage->instances();
    const auto at = std::find(instances.begin(), instances.end(), piano);
    if (at == instances.end()) {
      ADD_FAILURE() << "the piano is not placed";
      return glm::vec3(0.0f);
    }
    return glm::vec3(stage->placed(static_cast<std::size_t>(at - instances.begin())).root[3]);
  };
  const glm::vec3 piano_1 = root_of(rig_1.piano);
  const glm::vec3 piano_2 = root_of(rig_2.piano);
  EXPECT_NEAR(piano_2.x - piano_1.x, 1.7f, 1e-4f);

  // Every note of part i (Piano I, Piano II) is claimed by pianist i, and by nobody else.
  const music::Score& score = stage->scores().front();
  std::size_t claimed[2] = {0, 0};
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    const auto& note = world.get<components::Note>(stage->note_entity(0, i));
    const ecs::Entity expected = score.notes[i].part == 0 ? first : second;
    ASSERT_EQ(note.performer, expected) << "note " << i;
    ++claimed[score.notes[i].part == 0 ? 0 : 1];
  }
  EXPECT_EQ(claimed[0], claimed[1]) << "Piano II doubles Piano I an octave lower";
  EXPECT_GT(claimed[0], 80u);

  // Over 10 s each pianist's fingertips touch only their own piano's keys, the pitches of
  // their own part.
  ContactRecorder recorder;
  for (int k = 0; k < 300; ++k) {
    const double t = k / 30.0;
    evaluate_stage(*stage, t);
    recorder.record(*stage, t);
  }
  std::set<int> pitches[2];
  for (const music::Note& n : score.notes) pitches[n.part == 0 ? 0 : 1].insert(n.pitch);
  std::size_t spans[2] = {0, 0};
  for (const Contact& contact : recorder.contacts()) {
    const int who = contact.performer == first ? 0 : contact.performer == second ? 1 : -1;
    ASSERT_GE(who, 0);
    const ecs::Entity own_piano = who == 0 ? rig_1.piano : rig_2.piano;
    EXPECT_EQ(stage->instances()[contact.part_instance], own_piano) << "pianist " << who + 1;
    for (const ContactSpan& span : contact.spans) {
      EXPECT_TRUE(pitches[who].count(span.midi)) << "pianist " << who + 1 << " key " << span.midi;
      ++spans[who];
    }
  }
  EXPECT_GT(spans[0], 20u);
  EXPECT_GT(spans[1], 20u);
}

// A pianist and an organist (tests/data/keyboards/piano_and_organ.json): the organ is a model of
// its own with its own manual (C2-C7) and pedalboard (C2-G4). Piano II's bass line goes to the
// feet (the lowest notes below the split), the notes below C2 moved up onto the pedals, and the
// rest to the hands on the manual. Measured from the posed skeleton: every toe holding a pedal
// down is on that pedal's top where a toe presses it, and the pedal is down.
TEST(TwoPianists, APianistAndAnOrganistUsingThePedals) {
  auto scene = scene::load_scene(std::filesystem::path(TUTTI_SOURCE_DIR) / "tests" / "data" /
                                 "keyboards" / "piano_and_organ.json", performance::scene_load_options());
  ASSERT_TRUE(scene) << scene.error().message;
  auto built = performance::build_stage(*scene, {});
  ASSERT_TRUE(built) << built.error().message;
  Stage& stage = **built;
  const ecs::World& world = stage.world();
  const ecs::Entity organist = stage.find_performer("piano", 1);
  ASSERT_FALSE(organist.is_null());
  EXPECT_EQ(world.get<components::Performer>(organist).name, "organist");
  const PianoRig& rig = world.get<PianoRig>(organist);
  EXPECT_EQ(rig.key_nodes[35], -1) << "below the manual";
  EXPECT_GE(rig.key_nodes[36], 0);
  EXPECT_GE(rig.key_nodes[96], 0);
  EXPECT_EQ(rig.key_nodes[97], -1) << "above the manual";
  EXPECT_EQ(rig.pedal_nodes[35], -1);
  EXPECT_GE(rig.pedal_nodes[36], 0);
  EXPECT_GE(rig.pedal_nodes[67], 0);
  EXPECT_EQ(rig.pedal_nodes[68], -1) << "above the pedalboard";
  // The organist's bench and the organ's manual stand on a 130 mm platform, the pedals at the
  // floor: the 460 mm chair's top 520 mm above the pedals' 70 mm tops (AGO: 521 mm).
  EXPECT_NEAR(world.get<PlacedModel>(rig.body).root[3].y, 0.13f, 1e-6f);
  EXPECT_EQ(world.get<PlacedModel>(world.get<PianoRig>(stage.find_performer("piano", 0)).body)
                .root[3].y,
            0.0f);
  EXPECT_NEAR(rig.keyboard_to_world[3].y, 0.72f + 0.13f, 1e-6f) << "the manual raised with it";
  ASSERT_TRUE(rig.feet);
  const piano::FeetPlan& feet = *rig.feet;
  EXPECT_GT(feet.presses.size(), 20u);
  const auto& notes = stage.notes();
  EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& n) {
    return n.find("organist: ") == 0 && n.find(" on the pedals (") != std::string::npos &&
           n.find("moved by octaves onto them") != std::string::npos;
  })) << "Piano II goes down to G1";
  // The pianist has no pedals; the organist's pedal notes are theirs, at the score's onsets.
  EXPECT_FALSE(world.get<PianoRig>(stage.find_performer("piano", 0)).feet);
  for (const piano::PedalPress& press : feet.presses) {
    const auto& note = world.get<components::Note>(stage.note_entity(0, press.note));
    EXPECT_EQ(note.performer, organist);
    EXPECT_EQ(note.onset_s, press.down_s);
    EXPECT_GE(press.key, 36);
    EXPECT_LE(press.key, 67);
  }

  const auto placed_of = [&](ecs::Entity instance) -> const PlacedModel& {
    return world.get<PlacedModel>(instance);
  };
  std::vector<glm::mat4> organ_world, body_world;
  std::size_t toes_checked = 0;
  double worst_mm = 0.0;
  ContactRecorder recorder;
  for (int k = 0; k < 300; ++k) {
    const double t = k / 30.0;
    evaluate_stage(stage, t);
    recorder.record(stage, t);
    const PlacedModel& organ = placed_of(rig.piano);
    const PlacedModel& body = placed_of(rig.body);
    organ_world.resize(organ.asset->nodes.size());
    body_world.resize(body.asset->nodes.size());
    model::compute_world_matrices(*organ.asset, organ.pose, organ.root, organ_world);
    model::compute_world_matrices(*body.asset, body.pose, body.root, body_world);
    for (const piano::PedalPress& press : feet.presses) {
      if (t < press.down_s || t > press.up_s) continue;
      const int toe =
          press.foot == piano::kRightFoot ? rig.body_nodes.toe_right : rig.body_nodes.toe_left;
      ASSERT_GE(toe, 0);
      const int pedal = rig.pedal_nodes[static_cast<std::size_t>(press.key)];
      const double along = piano_model::pedal_is_sharp(press.key)
                               ? piano_model::PedalGeometry::kSharpToe_m
                               : piano_model::PedalGeometry::kNaturalToe_m;
      const glm::vec3 expected = glm::vec3(organ_world[static_cast<std::size_t>(pedal)] *
                                           glm::vec4(0.0f, 0.0f, static_cast<float>(along), 1.0f));
      const glm::vec3 at = glm::vec3(body_world[static_cast<std::size_t>(toe)][3]);
      worst_mm = std::max(worst_mm, 1000.0 * static_cast<double>(glm::distance(at, expected)));
      ++toes_checked;
      // The pedal is down: turned about its hinge by the full travel.
      const glm::quat& r = organ.pose.local[static_cast<std::size_t>(pedal)].rotation;
      EXPECT_NEAR(2.0 * std::asin(std::min(1.0f, glm::length(glm::vec3(r.x, r.y, r.z)))),
                  piano_model::PedalGeometry::kDownRad, 1e-4)
          << "pedal " << press.key << " at " << t;
    }
  }
  EXPECT_GT(toes_checked, 100u);
  EXPECT_LT(worst_mm, 1.0) << "a toe off the pedal it holds down";
  std::size_t key_spans = 0, pedal_spans = 0;
  for (const Contact& contact : recorder.contacts()) {
    if (contact.performer != organist) continue;
    EXPECT_EQ(stage.instances()[contact.part_instance], rig.piano);
    const bool on_pedal = contact.body_node == rig.body_nodes.toe_left ||
                          contact.body_node == rig.body_nodes.toe_right;
    for (const ContactSpan& span : contact.spans) {
      if (on_pedal) {
        EXPECT_TRUE(span.midi >= 36 && span.midi <= 67) << span.midi;
        ++pedal_spans;
      } else {
        EXPECT_TRUE(span.midi >= 36 && span.midi <= 96) << span.midi;
        ++key_spans;
      }
    }
  }
  EXPECT_GT(key_spans, 10u);
  EXPECT_GT(pedal_spans, 5u);
}

// With "sound": "keys" each keyboard is heard through its own touch: the organ's and the
// harpsichord's notes all at their one velocity (no dynamics) and none too slow to sound; the
// piano's velocities follow the fingers' speed.
TEST(TwoPianists, EachKeyboardSoundsWithItsOwnTouch) {
  for (const auto& [instrument, velocity] : {std::pair<std::string, int>{"organ", 100},
                                             {"harpsichord", 80}}) {
    auto scene = scene::load_scene(std::filesystem::path(TUTTI_SOURCE_DIR) / "tests" / "data" /
                                   "keyboards" / "piano_and_organ.json", performance::scene_load_options());
    ASSERT_TRUE(scene) << scene.error().message;
    piano::edit_keyboard_players(*scene)[1].instrument = instrument;
    for (piano::KeyboardPlayer& p : piano::edit_keyboard_players(*scene)) p.sound_from_keys = true;
    auto built = performance::build_stage(*scene, {});
    ASSERT_TRUE(built) << built.error().message;
    const Stage& stage = **built;
    const ecs::Entity pianist = stage.find_performer("piano", 0);
    const ecs::Entity other = stage.find_performer("piano", 1);
    std::set<int> piano_velocities;
    std::size_t heard = 0;
    for (std::size_t i = 0; i < stage.scores().front().notes.size(); ++i) {
      const auto& note = stage.world().get<components::Note>(stage.note_entity(0, i));
      if (note.performer == pianist && !note.silent) piano_velocities.insert(note.velocity);
      if (note.performer != other) continue;
      EXPECT_FALSE(note.silent) << instrument << " note " << i;
      EXPECT_EQ(note.velocity, velocity) << instrument << " note " << i;
      ++heard;
    }
    EXPECT_GT(heard, 80u) << instrument;
    EXPECT_GT(piano_velocities.size(), 1u) << "the piano's dynamics come from the fingers";
  }
}

}  // namespace
}  // namespace tutti::stage
