// SPDX-License-Identifier: MIT
// Scripted events arrive at their times, in order, each once.
#include <tutti/live/scripted_source.hpp>

#include <gtest/gtest.h>

namespace tutti::live {
namespace {

TEST(ScriptedSource, DeliversEventsWhenTheirTimeHasCome) {
  ScriptedSource source(
      {{0.5, 64, 90, true}, {0.1, 60, 80, true}, {0.5, 67, 70, true}, {0.9, 60, 0, false}});
  std::vector<LiveNoteEvent> out;
  source.poll(0.0, out);
  EXPECT_TRUE(out.empty());
  source.poll(0.1, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].key, 60);
  source.poll(0.6, out);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[1].key, 64);  // same time: the script's order
  EXPECT_EQ(out[2].key, 67);
  EXPECT_FALSE(source.done());
  source.poll(10.0, out);
  EXPECT_EQ(out.size(), 4u);
  EXPECT_TRUE(source.done());
  source.poll(20.0, out);
  EXPECT_EQ(out.size(), 4u);
}

}  // namespace
}  // namespace tutti::live
