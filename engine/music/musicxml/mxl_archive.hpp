// SPDX-License-Identifier: MIT
#pragma once
// The compressed MusicXML container (.mxl): a zip whose META-INF/container.xml names the score
// ("rootfile full-path"). Only that one file is inflated, and never past a size cap, so a zip
// bomb costs at most the cap in memory and time.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include <tutti/core/result.hpp>

namespace tutti::music::musicxml {

inline constexpr std::size_t kMaxMxlEntryBytes = std::size_t{64} << 20;  // 64 MiB

// True when the bytes start like a zip archive ("PK\3\4", or "PK\5\6" for an empty one).
bool looks_like_zip(std::span<const std::uint8_t> bytes);

// The bytes of the archive's score. The score is the first <rootfile> of container.xml whose
// media-type is absent or MusicXML; without a usable container, the first .xml/.musicxml entry
// outside META-INF/. Errors: "<source>: not a readable zip archive (...)", "<source>: the
// archive holds no MusicXML score", "<source>: <entry> inflates to more than 64 MiB", ...
Result<std::string> read_mxl_score(std::span<const std::uint8_t> bytes, const std::string& source,
                                   std::size_t max_entry_bytes = kMaxMxlEntryBytes);

}  // namespace tutti::music::musicxml
