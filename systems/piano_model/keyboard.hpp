// SPDX-License-Identifier: MIT
#pragma once
// The 88-key piano keyboard's geometry: the x position (millimetres, along the keyboard, 0 at
// the left edge of the lowest key) of every key's centre line, and which keys are black.
// Numbers come from content/piano/keyboard.json (standard key dimensions, see content/piano/
// README.md); nothing is hard-coded here.

#include <array>
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include <tutti/core/result.hpp>

namespace tutti::piano_model {

class Keyboard {
 public:
  // Errors name the file and the JSON path: "keyboard.json: /black_key_centres_mm/F#: ...".
  static Result<Keyboard> load(const std::filesystem::path& path);
  // The same keys with another compass (an instrument's: keyboard_instruments.hpp), and with
  // `octave_span_mm` > 0 every key's width and place scaled to that octave.
  static Result<Keyboard> load(const std::filesystem::path& path, int lowest_key, int highest_key,
                               double octave_span_mm = 0.0);
  static Result<Keyboard> from_json(const nlohmann::json& document, const std::string& file_name);

  int lowest_key() const { return lowest_key_; }    // MIDI key, 21 (A0) on a standard piano
  int highest_key() const { return highest_key_; }  // 108 (C8)
  int key_count() const { return highest_key_ - lowest_key_ + 1; }
  bool contains(int key) const { return key >= lowest_key_ && key <= highest_key_; }

  // Centre of the key's playing surface. Precondition: contains(key).
  double x_mm(int key) const { return x_mm_[static_cast<std::size_t>(key)]; }
  bool is_black(int key) const;
  double white_key_width_mm() const { return white_key_width_mm_; }  // δ in the paper

 private:
  std::array<double, 128> x_mm_{};
  int lowest_key_ = 21;
  int highest_key_ = 108;
  double white_key_width_mm_ = 23.5;
};

}  // namespace tutti::piano_model
