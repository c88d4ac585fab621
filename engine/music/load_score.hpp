// SPDX-License-Identifier: MIT
#pragma once
// One entry point for every score format. The format is decided by the file's bytes first
// (MIDI "MThd"/"RIFF", zip "PK" = compressed MusicXML, '<' = MusicXML, "//" = PIG text), then
// by its extension, so a mis-named file is still read correctly.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

#include <tutti/core/result.hpp>
#include <tutti/music/score.hpp>

namespace tutti::music {

enum class ScoreFormat { midi, musicxml, pig };

const char* format_name(ScoreFormat format);

std::optional<ScoreFormat> detect_score_format(std::span<const std::uint8_t> bytes,
                                               const std::filesystem::path& path);

// Errors: missing file, unknown format, or the reader's own message; always one line starting
// with the file name.
Result<Score> load_score(const std::filesystem::path& path);

}  // namespace tutti::music
