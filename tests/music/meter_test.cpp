// SPDX-License-Identifier: MIT
// Bars and beat lengths from time signatures.
#include <tutti/music/meter.hpp>

#include <gtest/gtest.h>

namespace tutti::music {
namespace {

// A score at 480 ticks per quarter with the given (tick, numerator, denominator) signatures.
Score with_signatures(std::initializer_list<TimeSignature> signatures) {
  Score score;
  score.tempo_map = TempoMap::with_ticks_per_quarter(480);
  for (const TimeSignature& ts : signatures) score.time_signatures.push_back(ts);
  return score;
}

TEST(Meter, BarsCountFromOneAndFollowChanges) {
  const Score plain = with_signatures({});
  EXPECT_EQ(bar_at_beats(plain, 0.0), 1);
  EXPECT_EQ(bar_at_beats(plain, 3.99), 1);
  EXPECT_EQ(bar_at_beats(plain, 4.0), 2);
  // 3/4 for two bars (6 quarters), then 6/8 (3 quarters per bar).
  const Score changing = with_signatures({{0, 0.0, 3, 4}, {6 * 480, 0.0, 6, 8}});
  EXPECT_EQ(bar_at_beats(changing, 2.9), 1);
  EXPECT_EQ(bar_at_beats(changing, 3.0), 2);
  EXPECT_EQ(bar_at_beats(changing, 6.0), 3);
  EXPECT_EQ(bar_at_beats(changing, 8.9), 3);
  EXPECT_EQ(bar_at_beats(changing, 9.0), 4);
}

TEST(Meter, BeatLengthIsTheDenominatorExceptInCompoundMeters) {
  EXPECT_DOUBLE_EQ(beat_length_at(with_signatures({}), 10.0), 1.0);
  EXPECT_DOUBLE_EQ(beat_length_at(with_signatures({{0, 0.0, 3, 4}}), 1.0), 1.0);
  EXPECT_DOUBLE_EQ(beat_length_at(with_signatures({{0, 0.0, 2, 2}}), 1.0), 2.0);
  EXPECT_DOUBLE_EQ(beat_length_at(with_signatures({{0, 0.0, 3, 8}}), 1.0), 0.5);
  EXPECT_DOUBLE_EQ(beat_length_at(with_signatures({{0, 0.0, 6, 8}}), 1.0), 1.5);
  EXPECT_DOUBLE_EQ(beat_length_at(with_signatures({{0, 0.0, 12, 16}}), 1.0), 0.75);
  const Score changing = with_signatures({{0, 0.0, 4, 4}, {8 * 480, 0.0, 6, 8}});
  EXPECT_DOUBLE_EQ(beat_length_at(changing, 7.9), 1.0);
  EXPECT_DOUBLE_EQ(beat_length_at(changing, 8.0), 1.5);
}

}  // namespace
}  // namespace tutti::music
