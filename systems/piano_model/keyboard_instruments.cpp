// SPDX-License-Identifier: MIT
#include <tutti/piano_model/keyboard_instruments.hpp>

#include <algorithm>

#include <nlohmann/json.hpp>

#include <tutti/music/part_names.hpp>
#include <tutti/piano_model/json_document.hpp>

namespace tutti::piano_model {
namespace {

Result<int> midi_key(const JsonReader& reader, const nlohmann::json& object,
                     const std::string& path, const char* key) {
  auto value = reader.number(object, path, key);
  if (!value) return value.error();
  if (*value < 0 || *value > 127 || *value != static_cast<int>(*value)) {
    return reader.error(path + "/" + key, "must be a MIDI key, an integer in [0, 127]");
  }
  return static_cast<int>(*value);
}

Status read_case(const JsonReader& reader, const nlohmann::json& object, const std::string& path,
                 KeyboardCase& out) {
  if (auto ok = reader.check_keys(object, path,
                                  {"cheek_width_mm", "cabinet_height_mm", "cabinet_depth_mm",
                                   "color"});
      !ok) {
    return ok;
  }
  const std::array fields{
      content::NumberField{"cheek_width_mm", &out.cheek_width_mm, 10.0, 500.0},
      content::NumberField{"cabinet_height_mm", &out.cabinet_height_mm, 760.0, 3000.0},
      content::NumberField{"cabinet_depth_mm", &out.cabinet_depth_mm, 200.0, 3000.0}};
  nlohmann::json sizes = object;  // the numbers, without the colour
  sizes.erase("color");
  if (auto ok = reader.read_number_fields(sizes, path, fields, /*required=*/true); !ok) return ok;
  if (!object.contains("color")) return reader.error(path + "/color", "missing");
  const nlohmann::json& color = object.at("color");
  if (!color.is_array() || color.size() != 3) {
    return reader.error(path + "/color", "expected [r, g, b]");
  }
  for (std::size_t i = 0; i < 3; ++i) {
    if (!color[i].is_number() || color[i].get<double>() < 0.0 || color[i].get<double>() > 1.0) {
      return reader.error(path + "/color/" + std::to_string(i), "must be a number in [0, 1]");
    }
    out.color[i] = color[i].get<double>();
  }
  return {};
}

Status read_names(const JsonReader& reader, const nlohmann::json& object, const std::string& path,
                  std::vector<std::string>& out) {
  if (!object.contains("names") || !object.at("names").is_array() || object.at("names").empty()) {
    return reader.error(path + "/names", "expected a non-empty array of part names");
  }
  for (std::size_t i = 0; i < object.at("names").size(); ++i) {
    const nlohmann::json& n = object.at("names")[i];
    if (!n.is_string() || music::part_name_words(n.get<std::string>()).empty()) {
      return reader.error(path + "/names/" + std::to_string(i), "expected a name with a word");
    }
    out.push_back(n.get<std::string>());
  }
  return {};
}

Result<Pedalboard> read_pedalboard(const JsonReader& reader, const nlohmann::json& object,
                                   const std::string& path) {
  if (!object.is_object()) return reader.error(path, "expected an object");
  if (auto ok = reader.check_keys(object, path,
                                  {"lowest_key", "highest_key", "natural_spacing_mm",
                                   "split_below", "names", "seat_raise_mm"});
      !ok) {
    return ok.error();
  }
  Pedalboard out;
  auto lowest = midi_key(reader, object, path, "lowest_key");
  if (!lowest) return lowest.error();
  auto highest = midi_key(reader, object, path, "highest_key");
  if (!highest) return highest.error();
  if (*highest - *lowest < 12) {
    return reader.error(path + "/highest_key", "a pedalboard spans at least an octave");
  }
  auto split = midi_key(reader, object, path, "split_below");
  if (!split) return split.error();
  out.lowest_key = *lowest;
  out.highest_key = *highest;
  out.split_below = *split;
  auto spacing = reader.number(object, path, "natural_spacing_mm");
  if (!spacing) return spacing.error();
  if (*spacing < 40.0 || *spacing > 90.0) {
    return reader.error(path + "/natural_spacing_mm", "must be in [40, 90] mm");
  }
  out.natural_spacing_mm = *spacing;
  auto raise = reader.number_or(object, path, "seat_raise_mm", 0.0);
  if (!raise) return raise.error();
  if (*raise < 0.0 || *raise > 300.0) {
    return reader.error(path + "/seat_raise_mm", "must be in [0, 300] mm");
  }
  out.seat_raise_mm = *raise;
  if (auto ok = read_names(reader, object, path, out.names); !ok) return ok.error();
  return out;
}

Result<KeyboardInstrument> read_instrument(const JsonReader& reader, const nlohmann::json& object,
                                           const std::string& id) {
  const std::string path = "/instruments/" + id;
  if (!object.is_object()) return reader.error(path, "expected an object");
  if (auto ok = reader.check_keys(object, path,
                                  {"player", "lowest_key", "highest_key", "programs", "names",
                                   "model", "case", "touch", "pedalboard", "octave_span_mm"});
      !ok) {
    return ok.error();
  }
  KeyboardInstrument out;
  out.id = id;
  for (const char* key : {"player", "model"}) {
    if (!object.contains(key) || !object.at(key).is_string() ||
        object.at(key).get<std::string>().empty()) {
      return reader.error(path + "/" + key, "expected a non-empty string");
    }
  }
  out.player = object.at("player").get<std::string>();
  out.model = object.at("model").get<std::string>();
  auto lowest = midi_key(reader, object, path, "lowest_key");
  if (!lowest) return lowest.error();
  auto highest = midi_key(reader, object, path, "highest_key");
  if (!highest) return highest.error();
  if (*highest - *lowest < 24) {
    return reader.error(path + "/highest_key", "a keyboard spans at least two octaves");
  }
  out.lowest_key = *lowest;
  out.highest_key = *highest;
  if (object.contains("octave_span_mm")) {
    auto span = reader.number(object, path, "octave_span_mm");
    if (!span) return span.error();
    // Keyboards from 125 mm (the smallest historical octaves) to 170 mm.
    if (*span < 125.0 || *span > 170.0) {
      return reader.error(path + "/octave_span_mm", "must be in [125, 170] mm");
    }
    out.octave_span_mm = *span;
  }
  if (!object.contains("programs") || !object.at("programs").is_array()) {
    return reader.error(path + "/programs", "expected an array of General MIDI programs");
  }
  for (std::size_t i = 0; i < object.at("programs").size(); ++i) {
    const nlohmann::json& p = object.at("programs")[i];
    if (!p.is_number_integer() || p.get<int>() < 0 || p.get<int>() > 127) {
      return reader.error(path + "/programs/" + std::to_string(i), "must be an integer in [0, 127]");
    }
    out.programs.push_back(p.get<int>());
  }
  if (auto ok = read_names(reader, object, path, out.names); !ok) return ok.error();
  if (object.contains("pedalboard")) {
    auto pedalboard = read_pedalboard(reader, object.at("pedalboard"), path + "/pedalboard");
    if (!pedalboard) return pedalboard.error();
    out.pedalboard = std::move(*pedalboard);
  }
  if (object.contains("touch")) {
    if (!object.at("touch").is_object()) return reader.error(path + "/touch", "expected an object");
    // Checked with key_action.json when it is merged over it.
    out.touch = std::make_shared<const nlohmann::json>(object.at("touch"));
  }
  if (object.contains("case")) {
    if (auto ok = read_case(reader, object.at("case"), path + "/case", out.case_shape); !ok) {
      return ok.error();
    }
  }
  return out;
}

}  // namespace

Result<KeyboardInstruments> KeyboardInstruments::load(const std::filesystem::path& path) {
  auto document = read_json_file(path);
  if (!document) return document.error();
  const JsonReader reader(path.filename().string());
  if (auto ok = reader.check_keys(*document, "", {"description", "touch", "source", "instruments"});
      !ok) {
    return ok.error();
  }
  if (!document->contains("instruments") || !document->at("instruments").is_object() ||
      document->at("instruments").empty()) {
    return reader.error("/instruments", "expected an object of instruments");
  }
  KeyboardInstruments out;
  for (const auto& item : document->at("instruments").items()) {
    auto instrument = read_instrument(reader, item.value(), item.key());
    if (!instrument) return instrument.error();
    for (const KeyboardInstrument& other : out.instruments_) {
      for (int program : instrument->programs) {
        if (std::count(other.programs.begin(), other.programs.end(), program) != 0) {
          return reader.error("/instruments/" + item.key() + "/programs",
                              "program " + std::to_string(program) + " is also " + other.id + "'s");
        }
      }
    }
    out.instruments_.push_back(std::move(*instrument));
  }
  return out;
}

const KeyboardInstrument* KeyboardInstruments::find(std::string_view id) const {
  for (const KeyboardInstrument& i : instruments_) {
    if (i.id == id) return &i;
  }
  return nullptr;
}

const KeyboardInstrument* KeyboardInstruments::recognise(const std::vector<std::string>& words,
                                                         int program) const {
  // The longest name found wins ("electric piano" over "piano").
  const KeyboardInstrument* named = nullptr;
  std::size_t named_words = 0;
  for (const KeyboardInstrument& i : instruments_) {
    const std::size_t found = music::longest_phrase(words, i.names);
    if (found > named_words) named = &i, named_words = found;
  }
  if (named != nullptr) return named;
  for (const KeyboardInstrument& i : instruments_) {
    if (std::count(i.programs.begin(), i.programs.end(), program) != 0) return &i;
  }
  return nullptr;
}

std::vector<std::string> KeyboardInstruments::ids() const {
  std::vector<std::string> out;
  for (const KeyboardInstrument& i : instruments_) out.push_back(i.id);
  return out;
}

std::filesystem::path keyboard_instruments_path(const std::filesystem::path& content_dir) {
  return content_dir / "piano" / "instruments.json";
}

const nlohmann::json& KeyboardInstrument::touch_or_piano() const {
  static const nlohmann::json piano_touch = nlohmann::json::object();
  return touch ? *touch : piano_touch;
}

}  // namespace tutti::piano_model
