// SPDX-License-Identifier: MIT
#pragma once
// Shared by the scene tests: paths into the source tree and a scratch folder per test.

#include <filesystem>

#include "scratch_dir.hpp"

namespace tutti::scene::test {

inline std::filesystem::path source_dir() { return TUTTI_SOURCE_DIR; }
inline std::filesystem::path scenes_dir() { return source_dir() / "content" / "scenes"; }

// The scene tests' scratch folders (tests/scratch_dir.hpp).
class ScratchDir : public tutti::test::ScratchDir {
 public:
  ScratchDir() : tutti::test::ScratchDir("tutti_scene_") {}
};

}  // namespace tutti::scene::test
