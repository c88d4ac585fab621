// SPDX-License-Identifier: MIT
// tutti-editor itself, under Xvfb: a script edits, saves and quits; the saved scene reopens with
// every edit, and `tutti render --still` shows the change. Killing the editor in the middle of a
// save leaves the previous file intact.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <thread>

#include <tutti/brass/brass_players.hpp>
#include <tutti/editor/atomic_file.hpp>
#include <tutti/editor/session.hpp>
#include "editor_test_support.hpp"
#include <tutti/scene/load_scene.hpp>
#include <tutti/performance/families.hpp>

std::vector<std::uint8_t> decode_png_for_test(const std::vector<std::uint8_t>& png, int& width,
                                              int& height);

namespace tutti::editor {
namespace {

using test::read_text;
using test::ScratchDir;

const std::filesystem::path kEditor = TUTTI_EDITOR_BINARY;
const std::filesystem::path kTutti = TUTTI_BINARY;
const std::filesystem::path kArtifacts = TUTTI_ARTIFACT_DIR;

bool have_display() { return std::getenv("DISPLAY") != nullptr; }

// Runs a command line; its output (stdout and stderr) and exit code.
std::string run(const std::string& command, int& code) {
  std::string output;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) {
    code = -1;
    return output;
  }
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  const int status = ::pclose(pipe);
  code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return output;
}

std::string quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

std::string editor_command(const std::filesystem::path& scene,
                           const std::filesystem::path& script) {
  return quoted(kEditor) + " " + quoted(scene) + " --script " + quoted(script) +
         " --audio-driver simulated --size 960x540";
}

// Pixels that differ by more than a little between two PNGs of the same size.
int differing_pixels(const std::filesystem::path& a, const std::filesystem::path& b) {
  auto bytes = [](const std::filesystem::path& p) {
    const std::string text = read_text(p);
    return std::vector<std::uint8_t>(text.begin(), text.end());
  };
  int wa = 0, ha = 0, wb = 0, hb = 0;
  const auto pa = decode_png_for_test(bytes(a), wa, ha);
  const auto pb = decode_png_for_test(bytes(b), wb, hb);
  if (pa.empty() || wa != wb || ha != hb) return -1;
  int count = 0;
  for (std::size_t i = 0; i + 3 < pa.size(); i += 4) {
    int d = 0;
    for (std::size_t c = 0; c < 3; ++c) d = std::max(d, std::abs(int(pa[i + c]) - int(pb[i + c])));
    if (d > 8) ++count;
  }
  return count;
}

// One frame of `scene` at t by `tutti render --still` (through `camera` when given).
std::filesystem::path still(const std::filesystem::path& scene, double t,
                            const std::filesystem::path& png, const std::string& camera = "") {
  int code = 0;
  const std::string output =
      run(quoted(kTutti) + " render " + quoted(scene) + " --still " + std::to_string(t) + " -o " +
              quoted(png) + " --size 480x270 --no-progress" +
              (camera.empty() ? "" : " --camera " + camera),
          code);
  EXPECT_EQ(code, 0) << output;
  return png;
}

// A legato boundary of `performer` where nobody planned a breath.
double legato_boundary(const std::filesystem::path& scene, std::size_t performer) {
  auto session = Session::open(scene);
  EXPECT_TRUE(session) << session.error().message;
  if (!session) return -1;
  const TimelineLane& lane = (*session)->timeline().lanes[performer];
  for (std::size_t i = 4; i < lane.notes.size(); ++i) {
    const bool legato = lane.notes[i - 1].end_s >= lane.notes[i].start_s - 1e-6;
    bool breath = false;
    for (const TimelineBreath& b : lane.breaths) {
      breath = breath || std::abs(b.boundary_s - lane.notes[i].start_s) < 1e-6;
    }
    if (legato && !breath && lane.notes[i].start_s > 3.0) return lane.notes[i].start_s;
  }
  return -1;
}

TEST(EditorCli, QuartetRoundTrip) {
  if (!have_display()) GTEST_SKIP() << "no display";
  ScratchDir dir;
  const auto scene = dir.copy_scene("quartet.json");
  const double boundary = legato_boundary(scene, 2);
  ASSERT_GT(boundary, 0.0);
  std::filesystem::create_directories(kArtifacts);
  const auto screenshot = kArtifacts / "editor_quartet.png";
  const auto script = dir.write("edit.txt",
                                "set-variation \"Trumpet 2\" sway_amount 1.0\n"
                                "add-breath \"Trombone 1\" " +
                                    std::to_string(boundary - 0.001) + "\n" + "seek " +
                                    std::to_string(boundary - 0.3) + "\nframes 3\n" +
                                    "screenshot " + screenshot.string() + "\nsave\nquit\n");
  int code = 0;
  const std::string output = run(editor_command(scene, script), code);
  ASSERT_EQ(code, 0) << output;
  EXPECT_NE(output.find("edit.txt:7: quit done"), std::string::npos) << output;
  EXPECT_GT(std::filesystem::file_size(screenshot), 10000u);

  // Reopened: every edit is there.
  auto saved = scene::load_scene(scene, performance::scene_load_options());
  ASSERT_TRUE(saved) << saved.error().message;
  EXPECT_DOUBLE_EQ(*brass::brass_players(*saved)[1].variation.sway_amount, 1.0);
  ASSERT_EQ(brass::brass_players(*saved)[2].breaths.add_s.size(), 1u);
  EXPECT_NEAR(brass::brass_players(*saved)[2].breaths.add_s[0], boundary,
              0.0005);  // to the millisecond
  auto reopened = Session::open(scene);
  ASSERT_TRUE(reopened);
  bool marked = false;
  for (const TimelineBreath& b : (*reopened)->timeline().lanes[2].breaths) {
    marked = marked || (b.marked && std::abs(b.boundary_s - boundary) < 1e-6);
  }
  EXPECT_TRUE(marked) << "the breath is planned from the saved mark";
  // The editor opens the saved file again and quits cleanly (nothing unsaved).
  const auto quit = dir.write("quit.txt", "quit\n");
  run(editor_command(scene, quit), code);
  EXPECT_EQ(code, 0);

  // tutti render shows the change: the previous version (.bak) against the saved one, during
  // the new breath.
  const double t = boundary - 0.15;
  // The wide camera: both edited players are in the picture.
  const auto before = still(backup_path(scene), t, dir.path() / "before.png", "wide");
  const auto after = still(scene, t, dir.path() / "after.png", "wide");
  const int changed = differing_pixels(before, after);
  EXPECT_GT(changed, 200) << "pixels that changed at " << t << " s";
  std::filesystem::copy_file(after, kArtifacts / "editor_quartet_after_render.png",
                             std::filesystem::copy_options::overwrite_existing);
  std::printf("quartet: %d pixels differ at %.3f s after the edits\n", changed, t);
}

TEST(EditorCli, PianoPinRoundTrip) {
  if (!have_display()) GTEST_SKIP() << "no display";
  ScratchDir dir;
  const auto scene = dir.copy_scene("piano.json");
  auto session = Session::open(scene);
  ASSERT_TRUE(session);
  const TimelineNote note = (*session)->timeline().lanes.back().notes[12];
  const int finger = note.finger == 5 ? 3 : 5;
  const auto script =
      dir.write("pin.txt", "pin " + std::to_string(note.start_s) + " " + std::to_string(note.key) +
                               " " + std::to_string(finger) + "\nsave\nquit\n");
  int code = 0;
  const std::string output = run(editor_command(scene, script), code);
  ASSERT_EQ(code, 0) << output;
  auto reopened = Session::open(scene);
  ASSERT_TRUE(reopened) << reopened.error().message;
  const TimelineNote pinned = (*reopened)->timeline().lanes.back().notes[12];
  EXPECT_TRUE(pinned.pinned);
  EXPECT_EQ(pinned.finger, finger);
  const double t = note.start_s + 0.03;
  const int changed = differing_pixels(still(backup_path(scene), t, dir.path() / "before.png"),
                                       still(scene, t, dir.path() / "after.png"));
  EXPECT_GT(changed, 20) << "another finger presses the key at " << t << " s";
  std::printf("piano: %d pixels differ at %.3f s after the pin\n", changed, t);
}

// `tutti scene new` on a third-party chorale writes a scene the editor opens, edits and saves, and
// `tutti render` shows the edit; an existing scene file is never replaced without --force.
TEST(EditorCli, ASceneMadeFromAPieceLoadsEditsAndRenders) {
  if (!have_display()) GTEST_SKIP() << "no display";
  const std::filesystem::path piece =
      std::filesystem::path(TUTTI_TESTDATA_DIR) / "musicxml" / "music21" / "bwv29.8.mxl";
  if (!std::filesystem::exists(piece)) GTEST_SKIP() << "no ../shared/testdata";
  ScratchDir dir;
  const auto scene = dir.path() / "chorale.json";
  int code = 0;
  std::string output =
      run(quoted(kTutti) + " scene new " + quoted(piece) + " -o " + quoted(scene), code);
  ASSERT_EQ(code, 0) << output;
  EXPECT_NE(output.find("3 brass players"), std::string::npos) << output;
  EXPECT_NE(output.find("not played"), std::string::npos) << output;
  const std::string written = read_text(scene);
  output = run(quoted(kTutti) + " scene new " + quoted(piece) + " -o " + quoted(scene), code);
  EXPECT_EQ(code, 2) << output;
  EXPECT_NE(output.find("already exists (--force replaces it)"), std::string::npos) << output;
  EXPECT_EQ(read_text(scene), written);

  const auto script = dir.write("edit.txt",
                                "set-variation \"Trumpet 2\" sway_amount 1.0\n"
                                "cut trumpet_2_front 8.0\nsave\nquit\n");
  output = run(editor_command(scene, script), code);
  ASSERT_EQ(code, 0) << output;
  auto saved = scene::load_scene(scene, performance::scene_load_options());
  ASSERT_TRUE(saved) << saved.error().message;
  EXPECT_DOUBLE_EQ(*brass::brass_players(*saved)[1].variation.sway_amount, 1.0);
  EXPECT_EQ(saved->camera_at(9.0).name, "trumpet_2_front");
  const int changed = differing_pixels(still(backup_path(scene), 9.0, dir.path() / "before.png"),
                                       still(scene, 9.0, dir.path() / "after.png"));
  EXPECT_GT(changed, 5000) << "the cut to Trumpet 2 is on screen at 9 s";
}

// Issue 22's round trip, as processes: `add-breath "Trombone 1" 6.4` and save in one editor run;
// `delete-breath "Trombone 1" 6.667` (the time it was saved at) and save in a second. The breath
// shows while it is there, and afterwards the scene renders byte for byte as the original at a
// time the breath covered.
TEST(EditorCli, ABreathAddedThenDeletedRendersAsTheOriginal) {
  if (!have_display()) GTEST_SKIP() << "no display";
  ScratchDir dir;
  const auto scene = dir.copy_scene("quartet.json");
  const auto original = dir.write("original.json", read_text(scene));
  int code = 0;
  std::string output = run(editor_command(scene, dir.write("add.txt",
                                                           "add-breath \"Trombone 1\" 6.4\n"
                                                           "save\nquit\n")),
                           code);
  ASSERT_EQ(code, 0) << output;
  const std::string added = read_text(scene);
  ASSERT_NE(added.find("6.667"), std::string::npos) << added;
  // The inhale before the note at 6.667 s, seen from the trombones' camera.
  const double t = 6.55;
  const auto before = still(original, t, dir.path() / "original.png", "trombones");
  const auto with_breath = still(scene, t, dir.path() / "added.png", "trombones");
  EXPECT_GT(differing_pixels(before, with_breath), 0) << "the added breath shows at " << t << " s";

  output = run(editor_command(scene, dir.write("delete.txt",
                                               "delete-breath \"Trombone 1\" 6.667\n"
                                               "save\nquit\n")),
               code);
  ASSERT_EQ(code, 0) << output;
  const auto after = still(scene, t, dir.path() / "after.png", "trombones");
  EXPECT_EQ(read_text(after), read_text(before)) << "the PNGs differ byte for byte";
  auto reopened = scene::load_scene(scene, performance::scene_load_options());
  ASSERT_TRUE(reopened) << reopened.error().message;
  EXPECT_TRUE(brass::brass_players(*reopened)[2].breaths.add_s.empty());
  EXPECT_TRUE(brass::brass_players(*reopened)[2].breaths.remove_s.empty());
}

TEST(EditorCli, KilledWhileSavingThePreviousFileIsIntact) {
  if (!have_display()) GTEST_SKIP() << "no display";
  ScratchDir dir;
  const auto scene = dir.copy_scene("quartet.json");
  const std::string original = read_text(scene);
  const auto script =
      dir.write("save.txt", "set-variation \"Trumpet 1\" sway_amount 0.1\nsave\nquit\n");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::setenv("TUTTI_EDITOR_TEST_SAVE_PAUSE_MS", "20000", 1);
    // exec: the shell becomes the editor, so the pid killed below is the editor's.
    const std::string command = "exec " + editor_command(scene, script) + " >/dev/null 2>&1";
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Wait until the new version is written and flushed beside the scene, not yet renamed.
  const auto saving = dir.path() / ".quartet.json.saving";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!std::filesystem::exists(saving) && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_TRUE(std::filesystem::exists(saving)) << "the editor never started saving";
  ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "killed inside the save, not finished";
  EXPECT_EQ(read_text(scene), original) << "the scene is the previous version, byte for byte";
  EXPECT_TRUE(scene::load_scene(scene, performance::scene_load_options())) << "and loads";
  EXPECT_NE(read_text(saving).find("\"sway_amount\": 0.1"), std::string::npos)
      << "the killed save had written the new version beside it";
}

TEST(EditorCli, BadInputIsAOneLineError) {
  int code = 0;
  ScratchDir dir;
  const auto script = dir.write("bad.txt", "frobnicate\n");
  std::string output = run(quoted(kEditor) + " /no/such/scene.json", code);
  EXPECT_EQ(code, 2);
  EXPECT_EQ(output, "error: /no/such/scene.json: no such file\n");
  output = run(editor_command(test::source_dir() / "content/scenes/quartet.json", script), code);
  EXPECT_EQ(code, 2);
  EXPECT_EQ(output, "error: bad.txt:1: unknown command \"frobnicate\"\n");
  output = run(quoted(kEditor) + " x.json --size 10x10", code);
  EXPECT_EQ(code, 2);
  EXPECT_EQ(output, "error: --size \"10x10\": expected WxH, at least 320x240\n");
  const auto typo = dir.write("typo.txt", "add-breth \"Trumpet 1\" 6.0\n");
  output = run(editor_command(test::source_dir() / "content/scenes/quartet.json", typo), code);
  EXPECT_EQ(code, 2);
  EXPECT_EQ(output,
            "error: typo.txt:1: unknown command \"add-breth\" (did you mean \"add-breath\"?)\n");
  // No display is the machine's lack, not the user's input: exit 3.
  const auto quit = dir.write("quit.txt", "quit\n");
  output = run("env -u DISPLAY -u WAYLAND_DISPLAY " +
                   editor_command(test::source_dir() / "content/scenes/quartet.json", quit),
               code);
  EXPECT_EQ(code, 3) << output;
  EXPECT_NE(output.find("error: cannot open a window: no display"), std::string::npos) << output;
}

}  // namespace
}  // namespace tutti::editor
