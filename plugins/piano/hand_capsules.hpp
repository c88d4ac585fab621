// SPDX-License-Identifier: MIT
#pragma once
// A pianist's hand as capsules: each finger's three bones, knuckle to tip, as thick as its pad,
// and the palm across the knuckles. One shape for the pose that keeps the hands apart
// (hands_apart.hpp) and for check-pose's measure of one hand inside the other.

#include <array>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace tutti::piano {

struct HandCapsule {
  glm::vec3 a{0.0f};
  glm::vec3 b{0.0f};
  float radius = 0.0f;
  int finger = 0;  // 0 = thumb .. 4 = little finger; kPalm for the palm
  const char* name = "";
};
inline constexpr int kPalm = 5;
// The palm's half thickness across the knuckles.
inline constexpr float kPalmRadiusM = 0.011f;

// Per finger (thumb first): its three bones' nodes and its tip node, -1 where the model has none.
using FingerChains = std::array<std::array<int, 4>, 5>;

// The capsules of a hand posed with `world` (one matrix per node), appended to `out` (cleared
// first). A bone whose node or next node is -1 is left out; so is the palm without the index's
// and the little finger's first bones.
void collect_hand_capsules(const FingerChains& chains, std::span<const glm::mat4> world,
                           std::vector<HandCapsule>& out);

// The closest distance between segments [p1, q1] and [p2, q2] (Ericson, Real-Time Collision
// Detection, 5.1.9).
double segment_distance(const glm::vec3& p1, const glm::vec3& q1, const glm::vec3& p2,
                        const glm::vec3& q2);

// How deep two capsules overlap (metres; <= 0 apart).
double overlap_m(const HandCapsule& one, const HandCapsule& other);

}  // namespace tutti::piano
