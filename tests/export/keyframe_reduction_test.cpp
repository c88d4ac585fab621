// SPDX-License-Identifier: MIT
// Keyframe reduction: what is dropped is reproduced by glTF's interpolation between what is kept,
// within the tolerance; straight lines and constants collapse; the span cap holds.
#include <tutti/export/keyframe_reduction.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/quaternion.hpp>

namespace tutti::gltf_export {
namespace {

// The worst error of rebuilding every sample by linear interpolation between the kept keys.
float worst_vec3_error(const std::vector<glm::vec3>& samples,
                       const std::vector<std::uint32_t>& keys) {
  float worst = 0.0f;
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
    for (std::uint32_t k = keys[i]; k <= keys[i + 1]; ++k) {
      const float t = static_cast<float>(k - keys[i]) / static_cast<float>(keys[i + 1] - keys[i]);
      worst = std::max(
          worst, glm::length(glm::mix(samples[keys[i]], samples[keys[i + 1]], t) - samples[k]));
    }
  }
  return worst;
}

TEST(KeyframeReduction, AStraightLineKeepsItsEnds) {
  std::vector<glm::vec3> line;
  for (int k = 0; k < 100; ++k) line.push_back(glm::vec3(0.01f * static_cast<float>(k), 0, 0));
  const auto keys = reduce_vec3(line, 1e-5f, 256);
  EXPECT_EQ(keys, (std::vector<std::uint32_t>{0, 99}));
  EXPECT_FALSE(constant_vec3(line, 1e-5f));
}

TEST(KeyframeReduction, ASineIsRebuiltWithinTheTolerance) {
  std::vector<glm::vec3> wave;
  for (int k = 0; k < 600; ++k) {
    const float t = static_cast<float>(k) / 30.0f;
    wave.push_back(glm::vec3(0.05f * std::sin(0.5f * t), 0.02f * std::cos(0.3f * t), 0.0f));
  }
  const float tolerance = 5e-5f;
  const auto keys = reduce_vec3(wave, tolerance, 256);
  EXPECT_EQ(keys.front(), 0u);
  EXPECT_EQ(keys.back(), 599u);
  EXPECT_LE(worst_vec3_error(wave, keys), tolerance);
  EXPECT_LT(keys.size(), wave.size() / 2) << "a smooth curve needs far fewer keys than samples";
  EXPECT_GT(keys.size(), 20u) << "but not just its ends";
  // Tighter tolerance, more keys.
  EXPECT_GT(reduce_vec3(wave, 1e-6f, 256).size(), keys.size());
}

TEST(KeyframeReduction, TheSpanCapBoundsTheGapBetweenKeys) {
  const std::vector<glm::vec3> still(1000, glm::vec3(1, 2, 3));
  const auto keys = reduce_vec3(still, 1e-5f, 100);
  ASSERT_GE(keys.size(), 2u);
  for (std::size_t i = 1; i < keys.size(); ++i) EXPECT_LE(keys[i] - keys[i - 1], 100u);
  EXPECT_TRUE(constant_vec3(still, 1e-5f));
}

TEST(KeyframeReduction, ShortChannels) {
  EXPECT_TRUE(reduce_vec3({}, 1e-5f, 256).empty());
  const std::vector<glm::vec3> one{glm::vec3(1)};
  EXPECT_EQ(reduce_vec3(one, 1e-5f, 256), (std::vector<std::uint32_t>{0}));
  const std::vector<glm::vec3> two{glm::vec3(1), glm::vec3(2)};
  EXPECT_EQ(reduce_vec3(two, 1e-5f, 256), (std::vector<std::uint32_t>{0, 1}));
}

TEST(KeyframeReduction, RotationsAreRebuiltBySlerpWithinTheAngle) {
  std::vector<glm::quat> turns;
  for (int k = 0; k < 300; ++k) {
    const float t = static_cast<float>(k) / 30.0f;
    turns.push_back(
        glm::angleAxis(0.6f * std::sin(2.0f * t), glm::normalize(glm::vec3(1, 0.3f, 0))) *
        glm::angleAxis(0.2f * t, glm::vec3(0, 1, 0)));
  }
  const float tolerance = 1.745329e-4f;
  const auto keys = reduce_rotation(turns, tolerance, 256);
  float worst = 0.0f;
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
    for (std::uint32_t k = keys[i]; k <= keys[i + 1]; ++k) {
      const float t = static_cast<float>(k - keys[i]) / static_cast<float>(keys[i + 1] - keys[i]);
      worst = std::max(
          worst, rotation_angle(slerp_shortest(turns[keys[i]], turns[keys[i + 1]], t), turns[k]));
    }
  }
  EXPECT_LE(worst, tolerance * 1.01f);  // float rounding of the check itself
  EXPECT_LT(keys.size(), turns.size());
  // A turn at constant speed about one axis is one slerp.
  std::vector<glm::quat> spin;
  for (int k = 0; k < 50; ++k)
    spin.push_back(glm::angleAxis(0.02f * static_cast<float>(k), glm::vec3(0, 0, 1)));
  EXPECT_EQ(reduce_rotation(spin, tolerance, 256).size(), 2u);
}

TEST(KeyframeReduction, QAndMinusQAreTheSameRotation) {
  const glm::quat q = glm::angleAxis(0.4f, glm::vec3(0, 1, 0));
  EXPECT_NEAR(rotation_angle(q, -q), 0.0f, 1e-3f);
  const std::vector<glm::quat> flips{q, -q, q};
  EXPECT_TRUE(constant_rotation(flips, 1e-3f));
}

TEST(KeyframeReduction, WeightsKeepEveryTargetWithinTheTolerance) {
  // Two targets: one ramps, one pulses.
  std::vector<float> samples;
  for (int k = 0; k < 200; ++k) {
    samples.push_back(static_cast<float>(k) / 199.0f);
    samples.push_back(k > 80 && k < 120 ? 0.8f : 0.0f);
  }
  const auto keys = reduce_weights(samples, 2, 1e-3f, 256);
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
    for (std::uint32_t k = keys[i]; k <= keys[i + 1]; ++k) {
      const float t = static_cast<float>(k - keys[i]) / static_cast<float>(keys[i + 1] - keys[i]);
      for (std::size_t w = 0; w < 2; ++w) {
        const float a = samples[keys[i] * 2 + w];
        const float b = samples[keys[i + 1] * 2 + w];
        EXPECT_NEAR(a + (b - a) * t, samples[k * 2 + w], 1e-3f) << "frame " << k;
      }
    }
  }
  EXPECT_LE(keys.size(), 6u) << "a ramp and a step need a handful of keys";
  EXPECT_FALSE(constant_weights(samples, 2, 1e-3f));
  EXPECT_TRUE(constant_weights(std::vector<float>(10, 0.25f), 2, 1e-3f));
}

}  // namespace
}  // namespace tutti::gltf_export
