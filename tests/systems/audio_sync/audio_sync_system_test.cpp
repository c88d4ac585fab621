// SPDX-License-Identifier: MIT
// The sync phase's system: the frame's time from the clock the consumer chose.
#include <tutti/audio_sync/audio_sync_system.hpp>

#include <gtest/gtest.h>

namespace tutti::audio_sync {
namespace {

double time_after_sync(ecs::World& world, const ecs::FrameTime& requested) {
  ecs::Schedule schedule;
  register_audio_sync(schedule);
  double seen = -1.0;
  schedule.add(ecs::Phase::evaluate, "probe",
               [&seen](ecs::World&, const ecs::FrameTime& frame) { seen = frame.t_s; });
  schedule.run(world, requested);
  return seen;
}

TEST(AudioSyncSystem, WithoutAClockTheRequestedTimeStays) {
  ecs::World world;
  EXPECT_EQ(time_after_sync(world, {3.25, 0.0}), 3.25);
  world.set_resource(FrameClock{});  // Source::given
  EXPECT_EQ(time_after_sync(world, {4.5, 0.0}), 4.5);
}

TEST(AudioSyncSystem, OfflineFrameKIsExactlyTheRendersFrameTime) {
  ecs::World world;
  FrameClock clock;
  clock.source = FrameClock::Source::offline;
  clock.start_s = 2.0;
  clock.fps = 30;
  clock.tempo_factor = 0.75;
  for (std::int64_t k : {0, 1, 29, 1000}) {
    clock.frame = k;
    world.set_resource(clock);
    EXPECT_EQ(time_after_sync(world, {99.0, 0.0}), offline_frame_time(2.0, 30, k, 0.75)) << k;
    EXPECT_DOUBLE_EQ(world.resource<ecs::FrameTime>()->dt_s, 0.75 / 30);
  }
}

TEST(AudioSyncSystem, LiveTheFrameFollowsTheAudioClock) {
  AudioClock audio({.sample_rate = 48000, .tempo_factor = 1.0});
  audio.start(100.0, 5.0);
  const double shown = audio.update(100.5, {24000, 0});  // half a second played
  ecs::World world;
  FrameClock clock;
  clock.source = FrameClock::Source::live;
  clock.clock = &audio;
  world.set_resource(clock);
  EXPECT_EQ(time_after_sync(world, {0.0, 1.0 / 60}), shown);
  EXPECT_GT(shown, 5.0);
}

}  // namespace
}  // namespace tutti::audio_sync
