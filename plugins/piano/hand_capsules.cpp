// SPDX-License-Identifier: MIT
#include <tutti/piano/hand_capsules.hpp>

#include <algorithm>
#include <cstddef>

#include <tutti/stage/fingertip_reach.hpp>

namespace tutti::piano {

void collect_hand_capsules(const FingerChains& chains, std::span<const glm::mat4> world,
                           std::vector<HandCapsule>& out) {
  static constexpr const char* kBoneNames[5][3] = {
      {"thumb's first bone", "thumb's middle bone", "thumb's tip"},
      {"index's first bone", "index's middle bone", "index's tip"},
      {"middle's first bone", "middle's middle bone", "middle's tip"},
      {"ring's first bone", "ring's middle bone", "ring's tip"},
      {"little's first bone", "little's middle bone", "little's tip"}};
  out.clear();
  const auto at = [&](int node) -> glm::vec3 {
    return glm::vec3(world[static_cast<std::size_t>(node)][3]);
  };
  const auto known = [&](int node) {
    return node >= 0 && static_cast<std::size_t>(node) < world.size();
  };
  for (std::size_t f = 0; f < 5; ++f) {
    for (std::size_t j = 0; j < 3; ++j) {
      if (!known(chains[f][j]) || !known(chains[f][j + 1])) continue;
      out.push_back({at(chains[f][j]), at(chains[f][j + 1]), stage::kFingertipPadRadiusM[f],
                     static_cast<int>(f), kBoneNames[f][j]});
    }
  }
  if (known(chains[1][0]) && known(chains[4][0])) {
    out.push_back({at(chains[1][0]), at(chains[4][0]), kPalmRadiusM, kPalm, "palm"});
  }
}

double segment_distance(const glm::vec3& p1, const glm::vec3& q1, const glm::vec3& p2,
                        const glm::vec3& q2) {
  const glm::vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const float a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
  constexpr float kTiny = 1e-12f;
  float s = 0.0f, t = 0.0f;
  if (a <= kTiny && e <= kTiny) return static_cast<double>(glm::length(r));
  if (a <= kTiny) {
    t = std::clamp(f / e, 0.0f, 1.0f);
  } else {
    const float c = glm::dot(d1, r);
    if (e <= kTiny) {
      s = std::clamp(-c / a, 0.0f, 1.0f);
    } else {
      const float b = glm::dot(d1, d2), denom = a * e - b * b;
      s = denom > kTiny ? std::clamp((b * f - c * e) / denom, 0.0f, 1.0f) : 0.0f;
      t = (b * s + f) / e;
      if (t < 0.0f) {
        t = 0.0f;
        s = std::clamp(-c / a, 0.0f, 1.0f);
      } else if (t > 1.0f) {
        t = 1.0f;
        s = std::clamp((b - c) / a, 0.0f, 1.0f);
      }
    }
  }
  return static_cast<double>(glm::distance(p1 + d1 * s, p2 + d2 * t));
}

double overlap_m(const HandCapsule& one, const HandCapsule& other) {
  return static_cast<double>(one.radius + other.radius) -
         segment_distance(one.a, one.b, other.a, other.b);
}

}  // namespace tutti::piano
