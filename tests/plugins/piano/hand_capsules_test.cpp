// SPDX-License-Identifier: MIT
#include <tutti/piano/hand_capsules.hpp>

#include <vector>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

namespace tutti::piano {
namespace {

glm::mat4 at(float x, float y, float z) { return glm::translate(glm::mat4(1.0f), {x, y, z}); }

TEST(HandCapsules, SegmentDistanceCoversCrossingParallelAndEndToEnd) {
  // Crossing 10 mm apart, one above the other.
  EXPECT_NEAR(segment_distance({-1, 0, 0}, {1, 0, 0}, {0, -1, 0.01f}, {0, 1, 0.01f}), 0.01, 1e-6);
  // Parallel, overlapping along their length.
  EXPECT_NEAR(segment_distance({0, 0, 0}, {1, 0, 0}, {0.5f, 0.02f, 0}, {1.5f, 0.02f, 0}), 0.02, 1e-6);
  // End to end along one line: the gap between the ends.
  EXPECT_NEAR(segment_distance({0, 0, 0}, {1, 0, 0}, {1.5f, 0, 0}, {2, 0, 0}), 0.5, 1e-6);
  // A point (zero-length segment) against a segment.
  EXPECT_NEAR(segment_distance({0.5f, 0.3f, 0}, {0.5f, 0.3f, 0}, {0, 0, 0}, {1, 0, 0}), 0.3, 1e-6);
}

TEST(HandCapsules, EveryBoneWithBothEndsAndThePalm) {
  // Five fingers side by side 20 mm apart, each three bones of 20 mm and a tip, along -z.
  std::vector<glm::mat4> world;
  FingerChains chains{};
  for (int f = 0; f < 5; ++f) {
    for (int j = 0; j < 4; ++j) {
      chains[static_cast<std::size_t>(f)][static_cast<std::size_t>(j)] = static_cast<int>(world.size());
      world.push_back(at(0.02f * static_cast<float>(f), 0.0f, -0.02f * static_cast<float>(j)));
    }
  }
  chains[2][3] = -1;  // the middle finger's tip is missing: its last bone is left out
  std::vector<HandCapsule> capsules{{}, {}};
  collect_hand_capsules(chains, world, capsules);
  ASSERT_EQ(capsules.size(), 15u);  // 5 x 3 bones less one, and the palm
  EXPECT_EQ(capsules.back().finger, kPalm);
  EXPECT_FLOAT_EQ(capsules.back().radius, kPalmRadiusM);
  EXPECT_FLOAT_EQ(capsules.back().b.x - capsules.back().a.x, 0.06f);  // index to little knuckle
  EXPECT_STREQ(capsules[0].name, "thumb's first bone");

  // A node index past the matrices counts as missing, not as memory to read.
  chains[0][0] = 1000;
  collect_hand_capsules(chains, world, capsules);
  EXPECT_EQ(capsules.size(), 14u);
}

TEST(HandCapsules, OverlapIsTheRadiiLessTheDistance) {
  const HandCapsule one{{0, 0, 0}, {0, 0, -0.02f}, 0.008f, 0, "one"};
  HandCapsule other{{0.012f, 0, 0}, {0.012f, 0, -0.02f}, 0.007f, 1, "other"};
  EXPECT_NEAR(overlap_m(one, other), 0.003, 1e-6);
  other.a.x = other.b.x = 0.02f;
  EXPECT_NEAR(overlap_m(one, other), -0.005, 1e-6);
}

}  // namespace
}  // namespace tutti::piano
