// SPDX-License-Identifier: MIT
#pragma once
// Reading numbers out of MusicXML element text. MusicXML numbers are xs:decimal / xs:integer
// with optional surrounding whitespace; anything else is reported by the caller, never thrown.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <pugixml.hpp>
#include <string>
#include <string_view>

namespace tutti::music::musicxml {

// XML's whitespace: space, tab, line feed, carriage return.
constexpr bool is_xml_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// The element's text (first PCDATA/CDATA child) without leading or trailing XML whitespace.
std::string_view trimmed_text(pugi::xml_node element);
std::string_view trim_xml_space(std::string_view text);

// Text from the file made safe for a one-line error message: control characters become '?',
// and anything past `max_chars` bytes is cut (with "...").
std::string one_line(std::string_view text, std::size_t max_chars = 64);

// A finite decimal ("12", "-0.5", "+3", "1e3"). nullopt on anything else, including nan/inf.
std::optional<double> parse_decimal(std::string_view text);
// A whole number that fits in 64 bits ("3", "-2", "+7"). nullopt otherwise.
std::optional<std::int64_t> parse_integer(std::string_view text);

}  // namespace tutti::music::musicxml
