// SPDX-License-Identifier: MIT
#include <tutti/cli/fit_fingering_command.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <tutti/core/exit_codes.hpp>
#include <tutti/fingering_planner/cost_weights.hpp>
#include "testdata.hpp"

namespace tutti::cli {
namespace {

namespace fs = std::filesystem;

fs::path corpus(const std::string& name) {
  return test::source_dir() / "tests/data/fingering_corpus/train" / name;
}

struct FitRun {
  int code = -1;
  std::string out;
  std::string err;
};

FitRun fit(const FitFingeringOptions& options) {
  std::ostringstream out;
  std::ostringstream err;
  FitRun r;
  r.code = run_fit_fingering(options, out, err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

TEST(FitFingeringCommandTest, FitsFromThePaperPresetAndWritesLoadableWeights) {
  const fs::path output = test::unique_temp_path("weights.json");
  FitFingeringOptions options;
  options.inputs = {corpus("scale_major_C.txt"), corpus("scale_major_A.txt")};
  options.output = output;
  options.start = "paper";
  options.rounds = 1;
  const FitRun r = fit(options);
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.out.find("match "), std::string::npos) << r.out;
  auto weights = fingering_planner::load_cost_weights(output);
  ASSERT_TRUE(weights.ok()) << weights.error().message;
  // The same inputs give the same file, byte for byte.
  std::ifstream first(output);
  const std::string first_bytes((std::istreambuf_iterator<char>(first)), {});
  ASSERT_EQ(fit(options).code, kExitOk);
  std::ifstream second(output);
  const std::string second_bytes((std::istreambuf_iterator<char>(second)), {});
  EXPECT_EQ(first_bytes, second_bytes);
  fs::remove(output);
}

TEST(FitFingeringCommandTest, FilesWithoutMarksAndBadOptionsAreOneLineErrors) {
  const fs::path plain = test::unique_temp_path("plain.txt");
  std::ofstream(plain) << "//Version: PigletFormat 1.0\n0\t0.0\t0.5\tC4\t64\t80\t0\t0\n";
  FitFingeringOptions options;
  options.inputs = {plain};
  options.output = test::unique_temp_path("never.json");
  FitRun r = fit(options);
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_EQ(r.err, "error: " + plain.string() + ": no fingering marks to fit to\n");
  EXPECT_FALSE(fs::exists(options.output));

  options.inputs = {"/no/such/file.txt"};
  r = fit(options);
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_EQ(r.err, "error: /no/such/file.txt: no such file\n");

  options.inputs = {corpus("scale_major_C.txt")};
  options.rounds = 0;
  r = fit(options);
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_EQ(r.err.rfind("error: --rounds", 0), 0u);
  fs::remove(plain);
}

}  // namespace
}  // namespace tutti::cli
