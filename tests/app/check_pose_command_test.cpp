// SPDX-License-Identifier: MIT
// `tutti check-pose`: the bundled quartet's figures as JSON, --check's exit code, and bad input
// as one error line with exit code 2.
#include <tutti/cli/check_pose_command.hpp>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <tutti/core/exit_codes.hpp>

#include "command_run.hpp"

namespace tutti::cli {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "scenes";

TEST(CheckPoseCommand, TheQuartetAsJson) {
  CheckPoseOptions o;
  o.scene = kScenes / "quartet.json";
  o.seconds = "0:4";
  o.json = true;
  o.check = true;
  const auto r = test::run_command(run_check_pose, o);
  ASSERT_EQ(r.code, kExitOk) << r.err << r.out;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc.at("frames"), 120);
  bool saw_buttons = false;
  for (const auto& m : doc.at("measures")) {
    if (m.at("name") == "Trumpet 1: pressing fingertip to its button top") {
      saw_buttons = true;
      EXPECT_LE(m.at("p95").get<double>(), 10.0);
      EXPECT_EQ(m.at("limit").at("of"), "p95");
    }
  }
  EXPECT_TRUE(saw_buttons);
}

TEST(CheckPoseCommand, BadInputIsOneLineAndExitTwo) {
  CheckPoseOptions missing;
  missing.scene = kScenes / "no_such_scene.json";
  auto r = test::run_command(run_check_pose, missing);
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("no_such_scene.json"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;

  CheckPoseOptions range;
  range.scene = kScenes / "quartet.json";
  range.seconds = "5:2";
  r = test::run_command(run_check_pose, range);
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("--seconds"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace tutti::cli
