// SPDX-License-Identifier: MIT
#pragma once
// A dense, process-wide number per component type, so a World finds a type's pool by indexing a
// vector instead of hashing. Numbers are handed out on first use and differ between runs: never
// store or send them.

#include <cstddef>
#include <type_traits>

namespace tutti::ecs {

namespace detail {
// The counter lives in one translation unit of tutti_ecs so every caller shares it.
std::size_t next_type_index() noexcept;
}  // namespace detail

template <typename T>
[[nodiscard]] std::size_t type_index() noexcept {
  static_assert(std::is_same_v<T, std::remove_cvref_t<T>>, "type_index takes unqualified types");
  static const std::size_t index = detail::next_type_index();
  return index;
}

}  // namespace tutti::ecs
