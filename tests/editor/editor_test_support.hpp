#pragma once
// Shared by the editor tests: a scratch folder per test with copies of the shipped scenes (their
// music paths point back into content/, so the copies load the real music).

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace tutti::editor::test {

inline std::filesystem::path source_dir() { return TUTTI_SOURCE_DIR; }

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

class ScratchDir {
 public:
  ScratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("tutti_editor_" + std::to_string(::getpid()) + "_" + info->test_suite_name() + "_" +
             info->name());
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const std::filesystem::path file = path_ / name;
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }
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

 private:
  std::filesystem::path path_;
};

}  // namespace tutti::editor::test
