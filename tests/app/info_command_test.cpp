// SPDX-License-Identifier: MIT
#include <tutti/cli/info_command.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include <tutti/core/exit_codes.hpp>
#include "testdata.hpp"

namespace tutti::cli {
namespace {

namespace fs = std::filesystem;

struct InfoRun {
  int code = -1;
  std::string out;
  std::string err;
};

InfoRun run(const fs::path& file, bool json) {
  std::ostringstream out;
  std::ostringstream err;
  InfoRun r;
  r.code = run_info(InfoOptions{file, json}, out, err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

class InfoCommandTest : public ::testing::Test {
 protected:
  void SetUp() override {
    pig_ = test::unique_temp_path("info.txt");
    std::ofstream(pig_) << "//Version: PigletFormat 1.0\n"
                           "0\t0.0\t0.5\tC4\t64\t80\t0\t1\n"
                           "1\t0.5\t1.0\tG4\t64\t80\t0\t5\n"
                           "2\t0.0\t2.0\tC3\t64\t80\t1\t-5\n";
  }
  void TearDown() override { fs::remove(pig_); }
  fs::path pig_;
};

TEST_F(InfoCommandTest, JsonHasTheDocumentedShape) {
  const InfoRun r = run(pig_, true);
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_TRUE(r.err.empty());
  const auto json = nlohmann::json::parse(r.out);
  EXPECT_EQ(json["notes"], 3);
  EXPECT_DOUBLE_EQ(json["duration_s"].get<double>(), 2.0);
  EXPECT_EQ(json["format"], "PIG");
  ASSERT_EQ(json["parts"].size(), 2u);
  const auto& right = json["parts"][0];
  EXPECT_EQ(right["name"], "Right hand");
  EXPECT_EQ(right["program"], 0);
  EXPECT_EQ(right["notes"], 2);
  EXPECT_EQ(right["lowest"], 60);
  EXPECT_EQ(right["highest"], 67);
  EXPECT_EQ(json["parts"][1]["lowest"], 48);
  EXPECT_EQ(json["fingered_notes"], 3);
}

TEST_F(InfoCommandTest, TextReportNamesPartsAndRanges) {
  const InfoRun r = run(pig_, false);
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.out.find("notes: 3"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Right hand"), std::string::npos);
  EXPECT_NE(r.out.find("C4..G4 (60..67)"), std::string::npos) << r.out;
}

TEST_F(InfoCommandTest, SameInputSameBytes) { EXPECT_EQ(run(pig_, true).out, run(pig_, true).out); }

TEST_F(InfoCommandTest, BadFileGivesOneErrorLineAndExitTwo) {
  const InfoRun r = run("/definitely/missing.mid", true);
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_TRUE(r.out.empty());
  EXPECT_EQ(r.err, "error: /definitely/missing.mid: no such file\n");
}

TEST_F(InfoCommandTest, ThirdPartyPieceReportsParts) {
  TUTTI_REQUIRE_TESTDATA();
  const InfoRun r = run(test::testdata("musicxml/music21/bwv69.6.xml"), true);
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto json = nlohmann::json::parse(r.out);
  EXPECT_GE(json["parts"].size(), 4u);
  int total = 0;
  for (const auto& part : json["parts"]) total += part["notes"].get<int>();
  EXPECT_EQ(total, json["notes"].get<int>());
  EXPECT_GT(json["duration_s"].get<double>(), 10.0);
}

// The acceptance check at the command's level: `tutti info --json` agrees with an independent
// parser (python mido, numbers recorded in tests/data/midi/mido_expected.json) on the note count
// and the duration of every valid MIDI file in ../shared/testdata/midi.
TEST_F(InfoCommandTest, AgreesWithMidoOnEveryValidMidiFile) {
  TUTTI_REQUIRE_TESTDATA();
  std::ifstream in(test::source_dir() / "tests/data/midi/mido_expected.json");
  ASSERT_TRUE(in) << "tests/data/midi/mido_expected.json missing";
  const auto expected = nlohmann::json::parse(in).at("files");
  const auto broken = test::broken_testdata_files("midi/");
  int compared_counts = 0;
  int compared_durations = 0;
  for (const auto& [file, mido] : expected.items()) {
    SCOPED_TRACE(file);
    const InfoRun r = run(test::testdata(file), true);
    if (broken.count(file) != 0) {
      EXPECT_EQ(r.code, kExitBadInput);
      continue;
    }
    ASSERT_EQ(r.code, kExitOk) << r.err;
    if (!mido.at("ok").get<bool>()) continue;  // mido could not read it: nothing to compare
    const auto json = nlohmann::json::parse(r.out);
    EXPECT_EQ(json.at("notes").get<int>(), mido.at("notes").get<int>());
    ++compared_counts;
    if (!mido.at("length").is_null()) {
      const double length = mido.at("length").get<double>();
      EXPECT_NEAR(json.at("duration_s").get<double>(), length, std::max(1e-6 * length, 1e-9));
      ++compared_durations;
    }
  }
  // Every file mido reads is compared; a shrinking count would mean the check went hollow.
  EXPECT_GE(compared_counts, 60);
  EXPECT_GE(compared_durations, 55);
}

}  // namespace
}  // namespace tutti::cli

namespace tutti::cli {
namespace {

// `tutti info --schedule SCENE`: the frame's phases with their systems, in run order, and what
// each reads and writes; the audio-sync system in the sync phase.
TEST(InfoSchedule, ListsEachPhaseWithItsSystems) {
  std::ostringstream out;
  std::ostringstream err;
  InfoOptions options;
  options.file = fs::path(TUTTI_SOURCE_DIR) / "content" / "scenes" / "quartet.json";
  options.schedule = true;
  ASSERT_EQ(run_info(options, out, err), kExitOk) << err.str();
  const std::string text = out.str();
  std::vector<std::string> phases;
  std::map<std::string, std::vector<std::string>> systems;
  std::istringstream lines(text);
  std::string line;
  std::getline(lines, line);  // the heading
  while (std::getline(lines, line)) {
    if (line.rfind("entities:", 0) == 0) break;
    if (line.rfind("  ", 0) != 0) {
      phases.push_back(line);
    } else {
      systems[phases.back()].push_back(line.substr(2, line.find(' ', 2) - 2));
    }
  }
  EXPECT_EQ(phases, (std::vector<std::string>{"sync", "evaluate", "express", "pose"}));
  EXPECT_EQ(systems["sync"], std::vector<std::string>{"audio_sync"});
  for (const std::string& phase : phases) EXPECT_FALSE(systems[phase].empty()) << phase;
  EXPECT_NE(std::find(systems["evaluate"].begin(), systems["evaluate"].end(), "note_sounding"),
            systems["evaluate"].end());
  EXPECT_NE(text.find("writes Mouth, Breath, Valve, Slide"), std::string::npos) << text;
  EXPECT_NE(text.find("4 Performer, 128 Note"), std::string::npos) << text;
}

TEST(InfoSchedule, ABrokenSceneIsOneLine) {
  std::ostringstream out;
  std::ostringstream err;
  InfoOptions options;
  options.file = "no_such_scene.json";
  options.schedule = true;
  EXPECT_EQ(run_info(options, out, err), kExitBadInput);
  const std::string message = err.str();
  EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 1) << message;
  EXPECT_NE(message.find("no_such_scene.json"), std::string::npos) << message;
}

}  // namespace
}  // namespace tutti::cli
