// SPDX-License-Identifier: MIT
#include <tutti/piano_model/keyboard.hpp>

#include <nlohmann/json.hpp>

#include <tutti/music/pitch.hpp>
#include <tutti/piano_model/json_document.hpp>

namespace tutti::piano_model {
namespace {

constexpr std::array<const char*, 12> kPitchClassNames = {"C",  "C#", "D",  "D#", "E",  "F",
                                                          "F#", "G",  "G#", "A",  "A#", "B"};
// Index of each white pitch class among the seven white keys of an octave (-1 for black).
constexpr std::array<int, 12> kWhiteIndex = {0, -1, 1, -1, 2, 3, -1, 4, -1, 5, -1, 6};

int floor_div(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

}  // namespace

bool Keyboard::is_black(int key) const { return music::is_black_key(key); }

Result<Keyboard> Keyboard::load(const std::filesystem::path& path) {
  auto document = read_json_file(path);
  if (!document) return document.error();
  return from_json(*document, path.filename().string());
}

Result<Keyboard> Keyboard::load(const std::filesystem::path& path, int lowest_key, int highest_key,
                                double octave_span_mm) {
  auto document = read_json_file(path);
  if (!document) return document.error();
  (*document)["lowest_key"] = lowest_key;
  (*document)["highest_key"] = highest_key;
  const nlohmann::json& width = (*document)["white_key_width_mm"];
  if (octave_span_mm > 0.0 && width.is_number() && width.get<double>() > 0.0) {
    const double scale = octave_span_mm / (7.0 * width.get<double>());
    (*document)["white_key_width_mm"] = octave_span_mm / 7.0;
    nlohmann::json& black = (*document)["black_key_centres_mm"];
    if (black.is_object()) {
      for (auto& centre : black) {
        if (centre.is_number()) centre = centre.get<double>() * scale;
      }
    }
  }
  return from_json(*document, path.filename().string());
}

Result<Keyboard> Keyboard::from_json(const nlohmann::json& document, const std::string& file_name) {
  const JsonReader reader(file_name);
  if (auto ok = reader.check_keys(document, "",
                                  {"description", "source", "lowest_key", "highest_key",
                                   "white_key_width_mm", "black_key_centres_mm"});
      !ok) {
    return ok.error();
  }
  auto lowest = reader.number(document, "", "lowest_key");
  if (!lowest) return lowest.error();
  auto highest = reader.number(document, "", "highest_key");
  if (!highest) return highest.error();
  auto width = reader.number(document, "", "white_key_width_mm");
  if (!width) return width.error();
  if (*lowest < 0 || *highest > 127 || *lowest > *highest || *lowest != static_cast<int>(*lowest) ||
      *highest != static_cast<int>(*highest)) {
    return reader.error("/lowest_key", "keys must be integers with 0 <= lowest <= highest <= 127");
  }
  if (*width <= 0) return reader.error("/white_key_width_mm", "must be positive");

  Keyboard keyboard;
  keyboard.lowest_key_ = static_cast<int>(*lowest);
  keyboard.highest_key_ = static_cast<int>(*highest);
  keyboard.white_key_width_mm_ = *width;
  const double octave_mm = 7.0 * *width;

  // Centre of each pitch class measured from the left edge of its octave's C.
  std::array<double, 12> centre{};
  if (!document.contains("black_key_centres_mm")) {
    return reader.error("/black_key_centres_mm", "missing");
  }
  const nlohmann::json& black = document.at("black_key_centres_mm");
  if (auto ok = reader.check_keys(black, "/black_key_centres_mm", {"C#", "D#", "F#", "G#", "A#"});
      !ok) {
    return ok.error();
  }
  for (int pc = 0; pc < 12; ++pc) {
    const auto upc = static_cast<std::size_t>(pc);
    if (kWhiteIndex[upc] >= 0) {
      centre[upc] = (kWhiteIndex[upc] + 0.5) * *width;
      continue;
    }
    auto value = reader.number(black, "/black_key_centres_mm", kPitchClassNames[upc]);
    if (!value) return value.error();
    // A black key sits between its two white neighbours' centres.
    const double below = (kWhiteIndex[upc - 1] + 0.5) * *width;
    const double above = (kWhiteIndex[upc + 1] + 0.5) * *width;
    if (*value <= below || *value >= above) {
      return reader.error(std::string("/black_key_centres_mm/") + kPitchClassNames[upc],
                          "must lie between the centres of the neighbouring white keys");
    }
    centre[upc] = *value;
  }

  auto absolute = [&](int key) {
    const int octave = floor_div(key, 12);
    return octave * octave_mm + centre[static_cast<std::size_t>(key - octave * 12)];
  };
  // Origin: the left edge of the lowest key (its centre minus half a white key for a white key,
  // or minus half the gap to the white key below for a black one; both are half a white key in
  // standard geometry closely enough for an origin).
  const double origin = absolute(keyboard.lowest_key_) - 0.5 * *width;
  for (int key = 0; key < 128; ++key) {
    keyboard.x_mm_[static_cast<std::size_t>(key)] = absolute(key) - origin;
  }
  return keyboard;
}

}  // namespace tutti::piano_model
