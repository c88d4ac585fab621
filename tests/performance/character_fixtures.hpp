// SPDX-License-Identifier: MIT
#pragma once
// The user-character fixtures (tests/data/characters/make_fixtures.py), made by Blender into
// `dir`: humanoids named the Unreal way in centimetres, as VRM 1.0, ..., and a pair of hand models
// (hands_only.glb). Listed in dir/fixtures.json.

#include <cstdlib>
#include <filesystem>
#include <string>

namespace tutti::test {

inline bool has_blender() { return std::system("command -v blender > /dev/null 2>&1") == 0; }

inline bool make_character_fixtures(const std::filesystem::path& dir) {
  const std::string command =
      "blender -b --factory-startup --python '" +
      (std::filesystem::path(TUTTI_SOURCE_DIR) / "tests/data/characters/make_fixtures.py").string() +
      "' -- '" + dir.string() + "' > /dev/null 2>&1";
  return std::system(command.c_str()) == 0;
}

}  // namespace tutti::test
