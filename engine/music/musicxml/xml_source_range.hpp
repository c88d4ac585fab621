// SPDX-License-Identifier: MIT
#pragma once
// Where an element of a parsed document sits in the text it was parsed from, so an edited
// element can be spliced back into the original bytes and everything around it stays exactly
// as it was (quotes, "<x />" spellings, entities, line ends: none of it goes through a
// serializer).

#include <cstddef>
#include <optional>
#include <pugixml.hpp>
#include <string_view>

namespace tutti::music::musicxml {

struct ByteRange {
  std::size_t begin = 0;  // the '<' of the start tag
  std::size_t end = 0;    // one past the '>' of the end tag (or of "<x/>")
};

// Preconditions: `text` is the buffer the document was parsed from, in UTF-8 (so pugixml did
// not convert it and its offsets are byte offsets of `text`), and the element and its
// descendants are unmodified. nullopt when the element cannot be located safely (for
// example, an element of the same name nested inside it).
std::optional<ByteRange> element_source_range(std::string_view text, pugi::xml_node element);

// The element's start tag as written ("<note default-x='80'>" or "<chord />"), or nullopt for
// an element that is not in `text` (created after parsing). Same preconditions on `text`.
std::optional<std::string_view> source_start_tag(std::string_view text, pugi::xml_node element);

}  // namespace tutti::music::musicxml
