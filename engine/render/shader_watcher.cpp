// SPDX-License-Identifier: MIT
#include <tutti/render/shader_watcher.hpp>

#include <algorithm>
#include <system_error>

namespace tutti::render {

namespace fs = std::filesystem;

ShaderWatcher::Stamp ShaderWatcher::stamp_of(const fs::path& path) {
  // error_code overloads: a missing or unreadable file is a state, not an exception.
  std::error_code ec;
  Stamp stamp;
  const fs::file_time_type mtime = fs::last_write_time(path, ec);
  if (ec) return stamp;
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) return stamp;
  stamp.exists = true;
  stamp.mtime = mtime;
  stamp.size = size;
  return stamp;
}

void ShaderWatcher::watch(const fs::path& file) {
  const bool known = std::any_of(entries_.begin(), entries_.end(),
                                 [&](const Entry& entry) { return entry.path == file; });
  if (!known) entries_.push_back({file, stamp_of(file)});
}

void ShaderWatcher::watch(std::span<const fs::path> files) {
  for (const fs::path& file : files) watch(file);
}

bool ShaderWatcher::changed() const {
  return std::any_of(entries_.begin(), entries_.end(),
                     [](const Entry& entry) { return stamp_of(entry.path) != entry.stamp; });
}

std::vector<fs::path> ShaderWatcher::poll() {
  std::vector<fs::path> changed_files;
  for (Entry& entry : entries_) {
    const Stamp now = stamp_of(entry.path);
    if (now == entry.stamp) continue;
    entry.stamp = now;
    changed_files.push_back(entry.path);
  }
  return changed_files;
}

std::vector<fs::path> ShaderWatcher::files() const {
  std::vector<fs::path> paths;
  paths.reserve(entries_.size());
  for (const Entry& entry : entries_) paths.push_back(entry.path);
  return paths;
}

}  // namespace tutti::render
