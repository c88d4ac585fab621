#include <tutti/content/content_dir.hpp>

#include <cstdlib>

namespace tutti::content {

std::filesystem::path default_content_dir() {
  if (const char* env = std::getenv("TUTTI_CONTENT_DIR"); env != nullptr && *env != '\0') {
    return env;
  }
  return TUTTI_CONTENT_DIR;
}

}  // namespace tutti::content
