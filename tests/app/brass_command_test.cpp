// SPDX-License-Identifier: MIT
// `tutti brass`: real pieces in, per-note fingerings, breaths and range reports out; bad input is
// one error line and exit code 2.
#include <tutti/cli/brass_command.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <tutti/core/exit_codes.hpp>
#include <tutti/music/midi/midi_writer.hpp>
#include "testdata.hpp"

namespace tutti::cli {
namespace {

struct BrassRun {
  int code = -1;
  std::string out;
  std::string err;
};

BrassRun run(const BrassOptions& options) {
  std::ostringstream out;
  std::ostringstream err;
  BrassRun r;
  r.code = run_brass(options, out, err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

BrassOptions on(const std::string& relative) {
  BrassOptions o;
  o.file = test::testdata(relative);
  return o;
}

TEST(BrassCommandTest, ChoraleTrumpetsAsJson) {
  TUTTI_REQUIRE_TESTDATA();
  BrassOptions options = on("musicxml/music21/bwv69.6.xml");
  options.json = true;
  const BrassRun r = run(options);
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  ASSERT_EQ(doc["players"].size(), 3u);
  for (const auto& player : doc["players"]) {
    EXPECT_NE(player["name"].get<std::string>().find("Trumpet"), std::string::npos);
    EXPECT_GT(player["notes"].size(), 50u);
    EXPECT_GT(player["breaths"].size(), 0u);
    EXPECT_EQ(player["breaths"][0]["kind"], "before_entrance");
    for (const auto& note : player["notes"]) {
      ASSERT_TRUE(note.contains("fingering")) << note.dump();
      EXPECT_GE(note["tension"].get<double>(), 0.0);
      EXPECT_LE(note["tension"].get<double>(), 1.0);
    }
  }
}

TEST(BrassCommandTest, TextListsEveryNoteOfOnePart) {
  TUTTI_REQUIRE_TESTDATA();
  BrassOptions options = on("midi/tonejs/symphony_7_2.mid");
  options.part = "horns";
  options.voice = 2;
  const BrassRun r = run(options);
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.out.find("\"2 Horns in E\" voice 2"), std::string::npos) << r.out.substr(0, 200);
  EXPECT_NE(r.out.find("horn_double"), std::string::npos);
  std::size_t lines = 0;
  for (char c : r.out) lines += c == '\n';
  EXPECT_GT(lines, 160u);  // 160 notes plus the header and the breaths
}

TEST(BrassCommandTest, InstrumentOverrideReportsNotesOutOfRange) {
  TUTTI_REQUIRE_TESTDATA();
  // The soprano line on a tuba: most of it is too high, reported and left unplayed.
  BrassOptions options = on("musicxml/music21/bwv69.6.xml");
  options.part = "Soprano";
  options.instrument = "tuba";
  options.json = true;
  const BrassRun r = run(options);
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  const auto& player = doc["players"][0];
  EXPECT_EQ(player["instrument"], "tuba");
  EXPECT_GT(player["unplayable"].get<int>(), 10);
  EXPECT_EQ(player["diagnostics"].size(), player["unplayable"].get<std::size_t>());
  const std::string first = player["diagnostics"][0];
  EXPECT_NE(first.find("Soprano"), std::string::npos) << first;
  EXPECT_NE(first.find("bar "), std::string::npos) << first;
  EXPECT_NE(first.find("left unplayed"), std::string::npos) << first;
}

TEST(BrassCommandTest, BadUsageIsOneLineAndExitTwo) {
  TUTTI_REQUIRE_TESTDATA();
  auto expect_error = [](const BrassOptions& options, const std::string& needle) {
    const BrassRun r = run(options);
    EXPECT_EQ(r.code, kExitBadInput) << needle;
    EXPECT_TRUE(r.out.empty());
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
  };
  expect_error(on("midi/no-such-file.mid"), "no-such-file.mid");
  // A piano piece: no brass to find.
  expect_error(on("musicxml/pianoplayer/bach_prelude.xml"), "no brass parts found");
  BrassOptions part = on("musicxml/music21/bwv69.6.xml");
  part.part = "Sousaphone";
  expect_error(part, "no part \"Sousaphone\"");
  part.part = "Alto";  // a voice, not an instrument tutti knows
  expect_error(part, "--instrument");
  part.instrument = "kazoo";
  expect_error(part, "no instrument \"kazoo\"");
  BrassOptions voice = on("musicxml/music21/bwv69.6.xml");
  voice.part = "1";
  voice.voice = 3;
  expect_error(voice, "voice(s)");
}

}  // namespace
}  // namespace tutti::cli

namespace tutti::cli {
namespace {

// A MIDI file with one part on General MIDI program `program` (0-based) and these notes, one
// after another, half a second each.
std::filesystem::path one_part_midi(const std::string& name, int program,
                                    const std::vector<int>& keys) {
  music::Score score;
  music::Part part;
  part.id = "track1-ch0";
  part.name = "";
  part.program = program;
  part.channel = 0;
  part.track = 1;
  score.parts.push_back(part);
  double t = 0.0;
  for (int key : keys) {
    music::Note note;
    note.pitch = key;
    note.onset_s = t;
    note.offset_s = t + 0.45;
    note.onset_beats = t * 2.0;
    note.offset_beats = (t + 0.45) * 2.0;
    note.onset_ticks = static_cast<std::int64_t>(t * 960.0);
    note.offset_ticks = static_cast<std::int64_t>((t + 0.45) * 960.0);
    note.velocity = 80;
    score.notes.push_back(note);
    t += 0.5;
  }
  const std::filesystem::path file = test::unique_temp_path(name);
  EXPECT_TRUE(music::write_midi_file(score, file));
  return file;
}

std::vector<std::string> fingerings(const BrassRun& r) {
  std::vector<std::string> out;
  const auto doc = nlohmann::json::parse(r.out);
  for (const auto& note : doc["players"][0]["notes"]) out.push_back(note["fingering"]);
  return out;
}

// MIDI at concert pitch on a trumpet program is read as a B♭ trumpet (Horii's Table 3.1): C4 is
// valves 1-3. A part that says "in C" / "C Trumpet" keeps the C trumpet.
TEST(BrassCommandTest, AMidiTrumpetIsABFlatTrumpet) {
  const auto file = one_part_midi("gm56.mid", 56, {60});
  BrassOptions options;
  options.file = file;
  options.json = true;
  BrassRun r = run(options);
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["players"][0]["instrument"], "trumpet_bb");
  EXPECT_EQ(fingerings(r), std::vector<std::string>{"1-3"});
  options.json = false;
  r = run(options);
  EXPECT_NE(r.out.find("1-3"), std::string::npos) << r.out;
  std::filesystem::remove(file);

  // Table 3.1, concert pitch: 60 → 1-3, 62 → 1-2, 64 → 2, 65 → open, 67 → 1-2, 69 → 2,
  // 57 → 2, 59 → 1-2-3.
  const auto table = one_part_midi("table31.mid", 56, {60, 62, 64, 65, 67, 69, 57, 59});
  options.file = table;
  options.json = true;
  r = run(options);
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_EQ(fingerings(r), (std::vector<std::string>{"1-3", "1-2", "2", "open", "1-2", "2", "2",
                                                     "1-2-3"}));
  std::filesystem::remove(table);
}

}  // namespace
}  // namespace tutti::cli
