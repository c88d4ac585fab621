// SPDX-License-Identifier: MIT
// `tutti export`: a .glb of the scene with one clip per performer plus the whole scene; the range
// options; one-line errors for bad input, and a failed export never touches an existing file.
#include <tutti/cli/export_command.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include <tutti/core/exit_codes.hpp>
#include "command_run.hpp"
#include <tutti/core/file_io.hpp>
#include "testdata.hpp"

namespace tutti::cli {
namespace {

namespace fs = std::filesystem;

using test::CommandRun;

CommandRun run(const ExportOptions& options) { return test::run_command(run_export, options); }

const fs::path kScenes = tutti::test::source_dir() / "content" / "scenes";

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "tutti-export-command-test";
  fs::create_directories(dir);
  return dir / name;
}

TEST(ExportCommand, WritesTheClipsAndSaysWhatItWrote) {
  ExportOptions options;
  options.scene = kScenes / "quartet.json";
  options.output = scratch("quartet.glb");
  options.seconds = "4:6";
  options.fps = 24;
  options.json_summary = true;
  const CommandRun r = run(options);
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto summary = nlohmann::json::parse(r.out);
  EXPECT_EQ(summary["fps"], 24);
  EXPECT_EQ(summary["frames"], 48);
  EXPECT_EQ(summary["clips"].size(), 5u);
  EXPECT_EQ(summary["clips"][4]["name"], "scene");
  auto bytes = read_file_bytes(options.output);
  ASSERT_TRUE(bytes);
  EXPECT_EQ(bytes->size(), summary["bytes"].get<std::size_t>());
  EXPECT_EQ(std::string(bytes->begin(), bytes->begin() + 4), "glTF");

  options.json_summary = false;
  const CommandRun text = run(options);
  ASSERT_EQ(text.code, kExitOk) << text.err;
  EXPECT_NE(text.out.find("clip \"Trumpet 1\""), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("tolerance 0.05 mm, 0.01 deg"), std::string::npos) << text.out;
}

TEST(ExportCommand, BadInputIsOneLineAndLeavesTheOldFile) {
  const fs::path existing = scratch("keep.glb");
  std::ofstream(existing) << "the user's file";
  const auto expect_error = [&](ExportOptions options, const std::string& part) {
    const CommandRun r = run(options);
    EXPECT_EQ(r.code, kExitBadInput);
    EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    auto kept = read_file_bytes(existing);
    ASSERT_TRUE(kept);
    EXPECT_EQ(std::string(kept->begin(), kept->end()), "the user's file");
  };
  ExportOptions o;
  o.scene = kScenes / "piano.json";
  o.output = existing;
  ExportOptions bad = o;
  bad.output = scratch("out.gltf");
  expect_error(bad, "the output is a .glb file");
  bad = o;
  bad.fps = 1000;
  expect_error(bad, "--fps: must be in [1, 240]");
  bad = o;
  bad.scene = kScenes / "no_such_scene.json";
  expect_error(bad, "no_such_scene.json");
  bad = o;
  bad.seconds = "50:60";
  expect_error(bad, "");
  bad = o;
  bad.seconds = "1:2";
  bad.frames = "0:10";
  expect_error(bad, "give one");
  bad = o;
  bad.seconds = "x";
  expect_error(bad, "");
}

}  // namespace
}  // namespace tutti::cli
