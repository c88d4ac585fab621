// SPDX-License-Identifier: MIT
#pragma once
// Readable component names for error messages, taken from the compiler's function signature so
// that no RTTI or registration is needed. The text is whatever g++/clang print (e.g.
// "tutti::ecs::Position", "{anonymous}::Tag"); it is for people, not for identity.

#include <string_view>

namespace tutti::ecs {

template <typename T>
[[nodiscard]] constexpr std::string_view type_name() noexcept {
  // g++:   "constexpr std::string_view tutti::ecs::type_name() [with T = Foo; std::string_view =
  // ...]" clang: "std::string_view tutti::ecs::type_name() [T = Foo]"
  constexpr std::string_view signature = __PRETTY_FUNCTION__;
  constexpr std::string_view marker = "T = ";
  constexpr std::size_t start = signature.find(marker);
  if constexpr (start == std::string_view::npos) {
    return "unknown type";
  } else {
    constexpr std::size_t first = start + marker.size();
    constexpr std::size_t semicolon = signature.find(';', first);
    constexpr std::size_t last =
        semicolon != std::string_view::npos ? semicolon : signature.rfind(']');
    return signature.substr(first, last - first);
  }
}

}  // namespace tutti::ecs
