// SPDX-License-Identifier: MIT
#pragma once
// Adds fingering marks to an existing MusicXML document without disturbing anything else: for
// every note of `fingered` with a finger and a source_index, the matching <note> element gets
// <notations><technical><fingering>N</fingering> (replacing an existing fingering mark, and
// adding <fingering substitution="yes">M</fingering> for a finger substitution). New elements
// go where the schema wants them (note_element_order.hpp), indented like their siblings.
//
// Only the edited <note> elements are re-serialized and spliced into the original text, so
// every other byte (declaration, doctype, comments, whitespace, line ends, quoting, entities)
// stays identical; a score with no fingers gives the input back byte for byte. Inside an
// edited note, "<x />" and "<x></x>" become "<x/>" and attributes get double quotes. Documents
// not in UTF-8 (UTF-16, Latin-1) are re-serialized whole in their own encoding.
//
// `original` is the file as read (.xml/.musicxml or .mxl); the result is uncompressed MusicXML.
// Errors: not MusicXML, or a score that does not match the file (a source_index past the last
// <note>, a finger outside 1..5).

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include <tutti/core/result.hpp>
#include <tutti/music/score.hpp>

namespace tutti::music {

Result<std::string> add_fingering_marks(std::span<const std::uint8_t> original,
                                        const std::string& source_name, const Score& fingered);
Status write_musicxml_with_fingering(const std::filesystem::path& original,
                                     const std::filesystem::path& output, const Score& fingered);

}  // namespace tutti::music
