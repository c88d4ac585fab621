// SPDX-License-Identifier: MIT
#include <tutti/music/musicxml/notation_values.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <numeric>

#include <tutti/music/musicxml/xml_text_values.hpp>

namespace tutti::music::musicxml {

namespace {

int clamp_velocity(double velocity) {
  return static_cast<int>(std::clamp<long>(std::lround(velocity), 1, 127));
}

// Quarter notes in a <beat-unit> value ("quarter" = 1, "eighth" = 0.5, ...).
std::optional<double> quarters_of_note_type(std::string_view type) {
  static const std::map<std::string_view, double> kQuarters = {
      {"maxima", 32.0}, {"long", 16.0},   {"breve", 8.0},     {"whole", 4.0},
      {"half", 2.0},    {"quarter", 1.0}, {"eighth", 0.5},    {"16th", 0.25},
      {"32nd", 0.125},  {"64th", 0.0625}, {"128th", 0.03125}, {"256th", 0.015625}};
  auto it = kQuarters.find(type);
  if (it == kQuarters.end()) return std::nullopt;
  return it->second;
}

// "3+2" -> 5; nullopt unless every term is a whole number in 1..1000.
std::optional<std::int64_t> composite_beats(std::string_view text) {
  std::int64_t count = 0;
  text = trim_xml_space(text);
  if (text.empty()) return std::nullopt;
  while (!text.empty()) {
    const std::size_t plus = text.find('+');
    const auto term = parse_integer(text.substr(0, plus));
    if (!term || *term < 1 || *term > 1000) return std::nullopt;
    count += *term;
    text = plus == std::string_view::npos ? std::string_view{} : text.substr(plus + 1);
  }
  return count;
}

}  // namespace

std::optional<int> velocity_from_percent(std::string_view percent_text) {
  const auto percent = parse_decimal(percent_text);
  if (!percent || *percent < 0.0) return std::nullopt;
  return clamp_velocity(std::min(*percent, 1000.0) * 0.9);
}

std::optional<int> velocity_of_dynamics_mark(std::string_view mark) {
  static const std::map<std::string_view, int> kVelocities = {
      {"pppppp", 5}, {"ppppp", 8},  {"pppp", 12},   {"ppp", 16},    {"pp", 33},
      {"p", 49},     {"mp", 64},    {"mf", 80},     {"f", 96},      {"ff", 112},
      {"fff", 124},  {"ffff", 127}, {"fffff", 127}, {"ffffff", 127}};
  auto it = kVelocities.find(mark);
  if (it == kVelocities.end()) return std::nullopt;
  return it->second;
}

std::optional<double> metronome_bpm(pugi::xml_node metronome) {
  const pugi::xml_node unit = metronome.child("beat-unit");
  const auto quarters = quarters_of_note_type(trimmed_text(unit));
  const auto per_minute = parse_decimal(trimmed_text(metronome.child("per-minute")));
  if (!quarters || !per_minute || *per_minute <= 0.0) return std::nullopt;
  double unit_quarters = *quarters;
  double dot = *quarters / 2.0;
  for (pugi::xml_node next = unit.next_sibling();
       next && std::strcmp(next.name(), "beat-unit-dot") == 0; next = next.next_sibling()) {
    unit_quarters += dot;
    dot /= 2.0;
  }
  return *per_minute * unit_quarters;
}

std::optional<std::pair<int, int>> time_signature_fraction(pugi::xml_node time) {
  if (time.child("senza-misura")) return std::nullopt;
  std::int64_t numerator = 0;
  std::int64_t denominator = 1;
  for (pugi::xml_node beats : time.children("beats")) {
    const pugi::xml_node beat_type = beats.next_sibling();
    if (std::strcmp(beat_type.name(), "beat-type") != 0) return std::nullopt;
    const auto type = parse_integer(trimmed_text(beat_type));
    const auto count = composite_beats(trimmed_text(beats));
    if (!type || *type < 1 || *type > 1024 || !count) return std::nullopt;
    const std::int64_t common = std::lcm(denominator, *type);
    if (common > 1024 * 1024) return std::nullopt;
    numerator = numerator * (common / denominator) + *count * (common / *type);
    denominator = common;
    if (numerator > 1'000'000) return std::nullopt;
  }
  if (numerator <= 0) return std::nullopt;
  return std::pair(static_cast<int>(numerator), static_cast<int>(denominator));
}

int concert_fifths(int written_fifths, int transpose_semitones) {
  int shift = (transpose_semitones * 7) % 12;
  if (shift < 0) shift += 12;
  if (shift > 6) shift -= 12;
  int fifths = written_fifths + shift;
  if (fifths > 7) fifths -= 12;
  if (fifths < -7) fifths += 12;
  return fifths;
}

}  // namespace tutti::music::musicxml
