// SPDX-License-Identifier: MIT
#pragma once
// "Did you mean" for a mistyped name: the closest of the names that exist, when one is close
// enough to be what was meant — a word it starts (`fov` for `fov_deg`, `position` for
// `position_m`), or a small edit (one in three letters: `rendr`, `fingring`, `sway_amout`; none
// for words shorter than three letters).

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace tutti {

std::optional<std::string> closest_name(std::string_view typed,
                                        std::span<const std::string_view> known);

// " (did you mean \"NAME\"?)", or "" when nothing is close.
std::string did_you_mean(std::string_view typed, std::span<const std::string_view> known);

}  // namespace tutti
