// SPDX-License-Identifier: MIT
#pragma once
// From input bytes to a parsed MusicXML document, shared by the reader and the fingering writer
// so both agree on what the document is and how its <note> elements are numbered.

#include <cstddef>
#include <cstdint>
#include <pugixml.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <tutti/core/result.hpp>

namespace tutti::music::musicxml {

// Deeper than any real score (MusicXML needs about 10 levels); guards code that recurses.
inline constexpr int kMaxElementDepth = 256;

// The XML text of an input: the bytes themselves, or the score inside an .mxl archive (detected
// by the zip signature, not by the file name). "<source>: empty file" for no bytes.
Result<std::string> musicxml_text(std::span<const std::uint8_t> bytes, const std::string& source);

// 1-based line number of a byte offset; LF, CRLF and lone CR (classic Mac files) all end lines.
std::size_t line_at(std::string_view text, std::ptrdiff_t offset);

// Parses `text` (kept alive by the caller) into `doc` and checks that the root element is
// <score-partwise> or <score-timewise> and that nothing nests deeper than kMaxElementDepth.
// `encoding` receives the encoding pugixml detected. Errors: "<source>: line 12: XML error:
// Start-end tags mismatch", "<source>: line 4: expected <score-partwise>, found <html>".
Status parse_musicxml(const std::string& text, unsigned int parse_flags, pugi::xml_document& doc,
                      const std::string& source, pugi::xml_encoding* encoding = nullptr);

// Every <note> element in document order: element i is the note with Note::source_index i.
std::vector<pugi::xml_node> note_elements(const pugi::xml_document& doc);

}  // namespace tutti::music::musicxml
