// SPDX-License-Identifier: MIT
// A scene drafted from third-party music alone: which parts are played by whom, where the players
// sit, that the cameras look at them and the cuts follow who plays, and that the document loads
// as a scene with every part found.
#include <tutti/performance/draft_scene.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <set>

#include <tutti/brass/brass_players.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/piano/keyboard_players.hpp>
#include <tutti/scene/load_scene.hpp>
#include <tutti/performance/families.hpp>
#include "testdata.hpp"

namespace tutti::performance {
namespace {

struct Drafted {
  music::Score score;
  DraftedScene draft;
  scene::Scene scene;
};

Drafted draft_of(const std::string& relative) {
  Drafted d;
  const std::filesystem::path file = test::testdata(relative);
  auto score = music::load_score(file);
  EXPECT_TRUE(score) << score.error().message;
  if (!score) return d;
  d.score = std::move(*score);
  auto drafted = draft_scene(d.score, file);
  EXPECT_TRUE(drafted) << drafted.error().message;
  if (!drafted) return d;
  d.draft = std::move(*drafted);
  auto parsed = scene::parse_scene(nlohmann::json::parse(d.draft.document.dump()), "draft.json",
                                   file.parent_path(), performance::scene_load_options());
  EXPECT_TRUE(parsed) << parsed.error().message;
  if (!parsed) return d;
  d.scene = std::move(*parsed);
  const Status parts = scene::check_scene_parts(d.scene, {&d.score, 1});
  EXPECT_TRUE(parts) << parts.error().message;
  return d;
}

std::string joined_notes(const DraftedScene& draft) {
  std::string all;
  for (const std::string& n : draft.notes) all += n + "\n";
  return all;
}

// Onsets of the performers a camera shows (by the camera's name), within [from, to).
int onsets_for_camera(const Drafted& d, const std::string& camera, double from, double to) {
  std::set<int> parts;
  for (const brass::BrassPlayer& p : brass::brass_players(d.scene)) {
    std::string stem;
    for (char c : p.name) stem += c == ' ' ? '_' : static_cast<char>(std::tolower(c));
    const std::string section = stem.substr(0, stem.find('_'));
    if (camera.rfind(stem + "_", 0) == 0 || camera == section + "s") {
      parts.insert(scene::find_part(d.score, p.part));
    }
  }
  if (!piano::keyboard_players(d.scene).empty() && camera.rfind("piano", 0) == 0) {
    for (const std::string& part : piano::keyboard_players(d.scene).front().parts) {
      parts.insert(scene::find_part(d.score, part));
    }
  }
  int count = 0;
  for (const music::Note& n : d.score.notes) {
    count += parts.count(n.part) != 0 && n.onset_s >= from && n.onset_s < to;
  }
  return count;
}

void expect_cuts_follow_the_players(const Drafted& d) {
  ASSERT_FALSE(d.scene.shots.empty());
  EXPECT_EQ(d.scene.cameras[d.scene.shots.front().camera].name, "wide");
  for (std::size_t s = 0; s < d.scene.shots.size(); ++s) {
    const std::string& camera = d.scene.cameras[d.scene.shots[s].camera].name;
    if (camera == "wide") continue;
    const double from = d.scene.shots[s].start_s;
    const double to = s + 1 < d.scene.shots.size() ? d.scene.shots[s + 1].start_s : 1e9;
    EXPECT_GT(onsets_for_camera(d, camera, from, to), 0)
        << camera << " is on screen from " << from << " s to " << to << " s, where they rest";
  }
}

TEST(DraftScene, AChoraleWithTrumpetsGetsThreeTrumpetersAndNamesTheVoicesItLeavesOut) {
  TUTTI_REQUIRE_TESTDATA();
  const Drafted d = draft_of("musicxml/music21/bwv29.8.mxl");
  ASSERT_EQ(brass::brass_players(d.scene).size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(brass::brass_players(d.scene)[i].instrument, "trumpet_bb");
    EXPECT_EQ(brass::brass_players(d.scene)[i].part, "Trumpet " + std::to_string(i + 1));
    EXPECT_EQ(brass::brass_players(d.scene)[i].lead, i == 0);
  }
  EXPECT_TRUE(piano::keyboard_players(d.scene).empty())
      << "Soprano, Alto, ... are not piano parts (their program is 0 "
         "only because the file states none)";
  const std::string notes = joined_notes(d.draft);
  for (const char* part : {"Soprano", "Alto", "Tenor", "Bass", "Timpani"}) {
    EXPECT_NE(notes.find(part), std::string::npos) << notes;
  }
  EXPECT_LT(d.scene.output.start_s, 0.0) << "the lead's cue, a beat before the entrance, is seen";
  expect_cuts_follow_the_players(d);
}

TEST(DraftScene, ASymphonysHornsAndTrumpetsGetAPlayerPerVoiceSeatedBySection) {
  TUTTI_REQUIRE_TESTDATA();
  const Drafted d = draft_of("midi/tonejs/symphony_7_2.mid");
  ASSERT_EQ(brass::brass_players(d.scene).size(), 4u);
  const char* instruments[] = {"trumpet_bb", "trumpet_bb", "horn_double", "horn_double"};
  const int voices[] = {1, 2, 1, 2};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(brass::brass_players(d.scene)[i].instrument, instruments[i]) << i;
    EXPECT_EQ(brass::brass_players(d.scene)[i].voice, voices[i]) << i;
    if (i > 0) {
      EXPECT_NEAR(brass::brass_players(d.scene)[i].position_m.x -
                      brass::brass_players(d.scene)[i - 1].position_m.x,
                  1.0, 1e-9)
          << "seated a metre apart, trumpets on the audience's left";
    }
  }
  EXPECT_EQ(brass::brass_players(d.scene)[0].part, "2 Trumpets in D");
  EXPECT_EQ(brass::brass_players(d.scene)[2].part, "2 Horns in E");
  // The middle of the arc sits forward, the ends turn in.
  EXPECT_GT(brass::brass_players(d.scene)[1].position_m.z,
            brass::brass_players(d.scene)[0].position_m.z);
  EXPECT_GT(brass::brass_players(d.scene)[0].facing_deg, 0.0);
  EXPECT_LT(brass::brass_players(d.scene)[3].facing_deg, 0.0);
  EXPECT_NE(joined_notes(d.draft).find("Violins 1"), std::string::npos);
  EXPECT_GT(d.scene.shots.size(), 10u);
  expect_cuts_follow_the_players(d);
}

TEST(DraftScene, EachPlayersCameraLooksAtThatPlayer) {
  TUTTI_REQUIRE_TESTDATA();
  const Drafted d = draft_of("midi/tonejs/symphony_7_2.mid");
  for (const brass::BrassPlayer& p : brass::brass_players(d.scene)) {
    std::string stem;
    for (char c : p.name) stem += c == ' ' ? '_' : static_cast<char>(std::tolower(c));
    const int index = d.scene.find_camera(stem + "_front");
    ASSERT_GE(index, 0) << p.name;
    const scene::Camera& c = d.scene.cameras[static_cast<std::size_t>(index)];
    EXPECT_LT(std::hypot(c.target_m.x - p.position_m.x, c.target_m.z - p.position_m.z), 0.2);
    // In front of the player: along the way they face.
    const double facing = p.facing_deg * 3.14159265358979 / 180.0;
    const double ahead = (c.position_m.x - p.position_m.x) * std::sin(facing) +
                         (c.position_m.z - p.position_m.z) * std::cos(facing);
    EXPECT_GT(ahead, 1.5) << p.name;
  }
}

TEST(DraftScene, APianoPieceGoesToThePianistWithThePianosCameras) {
  TUTTI_REQUIRE_TESTDATA();
  const Drafted d = draft_of("musicxml/pianoplayer/mozart_sonfacile.mxl");
  EXPECT_TRUE(brass::brass_players(d.scene).empty());
  ASSERT_EQ(piano::keyboard_players(d.scene).size(), 1u);
  EXPECT_EQ(piano::keyboard_players(d.scene).front().parts.size(), 2u);
  EXPECT_GE(d.scene.find_camera("piano_hands"), 0);
  EXPECT_TRUE(d.draft.notes.empty()) << joined_notes(d.draft);
  expect_cuts_follow_the_players(d);

  const Drafted bach = draft_of("midi/tonejs/bach_846.mid");
  ASSERT_EQ(piano::keyboard_players(bach.scene).size(), 1u);
  EXPECT_EQ(piano::keyboard_players(bach.scene).front().parts.front(), "Piano right");
}

TEST(DraftScene, BrassAndPianoTogetherSitSideBySide) {
  TUTTI_REQUIRE_TESTDATA();
  const Drafted d = draft_of("musicxml/lilypond-test-suite/72a-TransposingInstruments.xml");
  ASSERT_EQ(brass::brass_players(d.scene).size(), 2u);
  EXPECT_EQ(brass::brass_players(d.scene)[0].instrument, "trumpet_bb");
  EXPECT_EQ(brass::brass_players(d.scene)[1].instrument, "horn_double");
  ASSERT_EQ(piano::keyboard_players(d.scene).size(), 1u);
  EXPECT_EQ(piano::keyboard_players(d.scene).front().parts, std::vector<std::string>{"Piano"});
  for (const brass::BrassPlayer& p : brass::brass_players(d.scene)) {
    EXPECT_GT(p.position_m.x, 1.5) << p.name << " clear of the piano at the origin";
  }
}

TEST(DraftScene, TheSameScoreGivesTheSameDocument) {
  TUTTI_REQUIRE_TESTDATA();
  const Drafted a = draft_of("midi/tonejs/symphony_7_2.mid");
  const Drafted b = draft_of("midi/tonejs/symphony_7_2.mid");
  EXPECT_EQ(format_scene_document(a.draft.document), format_scene_document(b.draft.document));
}

TEST(DraftScene, MusicNobodyCanPlayIsAnErrorNamingTheParts) {
  music::Score score;
  score.source = "strings.mid";
  score.parts.push_back({"P1", "Violin I", 40, 0, 0, 0, 1, false});
  score.parts.push_back({"P2", "Cello", 42, 1, 1, 0, 1, false});
  music::Note n;
  n.part = 0;
  score.notes.push_back(n);
  n.part = 1;
  score.notes.push_back(n);
  music::finalize_score(score);
  auto drafted = draft_scene(score, "strings.mid");
  ASSERT_FALSE(drafted);
  EXPECT_EQ(drafted.error().message,
            "strings.mid: no part tutti can play (parts: Violin I, Cello); tutti plays trumpet, "
            "horn, trombone, euphonium, tuba and keyboards");
}

TEST(DraftScene, TheDocumentReadsLikeAHandWrittenScene) {
  TUTTI_REQUIRE_TESTDATA();
  const Drafted d = draft_of("musicxml/lilypond-test-suite/72a-TransposingInstruments.xml");
  const std::string text = format_scene_document(d.draft.document);
  EXPECT_EQ(text.rfind("{\n  \"description\": ", 0), 0u) << text;
  EXPECT_NE(text.find("\"position_m\": [2.2, 0.0, 0.0]"), std::string::npos) << text;
  EXPECT_EQ(nlohmann::ordered_json::parse(text), d.draft.document);
}

}  // namespace
}  // namespace tutti::performance
