// SPDX-License-Identifier: MIT
#pragma once
// Where the data files (content/<family>/..., content/scenes/...) are, when the caller does not
// say (the APIs take a content folder as an option): the environment variable TUTTI_CONTENT_DIR
// when set and non-empty; else, for a program installed as <prefix>/bin/..., the installation's
// <prefix>/share/tutti/content; else the source tree's content/ folder baked in at build time.

#include <filesystem>

namespace tutti::content {

std::filesystem::path default_content_dir();

// <prefix>/share/tutti/<name> when the running program is <prefix>/bin/<program> and that folder
// exists; else empty.
std::filesystem::path installed_data_dir(const char* name);

}  // namespace tutti::content
