// SPDX-License-Identifier: MIT
// `tutti play` as a process: bad options and missing files fail with one line before any window
// opens; under a display (ctest runs this program under `xvfb-run`) 20 frames of the piano scene
// play on the simulated audio device, validated, and the last frame is written as a PNG (kept
// under build/.../tests/runtime/artifacts/).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

std::vector<std::uint8_t> decode_png_for_test(const std::vector<std::uint8_t>& png, int& width,
                                              int& height);

namespace {

struct ProcessResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

ProcessResult run_tutti(const std::string& arguments, const std::string& environment = "") {
  const std::string command =
      environment + " " + std::string(TUTTI_EXE) + " " + arguments + " 2>&1";
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

int count_lines(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += c == '\n';
  return lines;
}

void expect_one_line_error(const ProcessResult& r, const std::string& contains,
                           int exit_code = 2) {
  EXPECT_EQ(r.exit_code, exit_code) << r.output;
  EXPECT_EQ(count_lines(r.output), 1) << r.output;
  EXPECT_EQ(r.output.rfind("error: ", 0), 0u) << r.output;
  EXPECT_NE(r.output.find(contains), std::string::npos) << r.output;
}

bool have_display() {
  const char* display = std::getenv("DISPLAY");
  return display != nullptr && display[0] != '\0';
}

TEST(PlayCommandTest, TempoZeroIsAnError) {
  expect_one_line_error(run_tutti("play " + scene("piano.json") + " --tempo 0"), "--tempo 0");
  expect_one_line_error(run_tutti("play " + scene("piano.json") + " --tempo 5"), "--tempo 5");
}

TEST(PlayCommandTest, MissingSceneIsAnError) {
  expect_one_line_error(run_tutti("play /nonexistent/scene.json"), "/nonexistent/scene.json");
}

TEST(PlayCommandTest, BadOptionsAreErrors) {
  expect_one_line_error(run_tutti("play " + scene("piano.json") + " --loop 5:2"), "--loop");
  expect_one_line_error(run_tutti("play " + scene("piano.json") + " --start soon"), "--start");
  expect_one_line_error(run_tutti("play " + scene("piano.json") + " --camera nosuch"), "nosuch");
  expect_one_line_error(run_tutti("play " + scene("piano.json") + " --screenshot x.jpg"), ".png");
  expect_one_line_error(run_tutti("play " + scene("piano.json") + " --frame-count -1"),
                        "--frame-count");
  expect_one_line_error(run_tutti("play " + scene("piano.json") + " --size 100x100"),
                        "--size \"100x100\": expected WxH, from 320x240 to 7680x4320");
  expect_one_line_error(run_tutti("play " + scene("piano.json") + " --quality best"), "--quality");
  expect_one_line_error(run_tutti("play " + scene("piano.json") + " --render-scale 2"),
                        "--render-scale");
}

// The machine lacks something (exit 3), not the user's input (2).
TEST(PlayCommandTest, NoDisplayIsAnEnvironmentError) {
  expect_one_line_error(run_tutti("play " + scene("piano.json") + " --frame-count 1",
                                  "env -u DISPLAY -u WAYLAND_DISPLAY"),
                        "no display", 3);
}

TEST(PlayCommandTest, PlaysThePianoSceneAndWritesAScreenshot) {
  if (!have_display()) {
    std::printf("SKIPPED: no display\n");
    GTEST_SKIP() << "DISPLAY is not set";
  }
  const std::filesystem::path dir = TUTTI_RUNTIME_ARTIFACT_DIR;
  std::filesystem::create_directories(dir);
  const std::filesystem::path png = dir / "play_piano.png";
  std::filesystem::remove(png);
  const ProcessResult r =
      run_tutti("play " + scene("piano.json") + " --frame-count 20 --screenshot " + png.string() +
                " --audio-driver simulated --validate");
  if (r.output.find("no Vulkan device found") != std::string::npos) {
    std::printf("SKIPPED: no Vulkan device\n");
    GTEST_SKIP() << r.output;
  }
  std::printf("%s", r.output.c_str());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("play: 20 frames"), std::string::npos) << r.output;
  std::ifstream in(png, std::ios::binary);
  ASSERT_TRUE(in) << png;
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                        std::istreambuf_iterator<char>());
  int width = 0;
  int height = 0;
  const std::vector<std::uint8_t> rgba = decode_png_for_test(bytes, width, height);
  ASSERT_FALSE(rgba.empty());
  EXPECT_GT(width, 0);
  std::size_t lit = 0;
  for (std::size_t i = 0; i < rgba.size(); i += 4) {
    if (rgba[i] > 40 || rgba[i + 1] > 40 || rgba[i + 2] > 40) ++lit;
  }
  EXPECT_GT(lit, rgba.size() / 4 / 20) << "fewer than 5 % of the pixels are not black";
}

}  // namespace
