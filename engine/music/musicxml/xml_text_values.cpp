// SPDX-License-Identifier: MIT
#include <tutti/music/musicxml/xml_text_values.hpp>

#include <charconv>
#include <cmath>

namespace tutti::music::musicxml {

namespace {
// from_chars rejects a leading '+', which XML numbers allow.
std::string_view without_plus(std::string_view text) {
  if (text.size() > 1 && text.front() == '+' && text[1] != '-') text.remove_prefix(1);
  return text;
}
}  // namespace

std::string_view trim_xml_space(std::string_view text) {
  while (!text.empty() && is_xml_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_xml_space(text.back())) text.remove_suffix(1);
  return text;
}

std::string_view trimmed_text(pugi::xml_node element) {
  return trim_xml_space(element.text().get());
}

std::string one_line(std::string_view text, std::size_t max_chars) {
  std::string line;
  for (const char c : text.substr(0, max_chars)) {
    line += static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? '?' : c;
  }
  if (text.size() > max_chars) line += "...";
  return line;
}

std::optional<double> parse_decimal(std::string_view text) {
  text = without_plus(trim_xml_space(text));
  if (text.empty()) return std::nullopt;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc{} || end != text.data() + text.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

std::optional<std::int64_t> parse_integer(std::string_view text) {
  text = without_plus(trim_xml_space(text));
  if (text.empty()) return std::nullopt;
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc{} || end != text.data() + text.size()) return std::nullopt;
  return value;
}

}  // namespace tutti::music::musicxml
