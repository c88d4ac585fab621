// SPDX-License-Identifier: MIT
#include <tutti/music/musicxml/musicxml_document.hpp>

#include <algorithm>
#include <cstring>

#include <tutti/music/musicxml/mxl_archive.hpp>
#include <tutti/music/musicxml/xml_text_values.hpp>

namespace tutti::music::musicxml {

namespace {

// Pre-order walk without recursion, so a hostile nesting depth cannot exhaust the stack.
template <typename Visit>
void for_each_element(pugi::xml_node root, Visit&& visit) {
  pugi::xml_node node = root.first_child();
  int depth = 1;
  while (node) {
    if (node.type() == pugi::node_element) visit(node, depth);
    if (node.first_child()) {
      node = node.first_child();
      ++depth;
      continue;
    }
    while (node && node != root && !node.next_sibling()) {
      node = node.parent();
      --depth;
    }
    if (!node || node == root) return;
    node = node.next_sibling();
  }
}

std::string where(const std::string& text, std::ptrdiff_t offset, pugi::xml_encoding encoding) {
  // Offsets count bytes of the buffer pugixml parsed; after a conversion (UTF-16, Latin-1)
  // they no longer match the input's bytes, so only a UTF-8 input gets a line number.
  if (encoding == pugi::encoding_utf8 && offset >= 0) {
    return "line " + std::to_string(line_at(text, offset)) + ": ";
  }
  return "";
}

}  // namespace

Result<std::string> musicxml_text(std::span<const std::uint8_t> bytes, const std::string& source) {
  if (bytes.empty()) return Error{source + ": empty file"};
  if (looks_like_zip(bytes)) {
    auto score = read_mxl_score(bytes, source);
    if (score && score->empty()) return Error{source + ": the archive's score is an empty file"};
    return score;
  }
  return std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

std::size_t line_at(std::string_view text, std::ptrdiff_t offset) {
  const std::size_t end =
      std::min(text.size(), static_cast<std::size_t>(std::max<std::ptrdiff_t>(offset, 0)));
  std::size_t line = 1;
  for (std::size_t i = 0; i < end; ++i) {
    if (text[i] == '\n' || (text[i] == '\r' && (i + 1 >= text.size() || text[i + 1] != '\n'))) {
      ++line;
    }
  }
  return line;
}

Status parse_musicxml(const std::string& text, unsigned int parse_flags, pugi::xml_document& doc,
                      const std::string& source, pugi::xml_encoding* encoding) {
  const pugi::xml_parse_result parsed =
      doc.load_buffer(text.data(), text.size(), parse_flags, pugi::encoding_auto);
  if (encoding != nullptr) *encoding = parsed.encoding;
  if (parsed.status == pugi::status_no_document_element) {
    return Error{source + ": no XML element found (not a MusicXML file)"};
  }
  if (!parsed) {
    return Error{source + ": " + where(text, parsed.offset, parsed.encoding) +
                 "XML error: " + parsed.description()};
  }
  const pugi::xml_node root = doc.document_element();
  const std::string_view root_name = root.name();
  if (root_name != "score-partwise" && root_name != "score-timewise") {
    return Error{source + ": " + where(text, root.offset_debug(), parsed.encoding) +
                 "expected <score-partwise> or <score-timewise>, found <" + one_line(root_name) +
                 ">"};
  }
  pugi::xml_node too_deep;
  for_each_element(doc, [&](pugi::xml_node element, int depth) {
    if (depth > kMaxElementDepth && !too_deep) too_deep = element;
  });
  if (too_deep) {
    return Error{source + ": " + where(text, too_deep.offset_debug(), parsed.encoding) +
                 "elements nested deeper than " + std::to_string(kMaxElementDepth) + " levels"};
  }
  return Status::success();
}

std::vector<pugi::xml_node> note_elements(const pugi::xml_document& doc) {
  std::vector<pugi::xml_node> notes;
  for_each_element(doc, [&](pugi::xml_node element, int) {
    if (std::strcmp(element.name(), "note") == 0) notes.push_back(element);
  });
  return notes;
}

}  // namespace tutti::music::musicxml
