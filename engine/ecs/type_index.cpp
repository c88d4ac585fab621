// SPDX-License-Identifier: MIT
#include <tutti/ecs/type_index.hpp>

#include <atomic>

namespace tutti::ecs::detail {

std::size_t next_type_index() noexcept {
  static std::atomic<std::size_t> next{0};
  return next.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace tutti::ecs::detail
