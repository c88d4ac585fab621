// SPDX-License-Identifier: MIT
#pragma once
// Shared by the editor tests: a scratch folder per test with copies of the shipped scenes (their
// music paths point back into content/, so the copies load the real music).

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <tutti/editor/scene_edits.hpp>

#include "scratch_dir.hpp"

namespace tutti::editor::test {

inline std::filesystem::path source_dir() { return TUTTI_SOURCE_DIR; }

// The k-th brass player of a scene file, as its edits name it ("/performers/k").
inline PlayerRef performer_at(std::size_t k) { return {"/performers/" + std::to_string(k), ""}; }

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

class ScratchDir : public tutti::test::ScratchDir {
 public:
  ScratchDir() : tutti::test::ScratchDir("tutti_editor_") {}

  // A copy of content/scenes/<name> whose "music" is made absolute.
  std::filesystem::path copy_scene(const std::string& name) const {
    std::string text = read_text(source_dir() / "content" / "scenes" / name);
    const std::string music = "\"../music/";
    const std::string absolute = "\"" + (source_dir() / "content" / "music").string() + "/";
    for (auto at = text.find(music); at != std::string::npos; at = text.find(music, at)) {
      text.replace(at, music.size(), absolute);
      at += absolute.size();
    }
    return write(name, text);
  }
};

}  // namespace tutti::editor::test
