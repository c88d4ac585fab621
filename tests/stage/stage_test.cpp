// SPDX-License-Identifier: MIT
// The stage: the shipped scenes build; the pose at t is a pure function of t; pressed keys and
// valves move their nodes; a user's own instrument model, through a mapping file with other node
// names and centimetre units, moves exactly like the generated one.
#include <tutti/stage/stage.hpp>

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <tutti/brass/brass_players.hpp>
#include <tutti/brass_motion/brass_pose_system.hpp>
#include <tutti/components/body_motion.hpp>
#include <tutti/components/finger.hpp>
#include <tutti/components/valve.hpp>
#include <tutti/ensemble_variation/ensemble_plan.hpp>
#include <tutti/ensemble_variation/ensemble_variation_system.hpp>
#include <tutti/brass/brass_components.hpp>
#include <tutti/performance/families.hpp>
#include <tutti/piano/keyboard_players.hpp>
#include <tutti/piano/piano_components.hpp>
#include <tutti/scene/load_scene.hpp>
#include "testdata.hpp"

namespace tutti::stage {
namespace {

using brass::BrassRig;
using piano::PianistPlan;
using piano::PianoRig;

Result<std::unique_ptr<Stage>> build_stage(const scene::Scene& scene, const StageOptions& options) {
  return performance::build_stage(scene, options);
}

// The families' components on their performers.
ecs::Entity brass_player(const Stage& stage, std::size_t seat) {
  return stage.find_performer("brass", seat);
}
const BrassRig& brass_rig(const Stage& stage, std::size_t seat) {
  return stage.world().get<BrassRig>(brass_player(stage, seat));
}
ecs::Entity pianist(const Stage& stage) { return stage.find_performer("piano", 0); }
const PianoRig& piano_rig(const Stage& stage) { return stage.world().get<PianoRig>(pianist(stage)); }
const PianistPlan& pianist_plan(const Stage& stage) {
  return stage.world().get<PianistPlan>(pianist(stage));
}
const ensemble_variation::EnsemblePlan* ensemble_of(const Stage& stage) {
  const auto* handle =
      stage.world().try_get<ensemble_variation::EnsembleMotionHandle>(brass_player(stage, 0));
  return handle != nullptr ? handle->plan.get() : nullptr;
}
const PlacedModel& placed(const Stage& stage, ecs::Entity instance) {
  return stage.world().get<PlacedModel>(instance);
}

std::unique_ptr<Stage> build(const std::filesystem::path& scene_file) {
  auto scene = scene::load_scene(scene_file, performance::scene_load_options());
  EXPECT_TRUE(scene) << scene.error().message;
  if (!scene) return nullptr;
  auto stage = build_stage(*scene, {});
  EXPECT_TRUE(stage) << stage.error().message;
  return stage ? std::move(*stage) : nullptr;
}

std::vector<std::vector<model::NodeTransform>> poses(const Stage& stage) {
  std::vector<std::vector<model::NodeTransform>> out;
  for (std::size_t i = 0; i < stage.instances().size(); ++i) {
    out.push_back(stage.placed(i).pose.local);
  }
  return out;
}

bool same(const std::vector<std::vector<model::NodeTransform>>& a,
          const std::vector<std::vector<model::NodeTransform>>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t n = 0; n < a[i].size(); ++n) {
      if (a[i][n].translation != b[i][n].translation || a[i][n].rotation != b[i][n].rotation) {
        return false;
      }
    }
  }
  return true;
}

glm::vec3 node_world(const Stage& stage, ecs::Entity instance, int node) {
  const PlacedModel& p = placed(stage, instance);
  const model::ModelAsset& asset = *p.asset;
  std::vector<glm::mat4> world(asset.nodes.size());
  model::compute_world_matrices(asset, p.pose, p.root, world);
  return glm::vec3(world[static_cast<std::size_t>(node)][3]);
}

TEST(Stage, PoseAtTIsAPureFunctionOfT) {
  for (const char* name : {"piano.json", "quartet.json"}) {
    auto stage = build(tutti::test::source_dir() / "content" / "scenes" / name);
    ASSERT_TRUE(stage);
    evaluate_stage(*stage, 7.25);
    const auto first = poses(*stage);
    int moved = 0;
    for (double t = 0.0; t < 30.0; t += 0.5) {
      evaluate_stage(*stage, t);
      moved += same(first, poses(*stage)) ? 0 : 1;
    }
    evaluate_stage(*stage, 7.25);
    EXPECT_TRUE(same(first, poses(*stage))) << name;
    EXPECT_GT(moved, 40) << name << ": the pose barely changes over 30 s";
  }
}

TEST(Stage, TheQuartetsLeadCuesAndEveryPlayerMovesInTheirOwnWay) {
  auto stage = build(tutti::test::source_dir() / "content" / "scenes" / "quartet.json");
  ASSERT_TRUE(stage);
  const ensemble_variation::EnsemblePlan* plan = ensemble_of(*stage);
  ASSERT_TRUE(plan);
  ASSERT_EQ(plan->performers.size(), 4u);
  EXPECT_EQ(plan->lead, 0);  // "Trumpet 1 leads"
  // No cue list in the scene: one cue, at the first entrance.
  ASSERT_EQ(plan->performers[0].cues.size(), 1u);
  const ensemble_variation::CueMotion& cue = plan->performers[0].cues.front();
  EXPECT_NEAR(cue.dip_s, plan->entrance_s, 1e-9);
  // The lead's bell at the top of the cue, in the rendered pose: the generated trumpet's bell
  // points along its -Z, which rises in the world as the bell lifts.
  const BrassRig& lead = brass_rig(*stage, 0);
  const auto bell_rise = [&](double t) {
    evaluate_stage(*stage, t);
    return (placed(*stage, lead.horn).root * glm::vec4(0, 0, -1, 0)).y;
  };
  const float before = bell_rise(cue.start_s - 0.01);
  const float lifted = bell_rise(cue.lift_s);
  EXPECT_GT(lifted - before, 0.1f) << "bell direction y " << before << " -> " << lifted;
  std::printf("quartet: first entrance %.3f s, the lead's cue %.3f .. %.3f s\n",
              plan->entrance_s, cue.start_s, cue.end_s);
  // Over the piece the four bodies move differently: their hips and spines differ.
  int differing = 0;
  for (double t = 5.0; t < 35.0; t += 1.0) {
    evaluate_stage(*stage, t);
    const auto* a = stage->world().try_get<components::BodyMotion>(brass_player(*stage, 0));
    const auto* b = stage->world().try_get<components::BodyMotion>(brass_player(*stage, 1));
    ASSERT_TRUE(a && b);
    differing += std::abs(a->sway_rad - b->sway_rad) > 0.005f ? 1 : 0;
  }
  EXPECT_GT(differing, 15);
}

// What is heard is what is played: a note cut short for a catch breath ends early in
// Stage::heard_scores, exactly where that player's breath starts; nothing else changes.
TEST(Stage, TheSoundStopsWhereAPlayerTakesACatchBreath) {
  auto stage = build(tutti::test::source_dir() / "content" / "scenes" / "quartet.json");
  ASSERT_TRUE(stage);
  const std::vector<music::Score> heard_scores = stage->heard_scores();
  ASSERT_EQ(heard_scores.size(), stage->scores().size());
  const music::Score& written = stage->scores().front();
  const music::Score& heard = heard_scores.front();
  ASSERT_EQ(heard.notes.size(), written.notes.size());
  std::vector<double> breath_starts;
  for (std::size_t seat = 0; seat < 4; ++seat) {
    const auto& player =
        stage->world().get<brass_motion::BrassPlayerMotionHandle>(brass_player(*stage, seat));
    for (const brass_motion::BreathEvent& e : player.motion->breaths.events) {
      breath_starts.push_back(e.start_s);
    }
  }
  std::size_t shortened = 0;
  for (std::size_t i = 0; i < heard.notes.size(); ++i) {
    EXPECT_EQ(heard.notes[i].onset_s, written.notes[i].onset_s);
    EXPECT_LE(heard.notes[i].offset_s, written.notes[i].offset_s);
    if (heard.notes[i].offset_s == written.notes[i].offset_s) continue;
    ++shortened;
    const bool at_a_breath =
        std::any_of(breath_starts.begin(), breath_starts.end(),
                    [&](double start) { return std::abs(start - heard.notes[i].offset_s) < 1e-9; });
    EXPECT_TRUE(at_a_breath) << "note " << i << " ends at " << heard.notes[i].offset_s;
  }
  EXPECT_GE(shortened, 4u) << "the quartet's players take catch breaths";
}

TEST(Stage, PressedKeysTurnTheirNodes) {
  auto stage = build(tutti::test::source_dir() / "content" / "scenes" / "piano.json");
  ASSERT_TRUE(stage && !pianist(*stage).is_null());
  const PianoRig& seat = piano_rig(*stage);
  int pressed_frames = 0;
  for (double t = 0.0; t < 12.0; t += 1.0 / 30) {
    evaluate_stage(*stage, t);
    for (const auto& hand : seat.fingers) {
      for (ecs::Entity e : hand) {
        const auto& finger = stage->world().get<components::Finger>(e);
        if (finger.key < 0 || finger.press_depth < 1.0) continue;
        ++pressed_frames;
        const int node = seat.key_nodes[static_cast<std::size_t>(finger.key)];
        ASSERT_GE(node, 0);
        const glm::quat r =
            placed(*stage, seat.piano).pose.local[static_cast<std::size_t>(node)].rotation;
        const float angle = 2.0f * std::acos(std::min(1.0f, std::abs(r.w)));
        EXPECT_NEAR(angle, seat.key_dip_rad[static_cast<std::size_t>(finger.key)], 1e-4) << t;
      }
    }
  }
  EXPECT_GT(pressed_frames, 100);
}

// A finger pinned in the scene (the editor's pin) is the finger that plays the note, and the
// fingers around it are re-planned to fit.
TEST(Stage, APinnedFingerPlaysItsNote) {
  auto scene = scene::load_scene(tutti::test::source_dir() / "content" / "scenes" / "piano.json",
                                 performance::scene_load_options());
  ASSERT_TRUE(scene) << scene.error().message;
  auto plain = build_stage(*scene, {});
  ASSERT_TRUE(plain) << plain.error().message;
  const PianistPlan& before = pianist_plan(**plain);
  // The 10th note, pinned to a finger the planner did not choose.
  const std::size_t i = 9;
  const music::Note note = before.score.notes[i];
  const int planned = before.fingering.fingers[i];
  ASSERT_GE(planned, 1);
  const int pinned = planned == 1 ? 2 : 1;
  piano::edit_keyboard_players(*scene).front().pins.push_back(
      piano::FingerPin{note.onset_s, note.pitch, pinned});
  auto stage = build_stage(*scene, {});
  ASSERT_TRUE(stage) << stage.error().message;
  const PianistPlan& seat = pianist_plan(**stage);
  EXPECT_EQ(seat.fingering.fingers[i], pinned);
  // That finger is on the note's key, pressed, just after its onset.
  const std::size_t side = seat.fingering.hands[i] == music::Hand::left ? 1 : 0;
  evaluate_stage(**stage, note.onset_s + 0.01);
  const auto& finger = (*stage)->world().get<components::Finger>(
      piano_rig(**stage).fingers[side][static_cast<std::size_t>(pinned - 1)]);
  EXPECT_EQ(finger.key, note.pitch);
  EXPECT_GT(finger.press_depth, 0.9);

  piano::edit_keyboard_players(*scene).front().pins.back().key =
      note.pitch + 1;  // a note that is not there
  auto wrong = build_stage(*scene, {});
  ASSERT_FALSE(wrong);
  EXPECT_NE(wrong.error().message.find("piano.json: /pianist/pins/0: no note of key " +
                                       std::to_string(note.pitch + 1) + " starts at"),
            std::string::npos)
      << wrong.error().message;
}

// "sound": "keys": the piano is heard as the simulated keys sound it, in the scene's style.
TEST(Stage, ThePianoSoundsAsItsKeysArePressed) {
  auto scene = scene::load_scene(tutti::test::source_dir() / "content" / "scenes" / "piano.json",
                                 performance::scene_load_options());
  ASSERT_TRUE(scene) << scene.error().message;
  auto written = build_stage(*scene, {});
  ASSERT_TRUE(written) << written.error().message;
  EXPECT_FALSE(pianist_plan(**written).played) << "no style: no key simulation";
  ASSERT_EQ((*written)->heard_scores()[0].notes.size(), (*written)->scores()[0].notes.size());

  piano::edit_keyboard_players(*scene).front().style = "beginner";
  piano::edit_keyboard_players(*scene).front().sound_from_keys = true;
  auto stage = build_stage(*scene, {});
  ASSERT_TRUE(stage) << stage.error().message;
  const PianistPlan& seat = pianist_plan(**stage);
  ASSERT_TRUE(seat.played);
  ASSERT_EQ(seat.played->size(), seat.score.notes.size());
  const music::Score heard = (*stage)->heard_scores()[0];
  EXPECT_EQ(heard.notes.size(), seat.performance.sounded);
  // Every heard piano note is one the keys sounded, at the time and velocity they sounded it.
  std::size_t moved = 0;
  std::size_t j = 0;
  for (std::size_t i = 0; i < seat.score.notes.size(); ++i) {
    const key_action::PlayedNote& p = (*seat.played)[i];
    if (p.outcome != key_action::KeyOutcome::sounded) continue;
    ASSERT_LT(j, heard.notes.size());
    EXPECT_EQ(heard.notes[j].onset_s, std::max(p.onset_s, 0.0));
    EXPECT_EQ(heard.notes[j].velocity, p.velocity);
    moved += std::abs(p.onset_s - seat.score.notes[i].onset_s) > 0.005;
    ++j;
  }
  EXPECT_GT(moved, seat.score.notes.size() / 3);
  // The key the finger holds down at the note's sounded time is that note's key.
  for (std::size_t i = 0; i < seat.score.notes.size(); i += 7) {
    const key_action::PlayedNote& p = (*seat.played)[i];
    if (p.outcome != key_action::KeyOutcome::sounded) continue;
    evaluate_stage(**stage, p.onset_s);
    const std::size_t side = seat.fingering.hands[i] == music::Hand::left ? 1 : 0;
    const auto& finger = (*stage)->world().get<components::Finger>(
        piano_rig(**stage).fingers[side][static_cast<std::size_t>(seat.fingering.fingers[i] - 1)]);
    EXPECT_EQ(finger.key, seat.score.notes[i].pitch) << "note " << i;
    EXPECT_GT(finger.press_depth, 0.6) << "note " << i;  // past escapement, short of the bed
    EXPECT_LT(finger.press_depth, 1.0) << "note " << i;
  }
  // Re-planning the same scene shares the performance; another seed plays it anew.
  StageOptions again;
  again.reuse_models = stage->get();
  auto same = build_stage(*scene, again);
  ASSERT_TRUE(same) << same.error().message;
  EXPECT_EQ(pianist_plan(**same).played, seat.played);
  piano::edit_keyboard_players(*scene).front().seed += 1;
  again.reuse_models = same->get();
  auto reseeded = build_stage(*scene, again);
  ASSERT_TRUE(reseeded) << reseeded.error().message;
  EXPECT_NE(pianist_plan(**reseeded).played, seat.played);
}

// The generated trumpet with every node renamed, its root scaled to centimetres: a "user's" model.
std::filesystem::path write_user_trumpet(const std::filesystem::path& dir) {
  tinygltf::TinyGLTF io;
  tinygltf::Model model;
  std::string error;
  std::string warning;
  const std::filesystem::path generated = default_asset_dir() / "trumpet.glb";
  EXPECT_TRUE(io.LoadBinaryFromFile(&model, &error, &warning, generated.string())) << error;
  for (tinygltf::Node& node : model.nodes) {
    if (node.name == "trumpet") node.scale = {100.0, 100.0, 100.0};
    node.name = "User:" + node.name;
  }
  const std::filesystem::path out = dir / "user_trumpet.glb";
  EXPECT_TRUE(io.WriteGltfSceneToFile(&model, out.string(), true, true, false, true));
  return out;
}

TEST(Stage, AUsersInstrumentThroughAMappingMovesLikeTheGeneratedOne) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("tutti-stage-test-" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  write_user_trumpet(dir);
  // The root's scale 100 makes the model 100 times too big in metres: the mapping scales back.
  std::ofstream(dir / "trumpet.mapping.json") << R"({
    "model": "user_trumpet.glb", "kind": "trumpet", "scale": 0.01,
    "nodes": {"valve_1": "User:valve_1", "valve_2": "User:valve_2", "valve_3": "User:valve_3",
              "mouthpiece": "User:mouthpiece", "grip_left": "User:grip_left",
              "grip_right": "User:grip_right"}})";
  const std::string music =
      (tutti::test::source_dir() / "content" / "music" / "quartet.musicxml").string();
  auto write_scene = [&](const std::string& name, const std::string& extra) {
    std::ofstream(dir / name) << R"({"music": ")" << music << R"(",
      "performers": [{"name": "T", "instrument": "trumpet_bb", "part": "Trumpet 1",
                      "position_m": [0, 0, 0])"
                              << extra << R"(}],
      "cameras": [{"name": "c", "position_m": [0, 1.5, 3], "target_m": [0, 1.5, 0]}]})";
  };
  write_scene("generated.json", "");
  write_scene("user.json", R"(, "instrument_model": "trumpet.mapping.json")");
  auto generated = build(dir / "generated.json");
  auto user = build(dir / "user.json");
  ASSERT_TRUE(generated && user);
  const BrassRig& g = brass_rig(*generated, 0);
  const BrassRig& u = brass_rig(*user, 0);
  ASSERT_GE(u.valves[0], 0);
  int pressed = 0;
  for (double t = 3.0; t < 20.0; t += 0.25) {
    evaluate_stage(*generated, t);
    evaluate_stage(*user, t);
    const auto& valve = generated->world().get<components::Valve>(g.instrument);
    pressed += valve.press[0] > 0.5f ? 1 : 0;
    for (std::size_t v = 0; v < 3; ++v) {
      const glm::vec3 a = node_world(*generated, g.horn, g.valves[v]);
      const glm::vec3 b = node_world(*user, u.horn, u.valves[v]);
      ASSERT_LT(glm::length(a - b), 1e-4f) << "valve " << v + 1 << " at " << t;
    }
    ASSERT_LT(glm::length(node_world(*generated, g.horn, g.mouthpiece) -
                          node_world(*user, u.horn, u.mouthpiece)),
              1e-4f);
  }
  EXPECT_GT(pressed, 5) << "the check must see valve 1 down";

  // A mapping naming a node the model does not have.
  std::ofstream(dir / "trumpet.mapping.json") << R"({
    "model": "user_trumpet.glb", "kind": "trumpet",
    "nodes": {"valve_1": "Piston A", "valve_2": "User:valve_2", "valve_3": "User:valve_3",
              "mouthpiece": "User:mouthpiece"}})";
  auto scene = scene::load_scene(dir / "user.json", performance::scene_load_options());
  ASSERT_TRUE(scene) << scene.error().message;
  auto broken = build_stage(*scene, {});
  ASSERT_FALSE(broken);
  EXPECT_EQ(broken.error().message,
            "trumpet.mapping.json: node \"Piston A\" for \"valve_1\" is not in user_trumpet.glb");
  std::filesystem::remove_all(dir);
}

// An expression from the editor reaches the rendered face: inside a strain span the player's
// tension morph shows at least 0.8 x its amount (the face's share of the strain) and the bell
// rises; outside the span the pose is what it was without it.
TEST(Stage, AStrainExpressionTightensTheFace) {
  auto stage = build(tutti::test::source_dir() / "content" / "scenes" / "quartet.json");
  ASSERT_TRUE(stage);
  ASSERT_TRUE(ensemble_of(*stage));
  const BrassRig& seat = brass_rig(*stage, 1);
  ASSERT_FALSE(seat.body.is_null());
  ASSERT_GE(seat.body_nodes.morph_tension, 0);
  const auto tension = [&](double t) {
    evaluate_stage(*stage, t);
    return placed(*stage, seat.body)
        .pose.morph_weights[static_cast<std::size_t>(seat.body_nodes.morph_tension)];
  };
  const auto bell_rise = [&] {  // the generated trumpet's bell points along its -Z
    return (placed(*stage, seat.horn).root * glm::vec4(0, 0, -1, 0)).y;
  };
  const float plain = tension(12.0);
  const float plain_bell = bell_rise();
  evaluate_stage(*stage, 20.0);
  const auto outside = poses(*stage);

  ensemble_variation::EnsemblePlan edited = *ensemble_of(*stage);
  ensemble_variation::ExpressionSpan span;
  span.kind = ensemble_variation::ExpressionKind::strain;
  span.start_s = 10.0;
  span.end_s = 14.0;
  span.amount = 1.0;
  edited.performers[1].expressions = {span};
  auto* handle = stage->world().try_get<ensemble_variation::EnsembleMotionHandle>(brass_player(*stage, 1));
  ASSERT_NE(handle, nullptr);
  handle->plan = std::make_shared<const ensemble_variation::EnsemblePlan>(std::move(edited));
  const float strained = tension(12.0);
  EXPECT_GE(strained, 0.8f - 1e-6f);
  EXPECT_GT(strained, plain) << "the face was already at " << plain;
  EXPECT_GT(bell_rise() - plain_bell, 0.03f);
  evaluate_stage(*stage, 20.0);
  EXPECT_TRUE(same(outside, poses(*stage)));
}

}  // namespace
}  // namespace tutti::stage
