// SPDX-License-Identifier: MIT
#include <tutti/music/musicxml/xml_source_range.hpp>

#include <cstring>

#include <tutti/music/musicxml/xml_text_values.hpp>

namespace tutti::music::musicxml {

namespace {

// Index of the '>' closing the start tag whose name ends at `from`. Attribute values may hold
// '>', so quoted text is skipped.
std::optional<std::size_t> start_tag_end(std::string_view text, std::size_t from) {
  char quote = 0;
  for (std::size_t i = from; i < text.size(); ++i) {
    const char c = text[i];
    if (quote != 0) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '>') {
      return i;
    }
  }
  return std::nullopt;
}

std::optional<std::size_t> offset_of(pugi::xml_node node, std::string_view text) {
  const std::ptrdiff_t offset = node.offset_debug();
  if (offset < 0 || static_cast<std::size_t>(offset) >= text.size()) return std::nullopt;
  return static_cast<std::size_t>(offset);
}

// Where, after the element's last descendant, only end tags can follow. Comment, CDATA and PI
// bodies could contain "</name>" as text, so the scan starts past their terminators; element
// start tags and character data cannot contain '<' at all.
std::optional<std::size_t> past_last_descendant(std::string_view text, pugi::xml_node element) {
  // The end tags after the last descendant are those of its ancestors; one of the same name
  // as `element` would be found first.
  pugi::xml_node last = element.last_child();
  for (;;) {
    if (last.type() == pugi::node_element && std::strcmp(last.name(), element.name()) == 0) {
      return std::nullopt;
    }
    if (!last.last_child()) break;
    last = last.last_child();
  }
  const auto offset = offset_of(last, text);
  if (!offset) return std::nullopt;
  auto after = [&](std::string_view terminator) -> std::optional<std::size_t> {
    const std::size_t at = text.find(terminator, *offset);
    if (at == std::string_view::npos) return std::nullopt;
    return at + terminator.size();
  };
  switch (last.type()) {
    case pugi::node_element:
    case pugi::node_pcdata:
      return *offset;
    case pugi::node_cdata:
      return after("]]>");
    case pugi::node_comment:
      return after("-->");
    case pugi::node_pi:
      return after("?>");
    default:
      return std::nullopt;
  }
}

// [begin, end) of the element's start tag in `text`.
std::optional<ByteRange> start_tag_range(std::string_view text, pugi::xml_node element) {
  if (element.type() != pugi::node_element) return std::nullopt;
  const std::string_view name = element.name();
  const auto name_at = offset_of(element, text);
  if (!name_at || *name_at == 0 || text[*name_at - 1] != '<' ||
      text.substr(*name_at, name.size()) != name) {
    return std::nullopt;
  }
  const auto tag_end = start_tag_end(text, *name_at + name.size());
  if (!tag_end) return std::nullopt;
  return ByteRange{*name_at - 1, *tag_end + 1};
}

}  // namespace

std::optional<std::string_view> source_start_tag(std::string_view text, pugi::xml_node element) {
  const auto range = start_tag_range(text, element);
  if (!range) return std::nullopt;
  return text.substr(range->begin, range->end - range->begin);
}

std::optional<ByteRange> element_source_range(std::string_view text, pugi::xml_node element) {
  const std::string_view name = element.name();
  const auto start_tag = start_tag_range(text, element);
  if (!start_tag) return std::nullopt;
  ByteRange range{start_tag->begin, start_tag->end};
  if (text[start_tag->end - 2] == '/') {
    if (element.first_child()) return std::nullopt;
    return range;
  }
  std::optional<std::size_t> from = start_tag->end;
  if (element.first_child()) from = past_last_descendant(text, element);
  if (!from) return std::nullopt;

  const std::string end_tag = "</" + std::string(name);
  for (std::size_t at = text.find(end_tag, *from); at != std::string_view::npos;
       at = text.find(end_tag, at + 1)) {
    std::size_t i = at + end_tag.size();
    if (i < text.size() && text[i] != '>' && !is_xml_space(text[i])) continue;  // </notehead>
    while (i < text.size() && is_xml_space(text[i])) ++i;
    if (i >= text.size() || text[i] != '>') return std::nullopt;
    range.end = i + 1;
    return range;
  }
  return std::nullopt;
}

}  // namespace tutti::music::musicxml
