// SPDX-License-Identifier: MIT
#include <tutti/music/load_score.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "testdata.hpp"

namespace tutti::music {
namespace {

namespace fs = std::filesystem;

std::vector<std::uint8_t> bytes_of(const std::string& text) {
  return std::vector<std::uint8_t>(text.begin(), text.end());
}

TEST(LoadScoreTest, DetectsByContentBeforeExtension) {
  EXPECT_EQ(detect_score_format(bytes_of("MThd...."), "a.xml"), ScoreFormat::midi);
  EXPECT_EQ(detect_score_format(bytes_of("RIFF...."), "a.txt"), ScoreFormat::midi);
  EXPECT_EQ(detect_score_format(bytes_of("PK\x03\x04..."), "a.mid"), ScoreFormat::musicxml);
  EXPECT_EQ(detect_score_format(bytes_of("\xEF\xBB\xBF  <?xml"), "a"), ScoreFormat::musicxml);
  EXPECT_EQ(detect_score_format(bytes_of("//Version: PigletFormat"), "a.mid"), ScoreFormat::pig);
  EXPECT_EQ(detect_score_format(bytes_of("????"), "a.mid"), ScoreFormat::midi);
  EXPECT_EQ(detect_score_format(bytes_of("????"), "a.MusicXML"), ScoreFormat::musicxml);
  EXPECT_EQ(detect_score_format(bytes_of("????"), "a.txt"), ScoreFormat::pig);
  EXPECT_FALSE(detect_score_format(bytes_of("????"), "a.wav").has_value());
}

TEST(LoadScoreTest, MissingAndUnknownFilesGiveOneLineErrors) {
  auto missing = load_score("/no/such/dir/piece.mid");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().message, "/no/such/dir/piece.mid: no such file");

  const fs::path unknown = test::unique_temp_path("unknown.bin");
  std::ofstream(unknown, std::ios::binary) << "\x01\x02\x03";
  auto result = load_score(unknown);
  fs::remove(unknown);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().message.rfind(unknown.string() + ": ", 0), 0u);
  EXPECT_EQ(result.error().message.find('\n'), std::string::npos);
}

TEST(LoadScoreTest, DispatchesPigText) {
  const fs::path path = test::unique_temp_path("score.txt");
  std::ofstream(path) << "//Version: PigletFormat 1.0\n0\t0.0\t0.5\tC4\t64\t80\t0\t1\n";
  auto score = load_score(path);
  fs::remove(path);
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->notes.size(), 1u);
  EXPECT_EQ(score->notes[0].pitch, 60);
}

TEST(LoadScoreTest, DispatchesThirdPartyMidiAndMusicXml) {
  TUTTI_REQUIRE_TESTDATA();
  auto midi = load_score(test::testdata("midi/jazz-soft/test-c-major-scale.mid"));
  ASSERT_TRUE(midi.ok()) << midi.error().message;
  EXPECT_GT(midi->notes.size(), 0u);
  auto xml = load_score(test::testdata("musicxml/lilypond-test-suite/01a-Pitches-Pitches.xml"));
  ASSERT_TRUE(xml.ok()) << xml.error().message;
  EXPECT_GT(xml->notes.size(), 0u);
}

}  // namespace
}  // namespace tutti::music
