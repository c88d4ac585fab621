// SPDX-License-Identifier: MIT
#include <tutti/content/content_dir.hpp>

#include <cstdlib>
#include <system_error>

namespace tutti::content {

std::filesystem::path installed_data_dir(const char* name) {
  // An installed program lives in <prefix>/bin and its data in <prefix>/share/tutti/<name>.
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec || exe.empty()) return {};
  const std::filesystem::path dir = exe.parent_path().parent_path() / "share" / "tutti" / name;
  return std::filesystem::is_directory(dir, ec) ? dir : std::filesystem::path{};
}

std::filesystem::path default_content_dir() {
  if (const char* env = std::getenv("TUTTI_CONTENT_DIR"); env != nullptr && *env != '\0') {
    return env;
  }
  if (std::filesystem::path installed = installed_data_dir("content"); !installed.empty()) {
    return installed;
  }
  return TUTTI_CONTENT_DIR;
}

}  // namespace tutti::content
