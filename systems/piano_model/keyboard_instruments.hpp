// SPDX-License-Identifier: MIT
#pragma once
// The keyboard family's instruments (content/piano/instruments.json): the piano, electric
// pianos, harpsichord, clavinet, celesta, organ manual and stage synth. Each has a player ("an
// organist"), a compass (which MIDI keys it has, with the piano's key sizes), how a score names
// it (General MIDI programs, part-name words in English, German, Italian and French) and its
// generated model with the case that model gets; an organ's pedalboard. Loaded strictly: an unknown key is an error
// naming the file and JSON path.

#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include <tutti/core/result.hpp>

namespace tutti::piano_model {

struct KeyboardCase {
  double cheek_width_mm = 60.0;
  double cabinet_height_mm = 1250.0;
  double cabinet_depth_mm = 600.0;
  std::array<double, 3> color{0.01, 0.01, 0.012};  // linear RGB
};

// An organ's pedalboard: the keys the feet play, flat and parallel (the AGO standard's are
// concave and radiating; the spacing of the naturals is the standard's).
struct Pedalboard {
  int lowest_key = 36;
  int highest_key = 67;
  double natural_spacing_mm = 63.5;
  // Without a pedal part or staff, the lowest line's notes below this key are the feet's.
  int split_below = 48;
  std::vector<std::string> names;  // a part named so is the pedals' ("pedal", "pédale")
  // The console's keys and the player's bench raised on a platform by this much (mm), so the
  // seat stands as high over the pedals as an organ bench.
  double seat_raise_mm = 0.0;
  bool contains(int key) const { return key >= lowest_key && key <= highest_key; }
};

struct KeyboardInstrument {
  std::string id;      // "organ"
  std::string player;  // "organist"
  int lowest_key = 21;
  int highest_key = 108;
  // Seven white keys' width (mm); 0 = the piano's (content/piano/keyboard.json, 164.5 mm).
  double octave_span_mm = 0.0;
  std::vector<int> programs;       // General MIDI, 0-based
  std::vector<std::string> names;  // lower case; a name of several words is matched as a phrase
  std::string model;               // generated model file ("keyboard_organ.glb")
  KeyboardCase case_shape;         // the generated model's case (the piano's: dimensions.json)
  // Merged over key_action.json (key_action::load_key_action): where in the travel a note sounds
  // and stops, and its velocity. Null = the piano's touch. Behind a pointer so that this header,
  // which most of the keyboard family includes, does not pull in the whole JSON library.
  std::shared_ptr<const nlohmann::json> touch;
  // *touch, or an empty object (the piano's touch) when there is none.
  const nlohmann::json& touch_or_piano() const;
  std::optional<Pedalboard> pedalboard;  // an organ's; none for the others
  bool contains(int key) const { return key >= lowest_key && key <= highest_key; }
};

class KeyboardInstruments {
 public:
  static Result<KeyboardInstruments> load(const std::filesystem::path& path);

  const std::vector<KeyboardInstrument>& all() const { return instruments_; }
  // nullptr when there is none of that id.
  const KeyboardInstrument* find(std::string_view id) const;
  // The instrument a part's name or program stands for: a name word or phrase first (any
  // instrument), else the program; nullptr when neither says a keyboard. `words` are the part
  // name's lower-case words in order.
  const KeyboardInstrument* recognise(const std::vector<std::string>& words, int program) const;
  std::vector<std::string> ids() const;

 private:
  std::vector<KeyboardInstrument> instruments_;
};

// content_dir / "piano" / "instruments.json".
std::filesystem::path keyboard_instruments_path(const std::filesystem::path& content_dir);

}  // namespace tutti::piano_model
