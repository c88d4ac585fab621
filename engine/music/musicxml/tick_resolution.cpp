// SPDX-License-Identifier: MIT
#include <tutti/music/musicxml/tick_resolution.hpp>

#include <cmath>
#include <numeric>

namespace tutti::music::musicxml {

int ticks_per_quarter_for(std::span<const double> divisions_values) {
  std::int64_t lcm = kBaseTicksPerQuarter;
  for (const double divisions : divisions_values) {
    if (divisions != std::floor(divisions) ||
        divisions > static_cast<double>(kMaxTicksPerQuarter)) {
      return kFallbackTicksPerQuarter;
    }
    const auto whole = static_cast<std::int64_t>(divisions);
    // Both factors are <= 10^6, so the product cannot overflow before the cap check.
    lcm = lcm / std::gcd(lcm, whole) * whole;
    if (lcm > kMaxTicksPerQuarter) return kFallbackTicksPerQuarter;
  }
  return static_cast<int>(lcm);
}

std::optional<std::int64_t> divisions_to_ticks(double duration, double divisions,
                                               int ticks_per_quarter) {
  // A product of integers below 2^53 is exact in a double, so whole durations in the exact
  // (lcm) mode stay exact; the range check comes before any conversion to an integer.
  const double ticks = duration * (static_cast<double>(ticks_per_quarter) / divisions);
  if (!std::isfinite(ticks) || ticks < 0.0 || ticks > static_cast<double>(kMaxTicks)) {
    return std::nullopt;
  }
  return std::llround(ticks);
}

}  // namespace tutti::music::musicxml
