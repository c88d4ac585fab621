// SPDX-License-Identifier: MIT
// Performance::sample allocates nothing once warmed up, nor does sampling in a caller's own
// context: every bundled scene sampled over its whole piece once (the outputs grow to their
// largest), then again at other times, counting every global operator new. Its own program: tests/allocation_counter.cpp replaces operator new.
#include <tutti/performance/performance.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "allocation_counter.hpp"
#include "character_fixtures.hpp"
#include "scratch_dir.hpp"

namespace tutti::performance {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "scenes";

// Samples `performance` over its piece once, then at other times, and expects no allocation in
// the second pass.
void expect_no_allocation_after_warm_up(Performance& performance, const std::string& what) {
  const double from_s = performance.start_s();
  const double to_s = performance.end_s();
  // The counter sees sampling's allocations: a fresh output grows on its first sample.
  Sample sample;
  const long cold = test::allocation_count();
  performance.sample(from_s, sample);
  EXPECT_GT(test::allocation_count() - cold, 0) << what;
  for (double t = from_s; t <= to_s; t += 0.1) performance.sample(t, sample);
  const long before = test::allocation_count();
  int samples = 0;
  for (double t = from_s + 0.05; t <= to_s; t += 0.2, ++samples) performance.sample(t, sample);
  const long allocations = test::allocation_count() - before;
  EXPECT_GT(samples, 20) << what;
  EXPECT_EQ(allocations, 0) << what << ": " << allocations << " allocations in " << samples
                            << " samples";

  // The same through a caller's own context (sample(context, t, out), the threads' path).
  SampleContext context = performance.make_context();
  Sample own;
  for (double t = from_s; t <= to_s; t += 0.1) performance.sample(context, t, own);
  const long before_context = test::allocation_count();
  for (double t = from_s + 0.05; t <= to_s; t += 0.2) performance.sample(context, t, own);
  EXPECT_EQ(test::allocation_count() - before_context, 0) << what << ", in a context";
}

class SampleAllocation : public ::testing::TestWithParam<const char*> {};

TEST_P(SampleAllocation, NoneAfterWarmUp) {
  Options options;
  options.asset_dir = TUTTI_PERFORMANCE_TEST_ASSET_DIR;
  auto opened = Performance::open(kScenes / GetParam(), options);
  ASSERT_TRUE(opened) << opened.error().message;
  expect_no_allocation_after_warm_up(**opened, GetParam());
}

INSTANTIATE_TEST_SUITE_P(BundledScenes, SampleAllocation,
                         ::testing::Values("piano.json", "piano_beginner.json", "piano_duo.json", "organ.json", "quartet.json",
                                           "quintet.json", "low_brass.json"));

// The pianist as a user's character playing with a user's hand models (the stand-ins' poses
// retargeted every frame).
TEST(SampleAllocation, AUsersCharacterWithUserHandsNoneAfterWarmUp) {
  if (!test::has_blender()) GTEST_SKIP() << "no blender";
  test::ScratchDir dir;
  ASSERT_TRUE(test::make_character_fixtures(dir.path()));
  nlohmann::json piano = nlohmann::json::parse(std::ifstream(kScenes / "piano.json"));
  piano["music"] = (kScenes.parent_path() / "music" / piano["music"].get<std::string>()).string();
  piano["pianist"]["character"] = "unreal_cm_t.glb";
  piano["pianist"]["hands"] = "hands_only.glb";
  std::ofstream(dir.path() / "piano.json") << piano.dump(1);
  Options options;
  options.asset_dir = TUTTI_PERFORMANCE_TEST_ASSET_DIR;
  auto opened = Performance::open(dir.path() / "piano.json", options);
  ASSERT_TRUE(opened) << opened.error().message;
  expect_no_allocation_after_warm_up(**opened, "user character with user hands");
}

}  // namespace
}  // namespace tutti::performance
