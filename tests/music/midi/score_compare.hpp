// SPDX-License-Identifier: MIT
#pragma once
// What "the same music" means for a MIDI round trip (read -> write -> read): the same notes
// (key, ticks, velocities, channel, part), tempo map, time and key signatures, pedals, parts
// and length. Part ids and track numbers are not compared: the writer renumbers tracks
// (conductor first, then one track per part).

#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>
#include <vector>

#include <tutti/music/score.hpp>

namespace tutti::test {

inline std::vector<music::Note> notes_in_canonical_order(std::vector<music::Note> notes) {
  // Notes of one key starting together in one part may come back in another order.
  std::sort(notes.begin(), notes.end(), [](const music::Note& a, const music::Note& b) {
    return std::tie(a.onset_ticks, a.part, a.pitch, a.offset_ticks, a.velocity) <
           std::tie(b.onset_ticks, b.part, b.pitch, b.offset_ticks, b.velocity);
  });
  return notes;
}

inline void expect_same_music(const music::Score& expected, const music::Score& actual) {
  ASSERT_EQ(expected.tempo_map.ticks_per_quarter(), actual.tempo_map.ticks_per_quarter());
  ASSERT_EQ(expected.tempo_map.changes().size(), actual.tempo_map.changes().size());
  for (std::size_t i = 0; i < expected.tempo_map.changes().size(); ++i) {
    const auto& e = expected.tempo_map.changes()[i];
    const auto& a = actual.tempo_map.changes()[i];
    EXPECT_EQ(e.tick, a.tick) << "tempo change " << i;
    EXPECT_EQ(e.microseconds_per_quarter, a.microseconds_per_quarter) << "tempo change " << i;
  }

  ASSERT_EQ(expected.parts.size(), actual.parts.size());
  for (std::size_t i = 0; i < expected.parts.size(); ++i) {
    const auto& e = expected.parts[i];
    const auto& a = actual.parts[i];
    EXPECT_EQ(e.name, a.name) << "part " << i;
    EXPECT_EQ(e.program, a.program) << "part " << i;
    EXPECT_EQ(e.channel, a.channel) << "part " << i;
    EXPECT_EQ(e.percussion, a.percussion) << "part " << i;
  }

  const auto e_notes = notes_in_canonical_order(expected.notes);
  const auto a_notes = notes_in_canonical_order(actual.notes);
  ASSERT_EQ(e_notes.size(), a_notes.size());
  for (std::size_t i = 0; i < e_notes.size(); ++i) {
    const auto& e = e_notes[i];
    const auto& a = a_notes[i];
    ASSERT_EQ(std::tie(e.pitch, e.onset_ticks, e.offset_ticks, e.velocity, e.channel, e.part),
              std::tie(a.pitch, a.onset_ticks, a.offset_ticks, a.velocity, a.channel, a.part))
        << "note " << i << " (source index " << e.source_index << ")";
    EXPECT_EQ(e.release_velocity, a.release_velocity) << "note " << i;
  }

  ASSERT_EQ(expected.time_signatures.size(), actual.time_signatures.size());
  for (std::size_t i = 0; i < expected.time_signatures.size(); ++i) {
    const auto& e = expected.time_signatures[i];
    const auto& a = actual.time_signatures[i];
    EXPECT_EQ(std::tie(e.tick, e.numerator, e.denominator),
              std::tie(a.tick, a.numerator, a.denominator));
  }
  ASSERT_EQ(expected.key_signatures.size(), actual.key_signatures.size());
  for (std::size_t i = 0; i < expected.key_signatures.size(); ++i) {
    const auto& e = expected.key_signatures[i];
    const auto& a = actual.key_signatures[i];
    EXPECT_EQ(std::tie(e.tick, e.fifths, e.minor), std::tie(a.tick, a.fifths, a.minor));
  }
  ASSERT_EQ(expected.pedal_spans.size(), actual.pedal_spans.size());
  for (std::size_t i = 0; i < expected.pedal_spans.size(); ++i) {
    const auto& e = expected.pedal_spans[i];
    const auto& a = actual.pedal_spans[i];
    EXPECT_EQ(std::tie(e.part, e.onset_ticks, e.offset_ticks),
              std::tie(a.part, a.onset_ticks, a.offset_ticks));
  }
  EXPECT_EQ(expected.end_ticks, actual.end_ticks);
  EXPECT_DOUBLE_EQ(expected.duration_s(), actual.duration_s());
}

}  // namespace tutti::test
