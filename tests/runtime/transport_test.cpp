// SPDX-License-Identifier: MIT
// Transport over the simulated audio device (LiveOutput with driver "simulated"), whose
// position is a function of the host time passed in: every case is deterministic.
#include <tutti/runtime/transport.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <vector>

#include <tutti/audio/sound_font.hpp>

namespace tutti::runtime {
namespace {

constexpr double kFrame = 1.0 / 60.0;
// The simulated device queues 2 × 512 frames and reports whole periods: the clock trails the
// host by about that much.
constexpr double kTolerance = 0.06;

audio::SynthTimeline test_timeline(double tempo) {
  audio::SynthTimeline timeline;
  timeline.tempo_factor = tempo;
  for (int n = 0; n < 8; ++n) {
    const auto frame = static_cast<std::int64_t>(n * 48000 / tempo) / 64 * 64;
    timeline.events.push_back({frame, audio::SynthEventKind::note_on, 0, 60 + n, 90, 0, n});
    timeline.events.push_back({frame + 24000, audio::SynthEventKind::note_off, 0, 60 + n, 0, 0, n});
  }
  timeline.end_frame = static_cast<std::int64_t>(9 * 48000 / tempo);
  return timeline;
}

class TransportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto font = audio::find_sound_font();
    if (!font) {
      std::printf("SKIPPED: no sound font\n");
      GTEST_SKIP() << font.error().message;
    }
    font_ = *font;
  }

  std::unique_ptr<Transport> make(double start_s = 0.0, double end_s = 30.0, double tempo = 1.0) {
    TransportOptions options;
    options.start_s = start_s;
    options.end_s = end_s;
    options.tempo = tempo;
    auto transport = Transport::create(options, [this](double factor) {
      ++opened_;
      opened_tempos_.push_back(factor);
      audio::LiveOutputOptions live;
      live.sound_font = font_;
      live.driver = "simulated";
      return audio::LiveOutput::open(test_timeline(factor), live);
    });
    EXPECT_TRUE(transport) << transport.error().message;
    return transport ? std::move(*transport) : nullptr;
  }

  // Updates every 1/60 s from host_from to host_to; the times shown.
  static std::vector<double> run(Transport& transport, double host_from, double host_to) {
    std::vector<double> times;
    for (double h = host_from; h <= host_to + 1e-9; h += kFrame)
      times.push_back(transport.update(h));
    return times;
  }

  std::filesystem::path font_;
  int opened_ = 0;
  std::vector<double> opened_tempos_;
};

TEST_F(TransportTest, PausedAtTheStartUntilPlayed) {
  auto transport = make(2.0, 30.0);
  ASSERT_NE(transport, nullptr);
  ASSERT_NE(transport->output(), nullptr);
  EXPECT_TRUE(transport->output()->simulated());
  EXPECT_FALSE(transport->playing());
  for (double t : run(*transport, 0.0, 1.0)) EXPECT_DOUBLE_EQ(t, 2.0);
}

TEST_F(TransportTest, TimeIsMonotonicAndFollowsTheDeviceWhilePlaying) {
  auto transport = make();
  ASSERT_NE(transport, nullptr);
  transport->play(0.0);
  const std::vector<double> times = run(*transport, 0.0, 3.0);
  for (std::size_t i = 1; i < times.size(); ++i) EXPECT_GE(times[i], times[i - 1]) << i;
  EXPECT_NEAR(times.back(), 3.0, kTolerance);
}

TEST_F(TransportTest, PauseHoldsAndResumeContinues) {
  auto transport = make();
  ASSERT_NE(transport, nullptr);
  transport->play(0.0);
  const double at_pause = run(*transport, 0.0, 1.0).back();
  transport->pause(1.0);
  EXPECT_FALSE(transport->playing());
  for (double t : run(*transport, 1.0, 2.0)) EXPECT_DOUBLE_EQ(t, at_pause);
  transport->toggle(2.0);  // resume
  EXPECT_TRUE(transport->playing());
  const std::vector<double> after = run(*transport, 2.0, 3.0);
  EXPECT_GE(after.front(), at_pause);
  EXPECT_NEAR(after.back(), at_pause + 1.0, kTolerance);
}

TEST_F(TransportTest, SeekLandsAndPlaysOnFromThere) {
  auto transport = make();
  ASSERT_NE(transport, nullptr);
  transport->play(0.0);
  run(*transport, 0.0, 0.5);
  transport->seek(0.5, 10.0);
  EXPECT_DOUBLE_EQ(transport->update(0.5), 10.0);
  EXPECT_NEAR(run(*transport, 0.5, 1.5).back(), 11.0, kTolerance);
  // Backwards too, and clamped to the scene.
  transport->seek(1.5, 4.0);
  EXPECT_DOUBLE_EQ(transport->update(1.5), 4.0);
  transport->seek(1.5, -100.0);
  EXPECT_DOUBLE_EQ(transport->update(1.5), 0.0);
  // Paused: the seek lands and holds.
  transport->pause(1.5);
  transport->seek(1.5, 7.0);
  for (double t : run(*transport, 1.5, 2.0)) EXPECT_DOUBLE_EQ(t, 7.0);
}

TEST_F(TransportTest, LoopWrapsToItsStart) {
  auto transport = make();
  ASSERT_NE(transport, nullptr);
  ASSERT_TRUE(transport->set_loop(0.0, 2.0, 3.0));  // outside it: goes to its start
  EXPECT_DOUBLE_EQ(transport->time(), 2.0);
  transport->play(0.0);
  const std::vector<double> times = run(*transport, 0.0, 3.5);
  int wraps = 0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    EXPECT_GE(times[i], 2.0) << i;
    EXPECT_LT(times[i], 3.0) << i;
    if (i > 0 && times[i] < times[i - 1]) ++wraps;
  }
  EXPECT_EQ(wraps, 3);  // 3.5 s of a 1 s loop
  transport->clear_loop();
  EXPECT_FALSE(transport->loop().has_value());
  EXPECT_GT(run(*transport, 3.5, 5.0).back(), 3.0);
  EXPECT_FALSE(transport->set_loop(5.0, 4.0, 4.0));  // empty
}

TEST_F(TransportTest, LoopEndsSetOneAtATime) {
  auto transport = make();
  ASSERT_NE(transport, nullptr);
  transport->play(0.0);
  run(*transport, 0.0, 1.0);
  const double a = transport->time();
  transport->set_loop_start(1.0, a);
  EXPECT_FALSE(transport->loop().has_value());  // no end yet
  run(*transport, 1.0, 2.0);
  const double b = transport->time();
  transport->set_loop_end(2.0, b);
  ASSERT_TRUE(transport->loop().has_value());
  EXPECT_DOUBLE_EQ(transport->loop()->from_s, a);
  EXPECT_DOUBLE_EQ(transport->loop()->to_s, b);
  EXPECT_DOUBLE_EQ(transport->update(2.0), a);  // at B: round to A at once
}

TEST_F(TransportTest, PracticeTempoReopensTheSoundAndKeepsTheTime) {
  auto transport = make();
  ASSERT_NE(transport, nullptr);
  transport->play(0.0);
  const double before = run(*transport, 0.0, 1.0).back();
  ASSERT_TRUE(transport->set_tempo(1.0, 0.5));
  EXPECT_EQ(opened_, 2);
  EXPECT_DOUBLE_EQ(opened_tempos_.back(), 0.5);
  EXPECT_DOUBLE_EQ(transport->tempo(), 0.5);
  EXPECT_TRUE(transport->playing());
  const std::vector<double> after = run(*transport, 1.0, 3.0);
  EXPECT_GE(after.front(), before);
  EXPECT_NEAR(after.back(), before + 1.0, kTolerance);  // 2 s at half speed
  EXPECT_FALSE(transport->set_tempo(3.0, 0.0));
  EXPECT_FALSE(transport->set_tempo(3.0, 4.5));
  EXPECT_DOUBLE_EQ(transport->tempo(), 0.5);
}

TEST_F(TransportTest, StopsAtTheEnd) {
  auto transport = make(0.0, 1.0);
  ASSERT_NE(transport, nullptr);
  transport->play(0.0);
  const std::vector<double> times = run(*transport, 0.0, 2.0);
  EXPECT_DOUBLE_EQ(times.back(), 1.0);
  EXPECT_FALSE(transport->playing());
  transport->play(2.0);  // from the top again
  EXPECT_DOUBLE_EQ(transport->time(), 0.0);
}

TEST(TransportOptionsTest, SilentTransportRunsOnTheHostClock) {
  TransportOptions options;
  options.end_s = 10.0;
  auto transport = Transport::create(options);
  ASSERT_TRUE(transport) << transport.error().message;
  EXPECT_EQ((*transport)->output(), nullptr);
  (*transport)->play(5.0);
  double t = 0.0;
  for (double h = 5.0; h <= 7.0 + 1e-9; h += kFrame) t = (*transport)->update(h);
  EXPECT_NEAR(t, 2.0, 0.01);
}

TEST(TransportOptionsTest, BadOptionsAreErrors) {
  TransportOptions options;
  options.start_s = 5.0;
  options.end_s = 5.0;
  EXPECT_FALSE(Transport::create(options));
  options.end_s = 10.0;
  options.tempo = 0.0;
  EXPECT_FALSE(Transport::create(options));
  options.tempo = 1.0;
  auto failing = Transport::create(
      options,
      [](double) -> Result<std::unique_ptr<audio::LiveOutput>> { return Error{"no sound"}; });
  ASSERT_FALSE(failing);
  EXPECT_EQ(failing.error().message, "no sound");
}

}  // namespace
}  // namespace tutti::runtime
