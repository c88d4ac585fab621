// SPDX-License-Identifier: MIT
#include <tutti/music/musicxml/grace_placement.hpp>

#include <algorithm>
#include <cmath>

namespace tutti::music::musicxml {

std::int64_t grace_run_ticks(std::int64_t slots, std::int64_t host_ticks,
                             std::optional<double> steal_percent, int ticks_per_quarter) {
  const std::int64_t half_host = std::max<std::int64_t>(host_ticks, 0) / 2;
  if (steal_percent && *steal_percent >= 0.0) {
    const double wanted = static_cast<double>(host_ticks) * std::min(*steal_percent, 100.0) / 100.0;
    return std::min(half_host, static_cast<std::int64_t>(std::llround(wanted)));
  }
  const std::int64_t slot_ticks = std::max(ticks_per_quarter / 8, 1);
  // slots <= number of <note> elements, far below 2^13 * 2^50 / slot_ticks.
  return std::min(half_host, slots * slot_ticks);
}

std::int64_t grace_slot_start(std::int64_t start, std::int64_t total, std::int64_t slots,
                              std::int64_t index) {
  if (slots <= 0) return start;
  // total * index / slots without the product: total = q * slots + r, r < slots.
  const std::int64_t q = total / slots;
  const std::int64_t r = total % slots;
  return start + q * index + r * index / slots;
}

}  // namespace tutti::music::musicxml
