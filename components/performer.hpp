// SPDX-License-Identifier: MIT
#pragma once
// A musician in the scene. The seed makes every per-performer variation reproducible.

#include <cstdint>
#include <string>

namespace tutti::components {

struct Performer {
  std::string name;        // shown in the editor and in messages; may be empty
  std::uint64_t seed = 0;  // seeds this performer's variation (same seed = same performance)
};

}  // namespace tutti::components
