// SPDX-License-Identifier: MIT
// `scene new` gives every keyboard part a player at an instrument of its own (content/piano/
// instruments.json): organ, synth and electric-piano parts, recognised by name or General MIDI
// program, get an organist and keyboardists beside the pianist; an accordion is not played.
// Third-party files: a MIDI file whose one part is a drawbar organ, and a lead sheet for
// electric piano.
#include <tutti/performance/draft_scene.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>

#include <tutti/music/load_score.hpp>
#include <tutti/performance/families.hpp>
#include <tutti/piano/keyboard_players.hpp>
#include <tutti/scene/load_scene.hpp>
#include "testdata.hpp"

namespace tutti::performance {
namespace {

scene::Scene parsed(const DraftedScene& drafted, const std::filesystem::path& dir) {
  auto scene = scene::parse_scene(nlohmann::json::parse(drafted.document.dump()), "draft.json", dir, performance::scene_load_options());
  EXPECT_TRUE(scene) << scene.error().message;
  return scene ? *scene : scene::Scene{};
}

music::Score keyboard_band() {
  music::Score score;
  score.source = "band.mid";
  score.parts.push_back({"P1", "Piano", 0, 0, 0, 0, 1, false});
  score.parts.push_back({"P2", "Track 2", 19, 1, 1, 0, 1, false});   // Church Organ, no name
  score.parts.push_back({"P3", "Synth Lead", 80, 2, 2, 0, 1, false});
  score.parts.push_back({"P4", "Accordion", 21, 3, 3, 0, 1, false});
  for (int part = 0; part < 4; ++part) {
    for (int k = 0; k < 8; ++k) {
      music::Note n;
      n.part = part;
      n.pitch = 48 + part * 5 + k;
      n.onset_s = 0.5 * k;
      n.offset_s = 0.5 * k + 0.4;
      score.notes.push_back(n);
    }
  }
  music::finalize_score(score);
  return score;
}

TEST(DraftKeyboards, OrganAndSynthPartsGetPlayersBesideThePianist) {
  const music::Score score = keyboard_band();
  auto drafted = draft_scene(score, "band.mid");
  ASSERT_TRUE(drafted) << drafted.error().message;
  ASSERT_TRUE(drafted->document.contains("pianists"));
  // The made-up score has no file: the scene reads a real one in its place (parts are checked
  // only when the music is loaded).
  DraftedScene with_music = *drafted;
  with_music.document["music"] =
      (std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "music" / "piano_duo.musicxml").string();
  const scene::Scene scene = parsed(with_music, std::filesystem::current_path());
  ASSERT_EQ(piano::keyboard_players(scene).size(), 3u);
  EXPECT_EQ(piano::keyboard_players(scene)[0].instrument, "piano");
  EXPECT_EQ(piano::keyboard_players(scene)[0].parts, std::vector<std::string>{"Piano"});
  EXPECT_EQ(piano::keyboard_players(scene)[1].instrument, "organ");
  EXPECT_EQ(piano::keyboard_players(scene)[1].name, "organist");
  EXPECT_EQ(piano::keyboard_players(scene)[1].parts, std::vector<std::string>{"Track 2"});
  EXPECT_EQ(piano::keyboard_players(scene)[2].instrument, "synth");
  EXPECT_EQ(piano::keyboard_players(scene)[2].name, "keyboardist");
  // Side by side on the audience's left of the piano, a piano's width and more apart.
  EXPECT_LT(piano::keyboard_players(scene)[1].position_m.x, -1.4);
  EXPECT_LT(piano::keyboard_players(scene)[2].position_m.x,
            piano::keyboard_players(scene)[1].position_m.x - 1.4);
  ASSERT_GE(scene.find_camera("organ_hands"), 0);
  ASSERT_GE(scene.find_camera("synth_hands"), 0);
  // The hands cameras look at each manual: the organ's stands 130 mm higher, on its platform.
  const auto target_y = [&](const char* camera) {
    return scene.cameras[static_cast<std::size_t>(scene.find_camera(camera))].target_m.y;
  };
  EXPECT_NEAR(target_y("synth_hands"), 0.74, 1e-9);
  EXPECT_NEAR(target_y("organ_hands"), 0.74 + 0.13, 1e-9);
  std::string notes;
  for (const std::string& n : drafted->notes) notes += n + "\n";
  EXPECT_NE(notes.find("not played (tutti plays trumpet, horn, trombone, euphonium, tuba and "
                       "keyboards): Accordion"),
            std::string::npos)
      << notes;
  const std::string description = drafted->document["description"].get<std::string>();
  EXPECT_NE(description.find("a pianist and an organist and a keyboardist"), std::string::npos)
      << description;
}

TEST(DraftKeyboards, APianoPieceStillHasOnePianistWrittenTheOlderWay) {
  music::Score score = keyboard_band();
  score.parts.resize(1);
  score.notes.erase(std::remove_if(score.notes.begin(), score.notes.end(),
                                   [](const music::Note& n) { return n.part != 0; }),
                    score.notes.end());
  music::finalize_score(score);
  auto drafted = draft_scene(score, "piano.mid");
  ASSERT_TRUE(drafted) << drafted.error().message;
  EXPECT_TRUE(drafted->document.contains("pianist"));
  EXPECT_FALSE(drafted->document.contains("pianists"));
}

TEST(DraftKeyboards, ThirdPartyOrganAndElectricPianoParts) {
  TUTTI_REQUIRE_TESTDATA();
  for (const auto& [file, instrument] :
       {std::pair<std::string, std::string>{"midi/jazz-soft/test-rpn-00-00-pitch-bend-range.mid",
                                            "organ"},
        {"musicxml/music21/berlinAlexandersRagtime.mxl", "electric_piano"}}) {
    const std::filesystem::path path = test::testdata(file);
    auto score = music::load_score(path);
    ASSERT_TRUE(score) << score.error().message;
    auto drafted = draft_scene(*score, path);
    ASSERT_TRUE(drafted) << drafted.error().message;
    const scene::Scene scene = parsed(*drafted, path.parent_path());
    ASSERT_EQ(piano::keyboard_players(scene).size(), 1u) << file;
    EXPECT_EQ(piano::keyboard_players(scene)[0].instrument, instrument) << file;
  }
}

// An organ piece on three staves (content/music/organ_chorale.musicxml): `scene new` gives it an
// organist, whose staged plan puts the third staff on the pedals with both feet.
TEST(DraftKeyboards, AnOrganPieceGetsAnOrganistWhoseFeetPlayThePedalStaff) {
  const std::filesystem::path path =
      std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "music" / "organ_chorale.musicxml";
  auto score = music::load_score(path);
  ASSERT_TRUE(score) << score.error().message;
  auto drafted = draft_scene(*score, path);
  ASSERT_TRUE(drafted) << drafted.error().message;
  const scene::Scene scene = parsed(*drafted, path.parent_path());
  ASSERT_EQ(piano::keyboard_players(scene).size(), 1u);
  EXPECT_EQ(piano::keyboard_players(scene)[0].instrument, "organ");
  EXPECT_EQ(piano::keyboard_players(scene)[0].name, "organist");
  auto stage = build_stage(scene, {});
  ASSERT_TRUE(stage) << stage.error().message;
  const auto& notes = (*stage)->notes();
  EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& n) {
    return n.find("organist: 32 notes on the pedals (") == 0;
  }));
}

}  // namespace
}  // namespace tutti::performance
