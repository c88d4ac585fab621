// SPDX-License-Identifier: MIT
#include <tutti/music/pitch.hpp>

#include <array>
#include <cctype>
#include <charconv>

namespace tutti::music {

namespace {
std::optional<int> step_semitone(char step) {
  switch (std::toupper(static_cast<unsigned char>(step))) {
    case 'C':
      return 0;
    case 'D':
      return 2;
    case 'E':
      return 4;
    case 'F':
      return 5;
    case 'G':
      return 7;
    case 'A':
      return 9;
    case 'B':
      return 11;
    default:
      return std::nullopt;
  }
}
}  // namespace

std::optional<int> midi_key(char step, int alter, int octave) {
  const auto semitone = step_semitone(step);
  if (!semitone || octave < -2 || octave > 10 || alter < -4 || alter > 4) return std::nullopt;
  const int key = (octave + 1) * 12 + *semitone + alter;
  if (key < 0 || key > 127) return std::nullopt;
  return key;
}

std::optional<int> parse_pitch_name(std::string_view name) {
  if (name.empty()) return std::nullopt;
  const char step = name.front();
  std::size_t i = 1;
  int alter = 0;
  for (; i < name.size(); ++i) {
    const char c = name[i];
    if (c == '#') {
      ++alter;
    } else if (c == 'x') {
      alter += 2;
    } else if (c == 'b') {
      --alter;
    } else {
      break;
    }
  }
  if (i >= name.size()) return std::nullopt;
  int octave = 0;
  const char* first = name.data() + i;
  const char* last = name.data() + name.size();
  const auto [end, ec] = std::from_chars(first, last, octave);
  if (ec != std::errc{} || end != last) return std::nullopt;
  return midi_key(step, alter, octave);
}

std::string pitch_name(int key) {
  static constexpr std::array<const char*, 12> kNames = {"C",  "C#", "D",  "D#", "E",  "F",
                                                         "F#", "G",  "G#", "A",  "A#", "B"};
  return std::string(kNames[static_cast<std::size_t>(key % 12)]) + std::to_string(key / 12 - 1);
}

}  // namespace tutti::music
