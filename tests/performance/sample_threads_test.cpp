// SPDX-License-Identifier: MIT
// One plan, many threads: four threads, each with its own context, sample one performance at
// different times at once and get, byte for byte, what one thread gets (ozz-animation's shared
// const animation and per-caller context). Built again under ThreadSanitizer in CI
// (CMakePresets.json "tsan"), which finds any write the threads share.
#include <tutti/performance/performance.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <thread>
#include <vector>

namespace tutti::performance {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "scenes";

// Every model's root, local transforms and morph weights, as bytes.
std::vector<std::uint8_t> bytes_of(const Sample& sample) {
  std::vector<std::uint8_t> out;
  const auto put = [&out](const void* data, std::size_t size) {
    const auto* first = static_cast<const std::uint8_t*>(data);
    out.insert(out.end(), first, first + size);
  };
  for (const ModelPose& model : sample.models) {
    put(&model.root, sizeof(Trs));
    put(model.local.data(), model.local.size() * sizeof(Trs));
    put(model.morph_weights.data(), model.morph_weights.size() * sizeof(float));
  }
  return out;
}

class SampleThreads : public ::testing::TestWithParam<const char*> {};

TEST_P(SampleThreads, FourThreadsSampleOnePlanAsOneThreadDoes) {
  auto opened = Performance::open(kScenes / GetParam());
  ASSERT_TRUE(opened) << opened.error().message;
  const Performance& performance = **opened;
  constexpr int kTimes = 48;
  constexpr int kThreads = 4;
  std::vector<double> times;
  const double span = performance.end_s() - performance.start_s();
  for (int i = 0; i < kTimes; ++i) times.push_back(performance.start_s() + span * (i + 0.5) / kTimes);

  // One thread, in time order.
  std::vector<std::vector<std::uint8_t>> expected;
  {
    SampleContext context = performance.make_context();
    Sample sample;
    for (const double t : times) {
      performance.sample(context, t, sample);
      expected.push_back(bytes_of(sample));
    }
  }
  // Four threads at once, each its share of the times and in reverse order.
  std::vector<SampleContext> contexts;
  for (int k = 0; k < kThreads; ++k) contexts.push_back(performance.make_context());
  std::vector<std::vector<std::uint8_t>> got(times.size());
  std::vector<std::thread> threads;
  for (int k = 0; k < kThreads; ++k) {
    threads.emplace_back([&, k] {
      Sample sample;
      for (int i = kTimes - 1 - k; i >= 0; i -= kThreads) {
        performance.sample(contexts[static_cast<std::size_t>(k)], times[static_cast<std::size_t>(i)],
                           sample);
        got[static_cast<std::size_t>(i)] = bytes_of(sample);
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (std::size_t i = 0; i < times.size(); ++i) {
    ASSERT_FALSE(expected[i].empty());
    EXPECT_EQ(got[i], expected[i]) << GetParam() << " at " << times[i] << " s";
  }
  // And what the performance's own sample(t) gives.
  Sample own;
  (*opened)->sample(times[7], own);
  EXPECT_EQ(bytes_of(own), expected[7]);
}

INSTANTIATE_TEST_SUITE_P(BundledScenes, SampleThreads,
                         ::testing::Values("piano.json", "piano_beginner.json", "piano_duo.json", "organ.json", "quartet.json",
                                           "quintet.json", "low_brass.json"));

TEST(SampleThreads, AContextRunsOnlyOnThePerformanceThatMadeIt) {
  auto a = Performance::open(kScenes / "low_brass.json");
  auto b = Performance::open(kScenes / "low_brass.json");
  ASSERT_TRUE(a && b);
  SampleContext from_a = (*a)->make_context();
  Sample sample;
  EXPECT_THROW((*b)->sample(from_a, 1.0, sample), std::invalid_argument);
  SampleContext moved = std::move(from_a);
  EXPECT_THROW((*a)->sample(from_a, 1.0, sample), std::invalid_argument);  // NOLINT: moved from
  EXPECT_NO_THROW((*a)->sample(moved, 1.0, sample));
}

}  // namespace
}  // namespace tutti::performance
