// SPDX-License-Identifier: MIT
// The editor's --script actions, run against a session with a host that records the transport.
#include <tutti/editor/script.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "editor_test_support.hpp"
#include <tutti/brass/brass_players.hpp>
#include <tutti/scene/load_scene.hpp>
#include <tutti/performance/families.hpp>

namespace tutti::editor {
namespace {

using test::performer_at;
using test::ScratchDir;

struct RecordingHost : ScriptHost {
  std::vector<std::string> calls;
  void seek(double t) override { calls.push_back("seek " + std::to_string(t)); }
  void set_playing(bool playing) override { calls.push_back(playing ? "play" : "pause"); }
  void select(const PlayerRef& player) override { calls.push_back("select " + player.pointer); }
  Status draw_frames(int count) override {
    calls.push_back("frames " + std::to_string(count));
    return Status::success();
  }
  Status screenshot(const std::filesystem::path& png) override {
    calls.push_back("screenshot " + png.string());
    return Status::success();
  }
};

Result<ScriptStep> run_all(const Script& script, Session& session, ScriptHost& host) {
  for (const ScriptCommand& command : script.commands) {
    auto step = run_script_command(script, command, session, host);
    if (!step || *step == ScriptStep::quit) return step;
  }
  return ScriptStep::next;
}

TEST(Script, BadScriptsAreOneLineErrorsBeforeAnythingRuns) {
  EXPECT_EQ(parse_script("save\nfrobnicate 3\n", "s.txt").error().message,
            "s.txt:2: unknown command \"frobnicate\"");
  EXPECT_EQ(parse_script("add-breath \"Trumpet 1\" soon\n", "s.txt").error().message,
            "s.txt:1: \"soon\" is not a number (usage: add-breath PERFORMER TIME)");
  EXPECT_EQ(parse_script("seek\n", "s.txt").error().message, "s.txt:1: usage: seek TIME");
  EXPECT_EQ(parse_script("add-breath \"Trumpet 1 6\n", "s.txt").error().message,
            "s.txt:1: unclosed quote");
  EXPECT_EQ(load_script("/no/such/script.txt").error().message,
            "/no/such/script.txt: no such file");
  auto ok = parse_script("# edits\n\nseek 2.5   # and a comment\nquit\n", "s.txt");
  ASSERT_TRUE(ok) << ok.error().message;
  ASSERT_EQ(ok->commands.size(), 2u);
  EXPECT_EQ(ok->commands[0].line, 3);
}

TEST(Script, EditsSaveAndQuit) {
  ScratchDir dir;
  const auto file = dir.copy_scene("quartet.json");
  auto session = Session::open(file);
  ASSERT_TRUE(session) << session.error().message;
  RecordingHost host;
  auto script = parse_script(
      "set-variation \"Trumpet 2\" sway_amount 0.8\n"
      "add-breath \"Trombone 1\" 6.0\n"
      "add-expression \"Trumpet 1\" strain 4 6 0.7\n"
      "cut close_trumpet 12.5\n"
      "seek 12\nframes 3\nscreenshot x.png\n"
      "quit\n",
      "s.txt");
  ASSERT_TRUE(script) << script.error().message;
  auto step = run_all(*script, **session, host);
  ASSERT_FALSE(step);
  EXPECT_NE(step.error().message.find("s.txt:4: quartet.json: /shots/"), std::string::npos)
      << "no camera of that name: " << step.error().message;

  auto fixed = parse_script(
      "cut wide 12.5\nselect \"Trombone 2\"\nseek 12\nframes 3\nscreenshot x.png\nquit\n", "s.txt");
  ASSERT_TRUE(fixed);
  step = run_all(*fixed, **session, host);
  ASSERT_FALSE(step);
  EXPECT_EQ(step.error().message, "s.txt:6: unsaved changes (save first, or quit-discarding)");
  EXPECT_EQ(host.calls, (std::vector<std::string>{"select /performers/3", "seek 12.000000",
                                                  "frames 3", "screenshot x.png"}));

  auto finish = parse_script("save\nquit\n", "s.txt");
  ASSERT_TRUE(finish);
  step = run_all(*finish, **session, host);
  ASSERT_TRUE(step) << step.error().message;
  EXPECT_EQ(*step, ScriptStep::quit);
  auto saved = scene::load_scene(file, performance::scene_load_options());
  ASSERT_TRUE(saved) << saved.error().message;
  EXPECT_DOUBLE_EQ(*brass::brass_players(*saved)[1].variation.sway_amount, 0.8);
  // The mark is stored at the boundary it names (the first note at or after 6 s), to the
  // millisecond.
  const double boundary = (*session)->breath_boundary(performer_at(2), 6.0);
  EXPECT_GT(boundary, 6.0);
  ASSERT_EQ(brass::brass_players(*saved)[2].breaths.add_s.size(), 1u);
  EXPECT_EQ(brass::brass_players(*saved)[2].breaths.add_s[0],
            std::round(boundary * 1000.0) / 1000.0);
  ASSERT_EQ(brass::brass_players(*saved)[0].expressions.size(), 1u);
  EXPECT_DOUBLE_EQ(brass::brass_players(*saved)[0].expressions[0].amount, 0.7);
  EXPECT_EQ(saved->cameras[saved->shots[saved->shot_at(12.6)].camera].name, "wide");
}

// The breath round trip: a breath added at 6.4 s lands on the next note's start (6.667 s, written
// to the millisecond); saved, reopened, `delete-breath` at that time removes that breath — not a
// rule's breath further on — and the scene is what it was. A time with no breath near is an error.
TEST(Script, ABreathAddedSavedAndReopenedIsDeletedAtItsTime) {
  ScratchDir dir;
  const auto file = dir.copy_scene("quartet.json");
  const nlohmann::json original = nlohmann::json::parse(std::ifstream(file));
  RecordingHost host;
  {
    auto session = Session::open(file);
    ASSERT_TRUE(session) << session.error().message;
    auto script = parse_script("add-breath \"Trombone 1\" 6.4\nsave\nquit\n", "a.txt");
    ASSERT_TRUE(script);
    ASSERT_TRUE(run_all(*script, **session, host));
  }
  const nlohmann::json added = nlohmann::json::parse(std::ifstream(file));
  ASSERT_TRUE(added["performers"][2].contains("breaths"));
  const double written = added["performers"][2]["breaths"]["add"][0].get<double>();
  EXPECT_EQ(written, std::round(written * 1000.0) / 1000.0) << written;
  EXPECT_GT(written, 6.4);
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", written);
  {
    auto session = Session::open(file);
    ASSERT_TRUE(session) << session.error().message;
    auto missing = parse_script("delete-breath \"Trombone 1\" 8.2\n", "b.txt");
    ASSERT_TRUE(missing);
    auto refused = run_all(*missing, **session, host);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().message.find("b.txt:1: no breath of \"Trombone 1\" at 8.200 s"),
              std::string::npos)
        << refused.error().message;
    auto script = parse_script(std::string("delete-breath \"Trombone 1\" ") + text +
                                   "\nsave\nquit\n",
                               "b.txt");
    ASSERT_TRUE(script);
    auto step = run_all(*script, **session, host);
    ASSERT_TRUE(step) << step.error().message;
  }
  const nlohmann::json after = nlohmann::json::parse(std::ifstream(file));
  EXPECT_EQ(after["performers"][2], original["performers"][2]) << after["performers"][2].dump();
  EXPECT_EQ(after, original);
}

TEST(Script, UnknownPerformerNamesTheOnesThere) {
  ScratchDir dir;
  auto session = Session::open(dir.copy_scene("quartet.json"));
  ASSERT_TRUE(session);
  RecordingHost host;
  auto script = parse_script("reroll-seed Tuba\n", "s.txt");
  ASSERT_TRUE(script);
  auto step = run_all(*script, **session, host);
  ASSERT_FALSE(step);
  EXPECT_EQ(step.error().message,
            "s.txt:1: no performer \"Tuba\" (performers: Trumpet 1, Trumpet 2, Trombone 1, "
            "Trombone 2)");
}

// Players are named across families; an edit a player's family does not take is refused with
// its reason, and the file is left as it was.
TEST(Script, AnEditAPlayersFamilyDoesNotTakeIsRefused) {
  ScratchDir dir;
  auto session = Session::open(dir.copy_scene("piano.json"));
  ASSERT_TRUE(session);
  RecordingHost host;
  const std::pair<const char*, const char*> cases[] = {
      {"add-breath pianist 1.0\n",
       "s.txt:1: pianist takes no breath marks (their family plans no breaths)"},
      {"add-expression pianist strain 1 2\n",
       "s.txt:1: pianist takes no expressions (their family has none)"},
      {"pin 1.5 64 3 Nobody\n", "s.txt:1: no performer \"Nobody\" (performers: pianist)"},
  };
  for (const auto& [text, message] : cases) {
    auto script = parse_script(text, "s.txt");
    ASSERT_TRUE(script) << text;
    auto step = run_all(*script, **session, host);
    ASSERT_FALSE(step) << text;
    EXPECT_EQ(step.error().message, message);
  }
  EXPECT_FALSE((*session)->document().dirty());
  auto select = parse_script("select pianist\n", "s.txt");
  ASSERT_TRUE(select);
  ASSERT_TRUE(run_all(*select, **session, host));
  EXPECT_EQ(host.calls.back(), "select /pianist");
}

}  // namespace
}  // namespace tutti::editor
