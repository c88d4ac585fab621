// SPDX-License-Identifier: MIT
#pragma once
// Writes a scene document the way people write them by hand: objects one key per line, short
// arrays and small objects on one line ("position_m": [0, 1.7, 6.5]), two-space indents. The
// same document always gives the same bytes.

#include <string>

#include <tutti/editor/json_edit.hpp>

namespace tutti::editor {

std::string format_scene_json(const Json& document);

}  // namespace tutti::editor
