// SPDX-License-Identifier: MIT
#include <tutti/music/musicxml/fingering_text.hpp>

#include <tutti/music/musicxml/xml_text_values.hpp>

namespace tutti::music::musicxml {

namespace {
int finger_digit(char c) { return c >= '1' && c <= '5' ? c - '0' : 0; }

std::string_view skip_separators(std::string_view text) {
  constexpr std::string_view kEnDash = "\xE2\x80\x93";
  for (;;) {
    if (text.empty()) return text;
    const char c = text.front();
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '-' || c == '_' || c == ',' ||
        c == '/' || c == '~') {
      text.remove_prefix(1);
    } else if (text.substr(0, kEnDash.size()) == kEnDash) {
      text.remove_prefix(kEnDash.size());
    } else {
      return text;
    }
  }
}
}  // namespace

std::optional<FingeringMark> parse_fingering_text(std::string_view text) {
  text = trim_xml_space(text);
  if (text.empty()) return std::nullopt;
  FingeringMark mark;
  mark.finger = finger_digit(text.front());
  if (mark.finger == 0) return std::nullopt;
  text = skip_separators(text.substr(1));
  if (!text.empty()) mark.substitute = finger_digit(text.front());
  return mark;
}

}  // namespace tutti::music::musicxml
