// SPDX-License-Identifier: MIT
#include <tutti/music/tempo_map.hpp>

#include <gtest/gtest.h>

namespace tutti::music {
namespace {

TEST(TempoMapTest, DefaultIs120BpmAt480Ppq) {
  const TempoMap map;
  EXPECT_EQ(map.ticks_per_quarter(), 480);
  EXPECT_DOUBLE_EQ(map.seconds_at(480), 0.5);
  EXPECT_DOUBLE_EQ(map.beats_at(960), 2.0);
  EXPECT_DOUBLE_EQ(map.bpm_at(0), 120.0);
}

TEST(TempoMapTest, TempoChangesAccumulate) {
  TempoMap map = TempoMap::with_ticks_per_quarter(100);
  map.set_tempo(200, 1'000'000.0);  // 60 BPM from beat 2
  map.set_tempo(400, 250'000.0);    // 240 BPM from beat 4
  EXPECT_DOUBLE_EQ(map.seconds_at(200), 1.0);
  EXPECT_DOUBLE_EQ(map.seconds_at(300), 2.0);
  EXPECT_DOUBLE_EQ(map.seconds_at(400), 3.0);
  EXPECT_DOUBLE_EQ(map.seconds_at(500), 3.25);
  EXPECT_DOUBLE_EQ(map.beats_at(500), 5.0);
  EXPECT_DOUBLE_EQ(map.bpm_at(450), 240.0);
  ASSERT_EQ(map.changes().size(), 3u);
  EXPECT_DOUBLE_EQ(map.changes()[2].seconds, 3.0);
}

TEST(TempoMapTest, ConversionsAreInverse) {
  TempoMap map = TempoMap::with_ticks_per_quarter(960);
  map.set_tempo(0, 600'000.0);
  map.set_tempo(3000, 420'000.0);
  map.set_tempo(7777, 900'000.0);
  for (double tick : {0.0, 1.0, 2999.0, 3000.0, 5000.5, 7777.0, 20000.0}) {
    EXPECT_NEAR(map.ticks_at_seconds(map.seconds_at(tick)), tick, 1e-6);
    EXPECT_NEAR(map.ticks_at_beats(map.beats_at(tick)), tick, 1e-6);
  }
  EXPECT_NEAR(map.seconds_at_beats(map.beats_at_seconds(4.2)), 4.2, 1e-9);
}

TEST(TempoMapTest, ChangesInAnyOrderAndReplacement) {
  TempoMap a = TempoMap::with_ticks_per_quarter(480);
  a.set_tempo(960, 1'000'000.0);
  a.set_tempo(480, 250'000.0);
  a.set_tempo(960, 500'000.0);  // replaces
  ASSERT_EQ(a.changes().size(), 3u);
  EXPECT_DOUBLE_EQ(a.seconds_at(960), 0.5 + 0.25);
  EXPECT_DOUBLE_EQ(a.seconds_at(1440), 0.75 + 0.5);
}

TEST(TempoMapTest, InvalidTempoIsIgnored) {
  TempoMap map;
  map.set_tempo(10, 0.0);
  map.set_tempo(20, -5.0);
  EXPECT_EQ(map.changes().size(), 1u);
}

TEST(TempoMapTest, SmpteTimeIgnoresTempoForSeconds) {
  TempoMap map = TempoMap::with_smpte(25, 40);  // 1000 ticks per second
  map.set_tempo(500, 1'000'000.0);
  EXPECT_TRUE(map.is_smpte());
  EXPECT_DOUBLE_EQ(map.seconds_at(1500), 1.5);
  // Beats still follow the tempo: 0.5 s at 120 BPM = 1 beat, then 1 s at 60 BPM = 1 beat.
  EXPECT_DOUBLE_EQ(map.beats_at(1500), 2.0);
  EXPECT_NEAR(map.ticks_at_beats(2.0), 1500.0, 1e-9);
}

TEST(TempoMapTest, DropFrameSmpteRunsAt2997) {
  const TempoMap map = TempoMap::with_smpte(29, 100);
  EXPECT_NEAR(map.seconds_at(2997), 1.0, 1e-12);
}

}  // namespace
}  // namespace tutti::music
