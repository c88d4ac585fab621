// SPDX-License-Identifier: MIT
#include <tutti/components/note.hpp>

#include <gtest/gtest.h>

TEST(NoteComponent, DefaultsAreMiddleCSilentUnassigned) {
  const tutti::components::Note n;
  EXPECT_EQ(n.pitch, 60);
  EXPECT_GE(n.offset_s, n.onset_s);
  EXPECT_GE(n.offset_beats, n.onset_beats);
  EXPECT_GE(n.velocity, 1);
  EXPECT_LE(n.velocity, 127);
  EXPECT_EQ(n.finger, 0);
  EXPECT_EQ(n.score_index, -1);
  EXPECT_TRUE(n.performer.is_null());
  EXPECT_FALSE(n.sounding);
}
