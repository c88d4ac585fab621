// SPDX-License-Identifier: MIT
// Contacts as measured facts (performance/pose_check.hpp) on the bundled scenes: trumpeters'
// fingertips on the buttons they press, left palms on the casings, no hand in a head or torso,
// fingers inside their joint limits, pianists' pads on the key tops at key bottom and no key left
// hanging. And the checks fail when the hold is wrong: a hold file that puts the right palm on
// the old grip above the buttons leaves the fingertips centimetres away.
#include <tutti/cli/pose_check.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>

#include <tutti/components/note.hpp>
#include <tutti/performance/families.hpp>
#include <tutti/model/model_asset.hpp>
#include <tutti/brass/brass_components.hpp>
#include <glm/glm.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/performance/draft_scene.hpp>
#include <tutti/scene/load_scene.hpp>
#include <tutti/stage/stage.hpp>

#include "scratch_dir.hpp"
#include "testdata.hpp"

namespace tutti::cli {
namespace {

using performance::build_stage;
using performance::draft_scene;

const std::filesystem::path kSource(TUTTI_SOURCE_DIR);

PoseReport check(const char* scene_name, const stage::StageOptions& stage_options = {},
                 double from_s = 0.0, double to_s = 12.0, int fps = 30) {
  auto scene = scene::load_scene(kSource / "content" / "scenes" / scene_name, performance::scene_load_options());
  EXPECT_TRUE(scene) << scene.error().message;
  if (!scene) return {};
  auto staged = build_stage(*scene, stage_options);
  EXPECT_TRUE(staged) << staged.error().message;
  if (!staged) return {};
  PoseCheckOptions options;
  options.from_s = from_s;
  options.to_s = to_s;
  options.fps = fps;
  options.content_dir = stage_options.content_dir;
  auto report = check_pose(**staged, options);
  EXPECT_TRUE(report) << report.error().message;
  return report ? *report : PoseReport{};
}

const PoseMeasure& get(const PoseReport& report, const std::string& name) {
  static const PoseMeasure missing;
  const PoseMeasure* m = report.find(name);
  EXPECT_NE(m, nullptr) << "no measure \"" << name << "\"";
  return m != nullptr ? *m : missing;
}

TEST(PoseCheck, TrumpetersFingertipsRideTheButtonsTheyPress) {
  const PoseReport report = check("quartet.json");
  EXPECT_EQ(report.frames, 360u);
  for (const char* who : {"Trumpet 1", "Trumpet 2"}) {
    const std::string w = who;
    const PoseMeasure& tips = get(report, w + ": pressing fingertip to its button top");
    EXPECT_GT(tips.samples.size(), 50u) << who;  // valves go down in the first 12 s
    EXPECT_LE(tips.percentile(0.95), 10.0) << who;
    EXPECT_LE(tips.worst(), 12.0) << who;
    EXPECT_LE(get(report, w + ": left palm to its grip (grip_left)").worst(), 1.0);
    EXPECT_LE(get(report, w + ": left hand's origin (wrist) to the valve casings' axis").worst(),
              60.0);
  }
  for (const char* who : {"Trombone 1", "Trombone 2"}) {
    // The chest and shoulder turn toward a far slide position and the slide dips (up to 16°); at
    // Trombone 2's farthest (T5, 2-4 s and 5.8-6.4 s) the palm is within 12 mm (README, "Holds and
    // contacts"). Without the turn and the dip it was 172 mm.
    const PoseMeasure& grip = get(report, std::string(who) + ": right palm to its grip (grip_right)");
    EXPECT_EQ(grip.samples.size(), 360u) << who;
    EXPECT_LE(grip.percentile(0.5), 1.0) << who;
    EXPECT_LE(grip.worst(), 20.0) << who;
    // The stand beside the slide: with it straight ahead the slide went 170 mm through its desk as
    // the instrument came up, and 123 mm at Trombone 2's far T5 (6.4 s).
    const PoseMeasure& desk =
        get(report, std::string(who) + ": instrument through the music stand's desk (depth; 0 = clear)");
    EXPECT_EQ(desk.samples.size(), 360u) << who;
    EXPECT_EQ(desk.worst(), 0.0) << who;
  }
  for (const char* who : {"Trumpet 1", "Trumpet 2", "Trombone 1", "Trombone 2"}) {
    const std::string w = who;
    EXPECT_EQ(get(report, w + ": instrument inside an arm's sleeve (depth; 0 = clear)").worst(), 0.0)
        << who;
    if (w.starts_with("Trombone")) {
      EXPECT_LE(get(report, w + ": left palm to its grip (grip_left)").worst(), 1.0) << who;
    }
    EXPECT_EQ(get(report, w + ": hands and fingertips inside the head (depth; 0 = outside)").worst(),
              0.0)
        << who;
    EXPECT_EQ(get(report, w + ": hands, fingertips and elbows inside the torso (depth; 0 = outside)")
                  .worst(),
              0.0)
        << who;
    EXPECT_LE(get(report, w + ": finger joints past their limits (worst joint)").worst(), 0.5)
        << who;
  }
}

// Trombone 2's far T5 (2.5 s and 5.8 s) and back: sampled 240 times a second, the slide arm turns
// under 2500 deg/s and every other joint under 1000. The body turned for the far position only
// while the slide was out (5489 deg/s, the forearm at 3.28 s, as the chest swung back 27 degrees
// in 75 ms) and the elbow whipped straight at full stretch; now the body is set for the slide's
// planned reach, eased (plan_slide_reach), and the arm's last 15 mm of stretch is soft
// (two_bone_ik.hpp).
TEST(PoseCheck, TheTrombonistsArmDoesNotWhipAtTheFarPositions) {
  const PoseReport report = check("quartet.json", {}, 2.0, 7.0, 240);
  const PoseMeasure& arm = get(report, "Trombone 2: slide arm's fastest joint while the slide moves");
  EXPECT_GT(arm.samples.size(), 50u);
  EXPECT_LE(arm.worst(), 2500.0) << arm.worst_at_s << " s, " << arm.worst_of;
  const PoseMeasure& rest = get(report, "Trombone 2: fastest joint's angular speed outside strokes");
  EXPECT_GT(rest.samples.size(), 1000u);
  EXPECT_LE(rest.worst(), 1000.0) << rest.worst_at_s << " s, " << rest.worst_of;
  EXPECT_LE(get(report, "Trombone 2: right palm to its grip (grip_right)").worst(), 20.0);
}

// The trumpeter's valve hand stays where it is while the fingers press the buttons: the hand is
// set on the buttons as they are up, and only the fingers follow them down. It used to turn with
// each press (the right hand at 705 deg/s at 25.0 s, and up to 1404 deg/s on third-party music).
TEST(PoseCheck, TheTrumpetersHandStaysStillWhileTheFingersPress) {
  const PoseReport report = check("quartet.json", {}, 22.0, 30.0);
  for (const char* who : {"Trumpet 1", "Trumpet 2"}) {
    const std::string w = who;
    const PoseMeasure& body = get(report, w + ": fastest joint's angular speed outside strokes");
    EXPECT_LE(body.worst(), 300.0) << who << " " << body.worst_at_s << " s, " << body.worst_of;
    const PoseMeasure& fingers = get(report, w + ": fastest finger joint's angular speed");
    EXPECT_GT(fingers.worst(), 100.0) << who << ": the fingers press";
    EXPECT_LE(fingers.worst(), 2500.0) << who;
    EXPECT_LE(get(report, w + ": pressing fingertip to its button top").percentile(0.95), 10.0)
        << who;
  }
}

// The quintet: trumpets, horn, trombone and tuba, each on its own model, seated; every contact
// the holds ask for, over the whole piece.
TEST(PoseCheck, TheQuintetsPlayersHoldTheirOwnInstruments) {
  const PoseReport report = check("quintet.json", {}, 0.0, 36.3);
  for (const char* who : {"Trumpet 1", "Trumpet 2", "Horn", "Tuba"}) {
    const std::string w = who;
    const PoseMeasure& tips = get(report, w + ": pressing fingertip to its button top");
    EXPECT_GT(tips.samples.size(), 100u) << who;
    EXPECT_LE(tips.percentile(0.95), 10.0) << who;
  }
  EXPECT_LE(get(report, "Horn: right palm to its grip (grip_right)").worst(), 1.0);
  EXPECT_LE(get(report, "Tuba: left palm to its grip (grip_left)").worst(), 1.0);
  EXPECT_LE(get(report, "Trombone: right palm to its grip (grip_right)").worst(), 20.0);
  // The horn's right hand is in its bell: every fingertip's pad inside the wall.
  EXPECT_EQ(get(report, "Horn: right fingertips through the bell's wall or out past its rim").worst(),
            0.0);
  for (const char* who : {"Trumpet 1", "Trumpet 2", "Horn", "Trombone", "Tuba"}) {
    EXPECT_EQ(get(report, std::string(who) + ": instrument inside an arm's sleeve (depth; 0 = clear)")
                  .worst(),
              0.0)
        << who;
  }
  for (const PoseMeasure& m : report.measures) {
    if (m.name.find("inside") != std::string::npos || m.name.find("limits") != std::string::npos) {
      EXPECT_TRUE(m.within_limit()) << m.name << ": " << m.worst();
    }
  }
}

// Every instrument family of content/instruments plays in a bundled scene on its own model: the
// euphonium in low_brass.json.
TEST(PoseCheck, TheEuphoniumPlaysItsButtons) {
  const PoseReport report = check("low_brass.json", {}, 0.0, 12.0);
  const PoseMeasure& tips = get(report, "Euphonium: pressing fingertip to its button top");
  EXPECT_GT(tips.samples.size(), 100u);
  EXPECT_LE(tips.percentile(0.95), 10.0);
  for (const PoseMeasure& m : report.measures) EXPECT_TRUE(m.within_limit()) << m.name;
}

// Between phrases the instrument comes down from the lips (the holds' rest) and goes back up
// before the first note: before the quintet's entrance every mouthpiece is away from its mouth,
// a second into the music every one is at it.
TEST(PoseCheck, InstrumentsComeDownBetweenPhrases) {
  auto scene = scene::load_scene(kSource / "content" / "scenes" / "quintet.json", performance::scene_load_options());
  ASSERT_TRUE(scene) << scene.error().message;
  auto staged = build_stage(*scene, {});
  ASSERT_TRUE(staged) << staged.error().message;
  stage::Stage& stage = **staged;
  const auto mouthpiece_to_mouth = [&](ecs::Entity performer) {
    const auto& rig = stage.world().get<brass::BrassRig>(performer);
    const auto& horn = stage.world().get<stage::PlacedModel>(rig.horn);
    const auto& body = stage.world().get<stage::PlacedModel>(rig.body);
    std::vector<glm::mat4> horn_world(horn.asset->nodes.size()), body_world(body.asset->nodes.size());
    model::compute_world_matrices(*horn.asset, horn.pose, horn.root, horn_world);
    model::compute_world_matrices(*body.asset, body.pose, body.root, body_world);
    return glm::distance(glm::vec3(horn_world[static_cast<std::size_t>(rig.mouthpiece)][3]),
                         glm::vec3(body_world[static_cast<std::size_t>(rig.body_nodes.mouth)][3]));
  };
  std::size_t players = 0;
  for (const double t : {-2.4, 1.0}) {
    stage.run({t, 1.0 / 30});
    for (ecs::Entity performer : stage.performers()) {
      if (stage.world().try_get<brass::BrassRig>(performer) == nullptr) continue;
      const float distance = mouthpiece_to_mouth(performer);
      if (t < 0) {
        EXPECT_GT(distance, 0.1f) << "at rest, t = " << t;
        ++players;
      } else {
        EXPECT_LT(distance, 0.01f) << "playing, t = " << t;
      }
    }
  }
  EXPECT_EQ(players, 5u);
}

TEST(PoseCheck, PianistsPadsMeetTheKeyTopsAndNoKeyIsLeftHanging) {
  for (const char* scene : {"piano.json", "piano_beginner.json"}) {
    const PoseReport report = check(scene);
    const PoseMeasure& pads =
        get(report, "pianist: pressing fingertip's pad above its key's top at key bottom");
    EXPECT_GT(pads.samples.size(), 100u) << scene;
    EXPECT_LE(pads.worst(), 3.0) << scene;
    EXPECT_GE(pads.percentile(0.0), -3.0) << scene;
    // The thumb strikes with the side of its tip: its pad too (finger_motion.json's pad_drop_mm).
    const PoseMeasure& thumb =
        get(report, "pianist: thumb's pad above its key's top at key bottom");
    EXPECT_GT(thumb.samples.size(), 50u) << scene;
    EXPECT_TRUE(thumb.within_limit()) << scene << ": " << thumb.percentile(0.0) << " .. "
                                      << thumb.worst();
    EXPECT_LE(get(report, "pianist: keys half down (25-75 %), no note sounding, of all keys' seconds")
                  .worst(),
              1.0)
        << scene;
    EXPECT_LE(get(report, "pianist: ... of them outside the keys' strokes (a key left hanging)")
                  .worst(),
              1.0)
        << scene;
    EXPECT_EQ(get(report, "pianist: hands and fingertips inside the head (depth; 0 = outside)")
                  .worst(),
              0.0);
  }
}

// A third-party piece staged as `tutti scene new` drafts it, checked over [from_s, to_s).
// A third-party piece staged as `scene new` drafts it; null (and a failure) when it cannot be.
std::unique_ptr<stage::Stage> stage_piece(const std::string& relative,
                                          const stage::StageOptions& stage_options = {}) {
  const std::filesystem::path file = test::testdata(relative);
  auto score = music::load_score(file);
  EXPECT_TRUE(score) << score.error().message;
  if (!score) return nullptr;
  auto drafted = draft_scene(*score, file);
  EXPECT_TRUE(drafted) << drafted.error().message;
  if (!drafted) return nullptr;
  auto scene = scene::parse_scene(nlohmann::json::parse(drafted->document.dump()), "draft.json",
                                  file.parent_path(), performance::scene_load_options());
  EXPECT_TRUE(scene) << scene.error().message;
  if (!scene) return nullptr;
  auto staged = build_stage(*scene, stage_options);
  EXPECT_TRUE(staged) << staged.error().message;
  if (!staged) return nullptr;
  return std::move(*staged);
}

PoseReport check_piece(const std::string& relative, double from_s, double to_s,
                       const stage::StageOptions& stage_options = {}) {
  auto staged = stage_piece(relative, stage_options);
  if (!staged) return {};
  PoseCheckOptions options;
  options.from_s = from_s;
  options.to_s = to_s;
  auto report = check_pose(*staged, options);
  EXPECT_TRUE(report) << report.error().message;
  return report ? *report : PoseReport{};
}

// Chopin's Polonaise Op. 1 No. 3 at 23 s: the left hand's A2-E3-C#4, a tenth the default hand
// cannot span, is rolled (chord_roll.hpp): C#4 is heard 80 ms late, its written end kept, and
// no note is heard before it is written. The thumb's pad lands on C#4: 1.1 mm from its edge as it
// strikes, the hand just arrived (it was 9.9 mm beside it).
TEST(PoseCheck, APolonaisesTenthIsRolledHeardAsStruckWithThePadsOnTheKeys) {
  TUTTI_REQUIRE_TESTDATA();
  auto staged = stage_piece("musicxml/music21/polonaise_op1n3.mxl");
  ASSERT_TRUE(staged);
  int later = 0, earlier = 0;
  const components::Note* rolled_top = nullptr;
  staged->world().view<const components::Note>().each(
      [&](ecs::Entity, const components::Note& note) {
        if (note.performer.is_null()) return;
        if (note.onset_s > note.written_onset_s + 1e-9) ++later;
        if (note.onset_s < note.written_onset_s - 1e-9) ++earlier;
        if (note.pitch == 61 && std::abs(note.written_onset_s - 23.0) < 1e-3 &&
            note.hand == components::HandSide::left) {
          rolled_top = &note;
        }
      });
  EXPECT_GT(later, 0);
  EXPECT_EQ(earlier, 0);
  ASSERT_NE(rolled_top, nullptr);
  EXPECT_NEAR(rolled_top->onset_s, 23.08, 2e-3);
  EXPECT_DOUBLE_EQ(rolled_top->offset_s, rolled_top->written_offset_s);
  PoseCheckOptions options;
  options.from_s = 22.9;
  options.to_s = 23.3;
  auto report = check_pose(*staged, options);
  ASSERT_TRUE(report) << report.error().message;
  EXPECT_LE(get(*report, "pianist: pressing pad off its key's top (0 = on it)").worst(), 1.5);
}

// Hands never pass through each other: the bundled pieces keep them apart, and so do true
// crossings, one hand lifted over the other (systems/finger_motion/pass_over.hpp). Clara
// Schumann's Polonaise op. 1 no. 3 writes the right hand's staff under the left's at 64.5 s: the
// right hand leaps from A5 over the left hand's chord to F2-G2-C#3 beside its A2-G3. With the
// lift switched off (content's "pass_over": {"lift_mm": 0}) the measure shows the right hand
// passing through the left; with it, the hands are apart. Each pressing pad lies on its key's
// top.
// Two pianists at two pianos: each is measured on their own (their pads on their own keys, their
// keys, their hands), and every limit holds for both.
TEST(PoseCheck, TwoPianistsAreMeasuredEachOnTheirOwn) {
  const PoseReport report = check("piano_duo.json");
  for (const std::string who : {"pianist", "pianist 2"}) {
    const PoseMeasure& pads =
        get(report, who + ": pressing fingertip's pad above its key's top at key bottom");
    EXPECT_GT(pads.samples.size(), 100u) << who;
    EXPECT_TRUE(pads.within_limit()) << who;
    EXPECT_TRUE(get(report, who + ": pressing pad off its key's top (0 = on it)").within_limit())
        << who;
    const PoseMeasure& apart = get(report, who + ": one hand inside the other (depth; 0 = apart)");
    EXPECT_GT(apart.samples.size(), 300u) << who;
    EXPECT_EQ(apart.worst(), 0.0) << who;
    const PoseMeasure& keys =
        get(report, who + ": keys half down (25-75 %), no note sounding, of all keys' seconds");
    EXPECT_EQ(keys.samples.size(), 1u) << who;
    EXPECT_TRUE(keys.within_limit()) << who;
  }
  for (const PoseMeasure& m : report.measures) EXPECT_TRUE(m.within_limit()) << m.name;
}

TEST(PoseCheck, OneHandInsideTheOtherIsMeasured) {
  for (const char* scene : {"piano.json", "piano_beginner.json"}) {
    const PoseReport report = check(scene);
    const PoseMeasure& apart = get(report, "pianist: one hand inside the other (depth; 0 = apart)");
    EXPECT_GT(apart.samples.size(), 300u) << scene;
    EXPECT_EQ(apart.worst(), 0.0) << scene << " at " << apart.worst_at_s << " s: " << apart.worst_of;
    EXPECT_TRUE(get(report, "pianist: pressing pad off its key's top (0 = on it)").within_limit())
        << scene;
  }
  TUTTI_REQUIRE_TESTDATA();
  const test::ScratchDir scratch;
  const std::filesystem::path content = scratch.path() / "content";
  std::filesystem::copy(kSource / "content", content, std::filesystem::copy_options::recursive);
  {
    const std::filesystem::path file = content / "piano" / "finger_motion.json";
    nlohmann::json params = nlohmann::json::parse(std::ifstream(file));
    params["pass_over"]["lift_mm"] = 0.0;
    std::ofstream(file) << params.dump(2);
  }
  for (const bool lifted : {false, true}) {
    stage::StageOptions options;
    if (!lifted) options.content_dir = content;
    const PoseReport report =
        check_piece("musicxml/music21/polonaise_op1n3.mxl", 64.0, 65.0, options);
    const PoseMeasure& apart = get(report, "pianist: one hand inside the other (depth; 0 = apart)");
    if (lifted) {
      EXPECT_EQ(apart.worst(), 0.0) << apart.worst_at_s << " s: " << apart.worst_of;
      for (const char* on_key : {"pianist: pressing pad off its key's top (0 = on it)",
                                 "pianist: pressing fingertip's pad above its key's top at key bottom",
                                 "pianist: fastest joint's angular speed outside strokes"}) {
        EXPECT_TRUE(get(report, on_key).within_limit()) << on_key;
      }
    } else {
      EXPECT_GT(apart.worst(), 5.0);
      EXPECT_NE(apart.worst_of.find("right "), std::string::npos) << apart.worst_of;
      EXPECT_NE(apart.worst_of.find(" in left "), std::string::npos) << apart.worst_of;
    }
  }
}

// The right hand crosses over the left and back in the Polonaise op. 1 no. 4 (15.0-16.1 s: it
// leaps from C#5 to C#3 and C#2 under the left hand's held C#4-E4-G4, then back to D5), and in
// no. 3 it holds D3 under the left hand's chords (2.0-2.75 s). It is lifted over the left hand,
// its fingers reaching down to their keys: 17.5 and 20.5 mm into it before.
TEST(PoseCheck, AHandCrossingTheOtherPassesOverIt) {
  TUTTI_REQUIRE_TESTDATA();
  for (const auto& [piece, from_s, to_s] :
       {std::tuple{"musicxml/music21/polonaise_op1n4.mxl", 14.9, 16.3},
        std::tuple{"musicxml/music21/polonaise_op1n3.mxl", 1.8, 2.9}}) {
    const PoseReport report = check_piece(piece, from_s, to_s);
    const PoseMeasure& apart = get(report, "pianist: one hand inside the other (depth; 0 = apart)");
    EXPECT_GT(apart.samples.size(), 30u) << piece;
    EXPECT_EQ(apart.worst(), 0.0) << piece << " " << apart.worst_at_s << " s: " << apart.worst_of;
    for (const char* limit : {"pianist: pressing pad off its key's top (0 = on it)",
                              "pianist: pressing fingertip's pad above its key's top at key bottom",
                              "pianist: fastest finger joint's angular speed",
                              "pianist: fastest joint's angular speed outside strokes"}) {
      const PoseMeasure& measure = get(report, limit);
      EXPECT_TRUE(measure.within_limit())
          << piece << " " << limit << ": " << measure.worst() << " at " << measure.worst_at_s;
    }
  }
}

// A finger that presses nothing gives way to the other hand: in Bach's Prelude in C (BWV 846)
// at 200.57 s the right thumb strikes C4 where the left thumb, idle beside the left hand's B3,
// hung (5.6 mm into it before the yield).
TEST(PoseCheck, AnIdleFingerGivesWayToTheOtherHand) {
  TUTTI_REQUIRE_TESTDATA();
  const PoseReport report = check_piece("midi/tonejs/bach_846.mid", 200.3, 200.9);
  const PoseMeasure& apart = get(report, "pianist: one hand inside the other (depth; 0 = apart)");
  EXPECT_GT(apart.samples.size(), 10u);
  EXPECT_EQ(apart.worst(), 0.0) << apart.worst_at_s << " s: " << apart.worst_of;
  EXPECT_TRUE(get(report, "pianist: fastest finger joint's angular speed").within_limit());
}

// A pressing finger in the other hand's way moves its pad along its key's top: in Scarlatti's
// K. 27 at 50.23 s the left thumb presses C#4 beside the right thumb on D4 (2.3 mm into it
// before). The pads stay on their keys.
TEST(PoseCheck, PressingFingersOfBothHandsOnNeighbouringKeysKeepApart) {
  TUTTI_REQUIRE_TESTDATA();
  const PoseReport report = check_piece("musicxml/pianoplayer/scarlatti_k027.xml", 50.0, 50.5);
  const PoseMeasure& apart = get(report, "pianist: one hand inside the other (depth; 0 = apart)");
  EXPECT_GT(apart.samples.size(), 10u);
  EXPECT_EQ(apart.worst(), 0.0) << apart.worst_at_s << " s: " << apart.worst_of;
  for (const char* on_key : {"pianist: pressing pad off its key's top (0 = on it)",
                             "pianist: thumb's pad above its key's top at key bottom",
                             "pianist: pressing fingertip's pad above its key's top at key bottom"}) {
    const PoseMeasure& measure = get(report, on_key);
    EXPECT_FALSE(measure.samples.empty()) << on_key;
    EXPECT_TRUE(measure.within_limit()) << on_key << ": " << measure.worst() << " at "
                                        << measure.worst_at_s << " s";
  }
}

// A key is let go before the other hand strikes beside it: in Mozart's K. 545 at 142.13 s the
// right thumb strikes C4 as the left thumb lets D4 go (2.5 mm into it while it rose), and in
// the Maple Leaf Rag at 10.27 s the right thumb takes G#4 as the left hand lets its chord go
// (7.3 mm).
TEST(PoseCheck, AKeyIsLetGoBeforeTheOtherHandStrikesBesideIt) {
  TUTTI_REQUIRE_TESTDATA();
  // The rag is one of the pieces tests/data/pieces/ adds (an absolute path: testdata() keeps it).
  const std::string rag = (kSource / "tests/data/pieces/joplin_maple_leaf_rag.mid").string();
  for (const auto& [piece, from_s, to_s] :
       {std::tuple{std::string("musicxml/pianoplayer/mozart_sonfacile.mxl"), 141.9, 142.4},
        std::tuple{rag, 10.0, 10.5}}) {
    const PoseReport report = check_piece(piece, from_s, to_s);
    const PoseMeasure& apart = get(report, "pianist: one hand inside the other (depth; 0 = apart)");
    EXPECT_GT(apart.samples.size(), 10u) << piece;
    EXPECT_EQ(apart.worst(), 0.0) << piece << " " << apart.worst_at_s << " s: " << apart.worst_of;
    EXPECT_TRUE(get(report, "pianist: pressing pad off its key's top (0 = on it)").within_limit())
        << piece;
  }
}

// Every joint's angular speed from frame to frame, the fastest reported with its joint's name and
// bound: outside strokes 1000 deg/s, fingers 2500, the slide arm while the slide moves 2000 (and
// only then: Trumpet 1 has no slide).
TEST(PoseCheck, TheFastestJointIsNamedAndBound) {
  const PoseReport report = check("quartet.json", {}, 5.6, 6.0);
  const PoseMeasure& trombone = get(report, "Trombone 2: slide arm's fastest joint while the slide moves");
  EXPECT_GT(trombone.samples.size(), 1u);
  EXPECT_EQ(trombone.worst_of, "forearm_r");
  EXPECT_EQ(trombone.limit, 2000.0);
  const PoseMeasure& trumpet = get(report, "Trumpet 1: fastest joint's angular speed outside strokes");
  EXPECT_GT(trumpet.samples.size(), 5u);
  EXPECT_GE(trumpet.percentile(0.0), 0.0);
  EXPECT_EQ(trumpet.limit, 1000.0);
  EXPECT_EQ(get(report, "Trumpet 1: fastest finger joint's angular speed").limit, 2500.0);
  EXPECT_EQ(report.find("Trumpet 1: slide arm's fastest joint while the slide moves"), nullptr);
}

// The same quartet with a hold that puts the right palm on the model's old grip, above and right
// of the buttons, instead of the fingertips on them: the check sees the fingers miss.
TEST(PoseCheck, AHoldWithoutFingertipsOnTheButtonsFails) {
  test::ScratchDir dir;
  const std::filesystem::path content = dir.path() / "content";
  std::filesystem::copy(kSource / "content", content, std::filesystem::copy_options::recursive);
  const std::filesystem::path hold = content / "instruments" / "holds" / "trumpet.json";
  std::stringstream text;
  text << std::ifstream(hold).rdbuf();
  std::string json = text.str();
  const std::string from = "\"fingertips_on\"";
  const auto at = json.find(from);
  ASSERT_NE(at, std::string::npos);
  const auto end = json.find('}', at);
  json.replace(at, end + 1 - at, "\"palm_at\": \"grip_right\"");
  std::ofstream(hold, std::ios::trunc) << json;

  stage::StageOptions options;
  options.content_dir = content;
  const PoseReport report = check("quartet.json", options);
  const PoseMeasure& tips = get(report, "Trumpet 1: pressing fingertip to its button top");
  EXPECT_GT(tips.percentile(0.95), 20.0);
  EXPECT_FALSE(tips.within_limit());
}

// A hold file edited in a copy of the content: `edit` changes its text.
stage::StageOptions with_hold(const test::ScratchDir& dir, const char* model,
                              const std::string& from, const std::string& to) {
  const std::filesystem::path content = dir.path() / "content";
  std::filesystem::copy(kSource / "content", content, std::filesystem::copy_options::recursive);
  const std::filesystem::path hold = content / "instruments" / "holds" / (std::string(model) + ".json");
  std::stringstream text;
  text << std::ifstream(hold).rdbuf();
  std::string json = text.str();
  const auto at = json.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) json.replace(at, from.size(), to);
  std::ofstream(hold, std::ios::trunc) << json;
  stage::StageOptions options;
  options.content_dir = content;
  return options;
}

// The horn's thumb left spread at the rig's rest (no thumb_adduct_deg): it leaves the bell through
// its wall, and the check says so.
TEST(PoseCheck, AHornThumbOutsideTheBellFails) {
  test::ScratchDir dir;
  const PoseReport report = check("quintet.json",
                                  with_hold(dir, "horn", "\"thumb_adduct_deg\": 60.0", "\"thumb_adduct_deg\": 0.0"),
                                  2.0, 4.0);
  const PoseMeasure& bell =
      get(report, "Horn: right fingertips through the bell's wall or out past its rim");
  EXPECT_GT(bell.worst(), 20.0);
  EXPECT_FALSE(bell.within_limit());
}

// The trombone's left elbow out to the side like the right one (no own "elbow"): the forearm's
// sleeve runs through the bell section's tube.
TEST(PoseCheck, ATromboneLeftElbowOutPutsTheTubeThroughTheSleeve) {
  test::ScratchDir dir;
  const PoseReport report =
      check("quartet.json",
            with_hold(dir, "trombone", "\"elbow\": {\"down\": 1.0, \"out\": -0.2, \"back\": -0.5},", ""));
  const PoseMeasure& sleeve =
      get(report, "Trombone 1: instrument inside an arm's sleeve (depth; 0 = clear)");
  EXPECT_GT(sleeve.worst(), 3.0);
  EXPECT_FALSE(sleeve.within_limit());
}

// The trombonist's stand straight ahead at 0.75 m, where the trumpeters' stands are: the slide
// goes through its desk as the trombone comes up (about 170 mm in), and the check says so.
TEST(PoseCheck, ATromboneStandStraightAheadPutsTheSlideThroughItsDesk) {
  test::ScratchDir dir;
  const PoseReport report =
      check("quartet.json",
            with_hold(dir, "trombone", "\"music_stand\": {\"forward_m\": 0.9, \"left_m\": 0.35}",
                      "\"music_stand\": {\"forward_m\": 0.75, \"left_m\": 0.0}"),
            -2.5, 0.0);
  const PoseMeasure& desk =
      get(report, "Trombone 1: instrument through the music stand's desk (depth; 0 = clear)");
  EXPECT_GT(desk.worst(), 50.0);
  EXPECT_FALSE(desk.within_limit());
  EXPECT_EQ(desk.worst_of, "slide");
}

TEST(PoseCheck, AnEmptyRangeIsAnError) {
  auto scene = scene::load_scene(kSource / "content" / "scenes" / "quartet.json", performance::scene_load_options());
  ASSERT_TRUE(scene);
  auto staged = build_stage(*scene, {});
  ASSERT_TRUE(staged);
  PoseCheckOptions options;
  options.from_s = 3.0;
  options.to_s = 3.0;
  EXPECT_FALSE(check_pose(**staged, options));
  options.to_s = 4.0;
  options.fps = 0;
  EXPECT_FALSE(check_pose(**staged, options));
}

}  // namespace
}  // namespace tutti::cli
