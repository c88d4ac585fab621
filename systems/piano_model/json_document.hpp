// SPDX-License-Identifier: MIT
#pragma once
// The JSON helpers moved to engine/content (shared with the instrument files); the piano code
// keeps using them under its own namespace.

#include <tutti/content/json_reader.hpp>

namespace tutti::piano_model {
using content::JsonReader;
using content::read_json_file;
}  // namespace tutti::piano_model
