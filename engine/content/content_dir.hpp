#pragma once
// Where the data files (content/piano/..., content/instruments/...) are: the environment variable TUTTI_CONTENT_DIR when
// set and non-empty, else the source tree's content/ folder baked in at build time.

#include <filesystem>

namespace tutti::content {

std::filesystem::path default_content_dir();

}  // namespace tutti::content
