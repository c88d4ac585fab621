// `tutti brass`: real pieces in, per-note fingerings, breaths and range reports out; bad input is
// one error line and exit code 2.
#include <tutti/cli/brass_command.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <sstream>

#include <tutti/cli/exit_codes.hpp>
#include "testdata.hpp"

namespace tutti::app {
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
}  // namespace tutti::app
