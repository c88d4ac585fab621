// SPDX-License-Identifier: MIT
#pragma once
// Which of a pianist's hands an entity belongs to. The left hand is the mirror image of the right
// (x along the keyboard flips), so anything lateral ("toward the little finger") changes sign.

#include <cstdint>

namespace tutti::components {

enum class HandSide : std::int8_t { right = 0, left = 1 };

}  // namespace tutti::components
