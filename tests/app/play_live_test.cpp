// SPDX-License-Identifier: MIT
// `tutti play` with live input, as a process: what cannot work fails with one line before any
// window opens — no ALSA sequencer on this machine (or no such port), a scene without a pianist.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

namespace {

struct ProcessResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

ProcessResult run_tutti(const std::string& arguments) {
  // No display: a test that got past the checks would fail on the window instead, loudly.
  const std::string command =
      "DISPLAY= WAYLAND_DISPLAY= " + std::string(TUTTI_EXE) + " " + arguments + " 2>&1";
  ProcessResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr) {
    result.output += buffer.data();
  }
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string scene(const char* name) {
  return std::string(TUTTI_SOURCE_DIR) + "/content/scenes/" + name;
}

void expect_one_line_error(const ProcessResult& r, const std::string& contains) {
  EXPECT_EQ(r.exit_code, 2) << r.output;
  int lines = 0;
  for (char c : r.output) lines += c == '\n';
  EXPECT_EQ(lines, 1) << r.output;
  EXPECT_EQ(r.output.rfind("error: ", 0), 0u) << r.output;
  EXPECT_NE(r.output.find(contains), std::string::npos) << r.output;
}

TEST(PlayLive, MidiInWithoutSequencerIsAOneLineError) {
  if (std::filesystem::exists("/dev/snd/seq")) GTEST_SKIP() << "this machine has a sequencer";
  for (const char* port : {"auto", "none", "20:0", "\"Some Keyboard\""}) {
    expect_one_line_error(run_tutti("play " + scene("piano.json") + " --midi-in " + port),
                          "ALSA sequencer: cannot open /dev/snd/seq");
  }
}

TEST(PlayLive, NoSuchPortIsAOneLineError) {
  if (!std::filesystem::exists("/dev/snd/seq")) GTEST_SKIP() << "no ALSA sequencer here";
  expect_one_line_error(run_tutti("play " + scene("piano.json") + " --midi-in NoSuchClient"),
                        "no port \"NoSuchClient\"");
}

TEST(PlayLive, SceneWithoutPianistIsAOneLineError) {
  expect_one_line_error(run_tutti("play " + scene("quartet.json") + " --keyboard-piano"),
                        "--keyboard-piano: quartet.json has no pianist");
  expect_one_line_error(run_tutti("play " + scene("quartet.json") + " --midi-in auto"),
                        "--midi-in: quartet.json has no pianist");
}

}  // namespace
