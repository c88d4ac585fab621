// SPDX-License-Identifier: MIT
#pragma once
// Writes an edited element back as text, reusing the original spelling wherever the element
// came from the source: every original start tag is copied byte for byte (quotes, attribute
// order and spacing, "<x />" vs "<x/>"), original character data, comments and CDATA come out
// raw, and only nodes created after parsing are spelled by this writer. An edited <note> thus
// differs from the original by exactly the inserted or changed marks.
//
// Preconditions: as for xml_source_range.hpp (`text` is the UTF-8 buffer the document was
// parsed from), and the document was parsed without parse_escapes and parse_eol so node
// values are still their source text. Element depth is bounded by the parse check
// (kMaxElementDepth), which bounds the recursion.

#include <pugixml.hpp>
#include <string>
#include <string_view>

namespace tutti::music::musicxml {

std::string serialize_keeping_source(std::string_view text, pugi::xml_node node);

}  // namespace tutti::music::musicxml
