// SPDX-License-Identifier: MIT
#pragma once
// default_content_dir moved to engine/content; the piano code keeps using it under its own name.

#include <tutti/content/content_dir.hpp>

namespace tutti::piano_model {
using content::default_content_dir;
}  // namespace tutti::piano_model
