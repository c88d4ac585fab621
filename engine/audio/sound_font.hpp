// SPDX-License-Identifier: MIT
#pragma once
// Where the General MIDI sound font is: an explicit path, else $TUTTI_SOUNDFONT, else the files
// Debian's fluid-soundfont-gm (and other GM fonts) install.

#include <filesystem>
#include <string>

#include <tutti/core/result.hpp>

namespace tutti::audio {

// `override_path` non-empty: that file (an error when it is missing). Otherwise $TUTTI_SOUNDFONT,
// then /usr/share/sounds/sf2/FluidR3_GM.sf2, default-GM.sf2, /usr/share/soundfonts/default.sf2.
Result<std::filesystem::path> find_sound_font(const std::filesystem::path& override_path = {});

}  // namespace tutti::audio
