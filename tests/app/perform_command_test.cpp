// SPDX-License-Identifier: MIT
// `tutti perform`: the notes as the simulated keys sounded them, written as MIDI; a report per
// style; deterministic; one-line errors for bad input.
#include <tutti/cli/perform_command.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include <tutti/core/exit_codes.hpp>
#include "command_run.hpp"
#include <tutti/core/file_io.hpp>
#include <tutti/music/load_score.hpp>
#include "testdata.hpp"

namespace tutti::cli {
namespace {

namespace fs = std::filesystem;

using test::CommandRun;

CommandRun run(const PerformOptions& options) { return test::run_command(run_perform, options); }

const fs::path kDemo = tutti::test::source_dir() / "content" / "music" / "ode_to_joy.musicxml";

TEST(PerformCommand, WritesTheNotesAsTheKeysSoundedThem) {
  PerformOptions o;
  o.input = kDemo;
  o.style = "beginner";
  o.seed = 5;
  o.output = tutti::test::unique_temp_path("beginner.mid");
  const CommandRun text = run(o);
  ASSERT_EQ(text.code, kExitOk) << text.err;
  EXPECT_EQ(text.out.rfind("beginner: sounded ", 0), 0u) << text.out;
  o.json = true;  // the same report as JSON on stdout, nothing else there
  const CommandRun r = run(o);
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const nlohmann::json json = nlohmann::json::parse(r.out)["beginner"];
  auto heard = music::load_score(o.output);
  ASSERT_TRUE(heard.ok()) << heard.error().message;
  ASSERT_EQ(heard->notes.size(), json["sounded"].get<std::size_t>());
  // Each sounded note is in the file at its sounded time (to a tick) and velocity.
  std::vector<std::pair<double, int>> sounded;
  for (const nlohmann::json& note : json["played"]) {
    if (note["outcome"] == "sounded") {
      // Nothing is written before time 0 (a first note's motor noise can sound it early).
      sounded.push_back(
          {std::max(0.0, note["onset_s"].get<double>()), note["velocity"].get<int>()});
    }
  }
  std::sort(sounded.begin(), sounded.end());
  std::vector<std::pair<double, int>> in_file;
  for (const music::Note& n : heard->notes) in_file.push_back({n.onset_s, n.velocity});
  std::sort(in_file.begin(), in_file.end());
  ASSERT_EQ(in_file.size(), sounded.size());
  for (std::size_t i = 0; i < sounded.size(); ++i) {
    EXPECT_NEAR(in_file[i].first, sounded[i].first, 0.0011) << i;
    EXPECT_EQ(in_file[i].second, sounded[i].second) << i;
  }
  fs::remove(o.output);
}

TEST(PerformCommand, ReportsEveryStyle) {
  PerformOptions o;
  o.input = kDemo;
  o.style = "all";
  const CommandRun r = run(o);
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.out.find("beginner: sounded"), std::string::npos);
  EXPECT_NE(r.out.find("gentle: sounded"), std::string::npos);
  EXPECT_NE(r.out.find("precise: sounded 94/94"), std::string::npos) << r.out;
}

TEST(PerformCommand, TheSameSeedWritesTheSameFile) {
  PerformOptions o;
  o.input = kDemo;
  o.style = "gentle";
  o.output = tutti::test::unique_temp_path("a.mid");
  ASSERT_EQ(run(o).code, kExitOk);
  auto first = read_file_bytes(o.output);
  ASSERT_EQ(run(o).code, kExitOk);
  auto second = read_file_bytes(o.output);
  ASSERT_TRUE(first.ok() && second.ok());
  EXPECT_EQ(*first, *second);
  o.seed = 99;
  ASSERT_EQ(run(o).code, kExitOk);
  auto reseeded = read_file_bytes(o.output);
  EXPECT_NE(*first, *reseeded);
  fs::remove(o.output);
}

TEST(PerformCommand, BadInputIsAOneLineError) {
  const auto expect_error = [](const PerformOptions& o, const std::string& needle) {
    const CommandRun r = run(o);
    EXPECT_EQ(r.code, kExitBadInput) << needle;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
  };
  PerformOptions o;
  o.input = "/nonexistent/piece.mid";
  expect_error(o, "/nonexistent/piece.mid");
  o.input = kDemo;
  o.style = "virtuoso";
  expect_error(o,
               "--style: unknown performance style 'virtuoso' (styles: beginner, gentle, precise)");
  o.style = "all";
  o.output = "x.mid";
  expect_error(o, "--style all");
  o.style = "precise";
  o.output = "x.wav";
  expect_error(o, "x.wav: the output is a MIDI file (.mid)");
  o.output.clear();
  const fs::path truncated = tutti::test::unique_temp_path("cut.mid");
  ASSERT_TRUE(write_file_atomically(truncated, std::string("MThd\0\0\0\6\0\1", 10)).ok());
  o.input = truncated;
  expect_error(o, truncated.string());
  fs::remove(truncated);
}

}  // namespace
}  // namespace tutti::cli
