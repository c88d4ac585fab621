// SPDX-License-Identifier: MIT
#pragma once
// A 3x5 pixel font for the digits 0-9: enough to write finger numbers on a plot without a font
// library. Row r of digit d is kDigits3x5[d][r]; bit 2 is the left column.

#include <array>
#include <cstdint>

namespace tutti::cli {

inline constexpr std::array<std::array<std::uint8_t, 5>, 10> kDigits3x5{{
    {0b111, 0b101, 0b101, 0b101, 0b111},  // 0
    {0b010, 0b110, 0b010, 0b010, 0b111},  // 1
    {0b111, 0b001, 0b111, 0b100, 0b111},  // 2
    {0b111, 0b001, 0b111, 0b001, 0b111},  // 3
    {0b101, 0b101, 0b111, 0b001, 0b001},  // 4
    {0b111, 0b100, 0b111, 0b001, 0b111},  // 5
    {0b111, 0b100, 0b111, 0b101, 0b111},  // 6
    {0b111, 0b001, 0b001, 0b001, 0b001},  // 7
    {0b111, 0b101, 0b111, 0b101, 0b111},  // 8
    {0b111, 0b101, 0b111, 0b001, 0b111},  // 9
}};

}  // namespace tutti::cli
