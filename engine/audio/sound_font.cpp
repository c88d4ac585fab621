// SPDX-License-Identifier: MIT
#include <tutti/audio/sound_font.hpp>

#include <cstdlib>
#include <system_error>

namespace tutti::audio {
namespace {

Result<std::filesystem::path> existing_file(const std::filesystem::path& path,
                                            const std::string& what) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    return Error{path.string() + ": no such sound font (" + what + ")"};
  }
  return path;
}

}  // namespace

Result<std::filesystem::path> find_sound_font(const std::filesystem::path& override_path) {
  if (!override_path.empty()) return existing_file(override_path, "given with --soundfont");
  if (const char* env = std::getenv("TUTTI_SOUNDFONT"); env != nullptr && *env != '\0') {
    return existing_file(env, "from TUTTI_SOUNDFONT");
  }
  for (const char* candidate :
       {"/usr/share/sounds/sf2/FluidR3_GM.sf2", "/usr/share/sounds/sf2/default-GM.sf2",
        "/usr/share/soundfonts/default.sf2"}) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec)) return std::filesystem::path(candidate);
  }
  return Error{
      "no General MIDI sound font found (looked in /usr/share/sounds/sf2 and "
      "/usr/share/soundfonts; install Debian's fluid-soundfont-gm or set TUTTI_SOUNDFONT)",
      ErrorCode::environment};
}

}  // namespace tutti::audio
