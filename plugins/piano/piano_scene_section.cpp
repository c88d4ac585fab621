// SPDX-License-Identifier: MIT
#include <tutti/piano/piano_scene_section.hpp>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include <tutti/core/did_you_mean.hpp>
#include <tutti/piano/keyboard_players.hpp>
#include <tutti/scene/performance_marks.hpp>

namespace tutti::piano {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using scene::Scene;
using scene::SectionContext;

// Two pianos' benches at least this far apart on the floor: the generated upright is 1.35 m wide.
// A coarse rule (it does not test the cases' outlines), so that two pianists never share a piano.
constexpr double kPianoSpacing_m = 1.4;

double floor_distance_m(const scene::Vec3& a, const scene::Vec3& b) {
  return std::hypot(a.x - b.x, a.z - b.z);
}

std::string join(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

// "pins": [{"time_s": t, "key": k, "finger": f}, ...] of a keyboard player.
Status parse_finger_pins(const scene::FieldReader& reader, const nlohmann::json& pianist,
                         const std::string& path, std::vector<FingerPin>& out) {
  if (!pianist.contains("pins")) return Status::success();
  const std::string where = path + "/pins";
  const nlohmann::json& list = pianist.at("pins");
  if (!list.is_array()) return reader.error(where, "expected an array");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string item = where + "/" + std::to_string(i);
    if (auto ok = reader.json().check_keys(list[i], item, {"time_s", "key", "finger"}); !ok) {
      return ok;
    }
    auto time =
        reader.number(list[i], item, "time_s", scene::kEarliestMark_s, scene::kLatestMark_s);
    if (!time) return time.error();
    if (!list[i].contains("key")) return reader.error(scene::join_path(item, "key"), "missing");
    auto key = reader.integer_or(list[i], item, "key", 0, 127, 0);
    if (!key) return key.error();
    if (!list[i].contains("finger"))
      return reader.error(scene::join_path(item, "finger"), "missing");
    auto finger = reader.integer_or(list[i], item, "finger", 1, 5, 1);
    if (!finger) return finger.error();
    FingerPin pin;
    pin.time_s = *time;
    pin.key = static_cast<int>(*key);
    pin.finger = static_cast<int>(*finger);
    for (std::size_t j = 0; j < out.size(); ++j) {
      if (out[j].key == pin.key && std::abs(out[j].time_s - pin.time_s) < 1e-6) {
        return reader.error(
            item, "a second pin on the same note (also " + where + "/" + std::to_string(j) + ")");
      }
    }
    out.push_back(pin);
  }
  return Status::success();
}

// "style": a style of content/piano/styles.json; "sound": "score" (as written) or "keys" (as
// the simulated keys sound it).
Status parse_pianist_style(const SectionContext& context, const json& object,
                           KeyboardPlayer& pianist) {
  const scene::FieldReader& reader = context.fields();
  const std::string& path = pianist.pointer;
  auto sound = reader.string_or(object, path, "sound", "score");
  if (!sound) return sound.error();
  if (*sound != "score" && *sound != "keys") {
    return context.error(path + "/sound",
                         "expected \"score\" or \"keys\", not \"" + *sound + "\"");
  }
  pianist.sound_from_keys = *sound == "keys";
  if (!object.contains("style")) return Status::success();
  auto style = reader.string_or(object, path, "style", "");
  if (!style) return style.error();
  auto styles = context.content_json(fs::path("piano") / "styles.json");
  if (!styles) return styles.error();
  std::vector<std::string> names;
  if (styles->contains("styles") && styles->at("styles").is_object()) {
    for (const auto& item : styles->at("styles").items()) names.push_back(item.key());
  }
  if (std::find(names.begin(), names.end(), *style) == names.end()) {
    return context.error(path + "/style", "unknown performance style \"" + *style +
                                               "\" (styles.json has: " + join(names) + ")");
  }
  pianist.style = *style;
  return Status::success();
}

Status parse_pianist(const SectionContext& context, const json& object, const Scene& scene,
                     KeyboardPlayer& pianist) {
  const scene::FieldReader& reader = context.fields();
  const std::string& path = pianist.pointer;
  if (!object.is_object()) return context.error(path, "expected an object");
  if (auto ok = reader.json().check_keys(
          object, path,
          {"name", "instrument", "parts", "music_file", "hand_size", "position_m", "facing_deg", "seed", "variation",
           "character", "hands", "pins", "style", "sound"});
      !ok) {
    return ok;
  }
  if (object.contains("name")) {
    auto name = reader.string(object, path, "name");
    if (!name) return name.error();
    pianist.name = *name;
  }
  if (!object.contains("parts")) return context.error(path + "/parts", "missing");
  const json& parts = object.at("parts");
  if (!parts.is_array()) return context.error(path + "/parts", "expected an array of part names");
  if (parts.empty()) return context.error(path + "/parts", "must name at least one part");
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string where = path + "/parts/" + std::to_string(i);
    if (!parts[i].is_string()) return context.error(where, "expected a string");
    if (parts[i].get<std::string>().empty()) return context.error(where, "must not be empty");
    pianist.parts.push_back(parts[i].get<std::string>());
  }
  auto music_file = context.music_index(object, path, scene);
  if (!music_file) return music_file.error();
  pianist.music_file = *music_file;

  // Hand sizes are the presets of content/piano/hands.json.
  auto hands = context.content_json(fs::path("piano") / "hands.json");
  if (!hands) return hands.error();
  std::vector<std::string> presets;
  if (hands->contains("presets") && hands->at("presets").is_object()) {
    for (const auto& item : hands->at("presets").items()) presets.push_back(item.key());
  }
  std::string fallback = presets.empty() ? "" : presets.front();
  if (hands->contains("default_preset") && hands->at("default_preset").is_string()) {
    fallback = hands->at("default_preset").get<std::string>();
  }
  auto hand_size = reader.string_or(object, path, "hand_size", fallback);
  if (!hand_size) return hand_size.error();
  if (std::find(presets.begin(), presets.end(), *hand_size) == presets.end()) {
    return context.error(path + "/hand_size", "unknown hand size \"" + *hand_size +
                                                   "\" (hands.json has: " + join(presets) + ")");
  }
  pianist.hand_size = *hand_size;

  // Instruments are those of content/piano/instruments.json.
  auto instruments = context.content_json(fs::path("piano") / "instruments.json");
  if (!instruments) return instruments.error();
  std::vector<std::string> ids;
  if (instruments->contains("instruments") && instruments->at("instruments").is_object()) {
    for (const auto& item : instruments->at("instruments").items()) ids.push_back(item.key());
  }
  auto instrument = reader.string_or(object, path, "instrument", "piano");
  if (!instrument) return instrument.error();
  if (std::find(ids.begin(), ids.end(), *instrument) == ids.end()) {
    const std::vector<std::string_view> names(ids.begin(), ids.end());
    return context.error(path + "/instrument", "unknown keyboard instrument \"" + *instrument +
                                                   "\"" + did_you_mean(*instrument, names) +
                                                   " (instruments.json has: " + join(ids) + ")");
  }
  pianist.instrument = *instrument;
  const json& entry = instruments->at("instruments").at(*instrument);
  if (!object.contains("name")) {
    pianist.name = entry.contains("player") && entry.at("player").is_string()
                       ? entry.at("player").get<std::string>()
                       : std::string("pianist");
  }

  auto position = reader.vec3_or(object, path, "position_m", 100.0, pianist.position_m);
  if (!position) return position.error();
  pianist.position_m = *position;
  auto facing = reader.number_or(object, path, "facing_deg", -360.0, 360.0, pianist.facing_deg);
  if (!facing) return facing.error();
  pianist.facing_deg = *facing;
  if (object.contains("seed")) {
    auto seed = reader.seed(object, path, "seed");
    if (!seed) return seed.error();
    pianist.seed = *seed;
    pianist.seed_given = true;
  }
  if (object.contains("variation")) {
    if (auto ok = context.variation(object.at("variation"), path + "/variation", pianist.variation);
        !ok) {
      return ok;
    }
  }
  if (auto ok =
          context.mapping(object, path, "character", scene::character_kind(), pianist.character_mapping);
      !ok) {
    return ok;
  }
  if (auto ok = parse_finger_pins(reader, object, path, pianist.pins); !ok) return ok;
  if (auto ok = parse_pianist_style(context, object, pianist); !ok) return ok;
  return context.mapping(object, path, "hands", scene::hand_kind(), pianist.hands_mapping);
}

}  // namespace

std::uint64_t keyboard_seed_stream(std::size_t index) {
  return index == 0 ? 0 : (std::uint64_t{1} << 32) + index;
}

Status PianoSceneSection::read(const json& document, const SectionContext& context,
                               Scene& scene) const {
  if (document.contains("pianist") && document.contains("pianists")) {
    return context.error("/pianists", "give \"pianists\" or the older \"pianist\", not both");
  }
  std::vector<const json*> objects;
  std::vector<std::string> pointers;
  if (document.contains("pianist")) {
    objects.push_back(&document.at("pianist"));
    pointers.emplace_back("/pianist");
  } else if (document.contains("pianists")) {
    const json& pianists = document.at("pianists");
    if (!pianists.is_array()) return context.error("/pianists", "expected an array");
    if (pianists.empty()) return context.error("/pianists", "must list at least one pianist");
    for (std::size_t i = 0; i < pianists.size(); ++i) {
      objects.push_back(&pianists[i]);
      pointers.push_back("/pianists/" + std::to_string(i));
    }
  }
  if (objects.empty()) return {};
  std::vector<KeyboardPlayer>& players = edit_keyboard_players(scene);
  for (std::size_t i = 0; i < objects.size(); ++i) {
    KeyboardPlayer pianist;
    pianist.pointer = pointers[i];
    if (auto ok = parse_pianist(context, *objects[i], scene, pianist); !ok) return ok;
    // Unnamed players are called for their instrument: "pianist", "pianist 2", "organist", ...
    if (objects[i]->is_object() && !objects[i]->contains("name")) {
      const std::string base = pianist.name;
      const auto taken = [&](const std::string& name) {
        return std::any_of(players.begin(), players.end(),
                           [&](const KeyboardPlayer& other) { return other.name == name; });
      };
      for (int k = 2; taken(pianist.name); ++k) pianist.name = base + " " + std::to_string(k);
    }
    for (const KeyboardPlayer& other : players) {
      if (other.name == pianist.name) {
        return context.error(pianist.pointer + "/name", "duplicate pianist name \"" +
                                                            pianist.name + "\" (also " +
                                                            other.pointer + ")");
      }
      if (floor_distance_m(other.position_m, pianist.position_m) < kPianoSpacing_m) {
        return context.error(pianist.pointer + "/position_m",
                             "the piano stands on " + other.pointer + "'s (benches " +
                                 scene::format_number(floor_distance_m(other.position_m, pianist.position_m)) +
                                 " m apart; two pianos need " + scene::format_number(kPianoSpacing_m) +
                                 " m)");
      }
    }
    if (!pianist.seed_given) {
      pianist.seed = scene::derive_seed(scene.seed, keyboard_seed_stream(i));
    }
    // A note has one player: a part is played by one keyboard player.
    for (std::size_t p = 0; p < pianist.parts.size(); ++p) {
      scene.part_claims.push_back({pianist.parts[p], pianist.music_file,
                                   pianist.pointer + "/parts/" + std::to_string(p),
                                   pianist.pointer, /*exclusive=*/true});
    }
    players.push_back(std::move(pianist));
  }
  return {};
}

}  // namespace tutti::piano
