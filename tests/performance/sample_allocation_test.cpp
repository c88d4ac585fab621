// SPDX-License-Identifier: MIT
// Performance::sample allocates nothing once warmed up: every bundled scene sampled over its whole
// piece once (the outputs grow to their largest), then again at other times, counting every
// global operator new. Its own program: tests/allocation_counter.cpp replaces operator new.
#include <tutti/performance/performance.hpp>

#include <gtest/gtest.h>

#include <filesystem>

#include "allocation_counter.hpp"

namespace tutti::performance {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "scenes";

class SampleAllocation : public ::testing::TestWithParam<const char*> {};

TEST_P(SampleAllocation, NoneAfterWarmUp) {
  Options options;
  options.asset_dir = TUTTI_PERFORMANCE_TEST_ASSET_DIR;
  auto opened = Performance::open(kScenes / GetParam(), options);
  ASSERT_TRUE(opened) << opened.error().message;
  Performance& performance = **opened;
  const double from_s = performance.start_s();
  const double to_s = performance.end_s();
  // The counter sees sampling's allocations: a fresh output grows on its first sample.
  Sample sample;
  const long cold = test::allocation_count();
  performance.sample(from_s, sample);
  EXPECT_GT(test::allocation_count() - cold, 0);
  for (double t = from_s; t <= to_s; t += 0.1) performance.sample(t, sample);
  const long before = test::allocation_count();
  int samples = 0;
  for (double t = from_s + 0.05; t <= to_s; t += 0.2, ++samples) performance.sample(t, sample);
  const long allocations = test::allocation_count() - before;
  EXPECT_GT(samples, 20);
  EXPECT_EQ(allocations, 0) << GetParam() << ": " << allocations << " allocations in " << samples
                            << " samples";
}

INSTANTIATE_TEST_SUITE_P(BundledScenes, SampleAllocation,
                         ::testing::Values("piano.json", "piano_beginner.json", "quartet.json",
                                           "quintet.json", "low_brass.json"));

}  // namespace
}  // namespace tutti::performance
