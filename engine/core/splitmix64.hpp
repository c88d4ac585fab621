// SPDX-License-Identifier: MIT
#pragma once
// splitmix64 (Steele, Lea, Flood 2014): one step of the generator from state `x` — add the golden
// gamma, then mix. Every seeded choice in tutti derives its bits from it, so a seed means the same
// thing everywhere and on every platform.

#include <cstdint>

namespace tutti {

constexpr std::uint64_t kSplitmixGamma = 0x9E3779B97F4A7C15ull;

constexpr std::uint64_t splitmix64(std::uint64_t x) noexcept {
  x += kSplitmixGamma;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

}  // namespace tutti
