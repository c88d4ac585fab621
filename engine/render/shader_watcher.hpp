// SPDX-License-Identifier: MIT
#pragma once
// Polled change detection for shader hot reload: a set of files (a shader and everything it
// included, CompiledShader::included_files), each remembered by modification time and size. No
// threads, no inotify: the editor calls poll() once a frame (a few stat calls) and recompiles
// when it returns something. Deterministic, so tests drive it by setting mtimes.
//
// A file counts as changed when its mtime or size differs from the last recorded state, or when
// it appears or disappears (an editor saving via rename can make a file vanish for a moment;
// that is reported, and reported again when it is back).

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

namespace tutti::render {

class ShaderWatcher {
 public:
  ShaderWatcher() = default;
  explicit ShaderWatcher(std::span<const std::filesystem::path> files) { watch(files); }

  // Adds files (already watched ones are ignored) and records their current state, so they are
  // not reported until they change after this call.
  void watch(const std::filesystem::path& file);
  void watch(std::span<const std::filesystem::path> files);
  // Forgets all files (e.g. before watching a recompiled shader's new include list).
  void clear() { entries_.clear(); }

  // Whether any file changed since it was last recorded; records nothing.
  bool changed() const;
  // The files that changed since they were last recorded, in watch order, and records their new
  // state: a second poll() without further changes returns nothing.
  std::vector<std::filesystem::path> poll();

  std::vector<std::filesystem::path> files() const;

 private:
  struct Stamp {
    bool exists = false;
    std::filesystem::file_time_type mtime{};
    std::uintmax_t size = 0;
    bool operator==(const Stamp&) const = default;
  };
  struct Entry {
    std::filesystem::path path;
    Stamp stamp;
  };
  static Stamp stamp_of(const std::filesystem::path& path);

  std::vector<Entry> entries_;
};

}  // namespace tutti::render
