// SPDX-License-Identifier: MIT
#include <tutti/scene/load_scene.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <string_view>
#include <system_error>

#include <tutti/brass_model/instrument.hpp>
#include <tutti/content/content_dir.hpp>
#include <tutti/core/did_you_mean.hpp>
#include <tutti/core/file_io.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/scene/asset_mapping.hpp>
#include <tutti/scene/json_fields.hpp>
#include <tutti/scene/performance_marks.hpp>

namespace tutti::scene {
namespace {

namespace fs = std::filesystem;

// Two pianos' benches at least this far apart on the floor: the generated upright is 1.35 m wide.
// A coarse rule (it does not test the cases' outlines), so that two pianists never share a piano.
constexpr double kPianoSpacing_m = 1.4;

double floor_distance_m(const Vec3& a, const Vec3& b) {
  return std::hypot(a.x - b.x, a.z - b.z);
}
using nlohmann::json;

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

std::string join(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

bool is_file(const fs::path& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

class SceneParser {
 public:
  SceneParser(const std::string& file_name, fs::path base_dir, fs::path content_dir)
      : reader_(file_name),
        base_dir_(std::move(base_dir)),
        content_dir_(content_dir.empty() ? content::default_content_dir() : std::move(content_dir)) {}

  Result<Scene> parse(const json& document);

 private:
  Status parse_music(const json& document, Scene& scene) const;
  Status parse_performer(const json& object, const std::string& path, const Scene& scene,
                         Performer& performer);
  Status parse_pianist(const json& object, const Scene& scene, Pianist& pianist) const;
  Status parse_pianist_style(const json& object, Pianist& pianist) const;
  Status parse_pianists(const json& document, Scene& scene) const;
  Status parse_variation(const json& object, const std::string& path, Variation& variation) const;
  Status parse_mapping(const json& object, const std::string& path, const char* key,
                       AssetKind expected, fs::path& out) const;
  Status parse_instrument_mapping(const json& object, const std::string& path,
                                  const std::string& instrument, fs::path& out) const;
  Status parse_cameras(const json& document, Scene& scene) const;
  Status parse_shots(const json& document, Scene& scene) const;
  Status parse_light(const json& object, const std::string& path, DirectionalLight& light) const;
  Status parse_lights(const json& document, Lights& lights) const;
  Status parse_output(const json& document, Output& output) const;
  Result<std::size_t> music_index(const json& object, const std::string& path,
                                  const Scene& scene) const;
  const std::vector<std::string>& instrument_ids();

  FieldReader reader_;
  fs::path base_dir_;
  fs::path content_dir_;
  std::vector<std::string> instrument_ids_;
  bool instrument_ids_listed_ = false;
};

Status SceneParser::parse_music(const json& document, Scene& scene) const {
  if (!document.contains("music")) return reader_.error("/music", "missing");
  const json& music = document.at("music");
  auto add = [&](const json& entry, const std::string& where) -> Status {
    if (!entry.is_string()) return reader_.error(where, "expected a string (a file path)");
    const std::string written = entry.get<std::string>();
    if (written.empty()) return reader_.error(where, "must not be empty");
    const fs::path resolved = (base_dir_ / written).lexically_normal();
    if (!is_file(resolved)) return reader_.error(where, "no such file \"" + written + "\"");
    scene.music.push_back(resolved);
    return {};
  };
  if (music.is_string()) return add(music, "/music");
  if (!music.is_array()) return reader_.error("/music", "expected a file path or an array of them");
  if (music.empty()) return reader_.error("/music", "must name at least one file");
  for (std::size_t i = 0; i < music.size(); ++i) {
    if (auto ok = add(music[i], "/music/" + std::to_string(i)); !ok) return ok;
  }
  return {};
}

const std::vector<std::string>& SceneParser::instrument_ids() {
  if (!instrument_ids_listed_) {
    instrument_ids_listed_ = true;
    std::error_code ec;
    for (fs::directory_iterator it(content_dir_ / "instruments", ec), end; !ec && it != end;
         it.increment(ec)) {
      if (it->path().extension() == ".json") instrument_ids_.push_back(it->path().stem().string());
    }
    std::sort(instrument_ids_.begin(), instrument_ids_.end());
  }
  return instrument_ids_;
}

Result<std::size_t> SceneParser::music_index(const json& object, const std::string& path,
                                             const Scene& scene) const {
  auto index = reader_.integer_or(object, path, "music_file", 0,
                                  static_cast<std::int64_t>(scene.music.size()) - 1, 0);
  if (!index) return index.error();
  return static_cast<std::size_t>(*index);
}

Status SceneParser::parse_variation(const json& object, const std::string& path,
                                    Variation& variation) const {
  if (!object.is_object()) return reader_.error(path, "expected an object");
  for (const auto& item : object.items()) {
    const auto field = std::find_if(kVariationFields.begin(), kVariationFields.end(),
                                    [&](const VariationField& f) { return f.key == item.key(); });
    if (field == kVariationFields.end()) {
      std::vector<std::string> known;
      for (const VariationField& f : kVariationFields) known.emplace_back(f.key);
      const std::vector<std::string_view> names(known.begin(), known.end());
      return reader_.error(join_path(path, item.key()),
                           "unknown key" + did_you_mean(item.key(), names) + " (known: " +
                               join(known) + ")");
    }
    auto value = reader_.number(object, path, item.key().c_str(), 0.0, 1.0);
    if (!value) return value.error();
    variation.*(field->value) = *value;
  }
  return {};
}

Status SceneParser::parse_mapping(const json& object, const std::string& path, const char* key,
                                  AssetKind expected, fs::path& out) const {
  if (!object.contains(key)) return {};
  auto written = reader_.string(object, path, key);
  if (!written) return written.error();
  const std::string where = join_path(path, key);
  const fs::path resolved = (base_dir_ / *written).lexically_normal();
  if (!is_file(resolved)) return reader_.error(where, "no such file \"" + *written + "\"");
  // A character or a pianist's hands may be the model file itself: the stage recognises the
  // humanoid or the hands in it (engine/humanoid); instruments still need a mapping file.
  const std::string extension = resolved.extension().string();
  if (extension == ".glb" || extension == ".gltf" || extension == ".vrm") {
    if (expected != AssetKind::character && expected != AssetKind::hand) {
      return reader_.error(where, "\"" + *written + "\" is a model; a " +
                                      std::string(asset_kind_name(expected)) +
                                      " needs a mapping file (only characters and hands are "
                                      "recognised by themselves)");
    }
    out = resolved;
    return {};
  }
  auto mapping = load_asset_mapping(resolved);
  if (!mapping) return mapping.error();
  if (mapping->kind != expected) {
    return reader_.error(where, "\"" + *written + "\" maps a " +
                                    std::string(asset_kind_name(mapping->kind)) + ", expected a " +
                                    std::string(asset_kind_name(expected)));
  }
  out = resolved;
  return {};
}

Status SceneParser::parse_instrument_mapping(const json& object, const std::string& path,
                                             const std::string& instrument, fs::path& out) const {
  if (!object.contains("instrument_model")) return {};
  auto loaded = brass::load_instrument(content_dir_ / "instruments" / (instrument + ".json"));
  if (!loaded) return loaded.error();
  AssetKind kind = AssetKind::trombone;
  if (loaded->mechanism == brass::Mechanism::valves) {
    if (loaded->valves.size() != 3) {
      return reader_.error(
          join_path(path, "instrument_model"),
          "user models exist for trumpets and trombones only, not " + loaded->display_name);
    }
    kind = AssetKind::trumpet;
  }
  return parse_mapping(object, path, "instrument_model", kind, out);
}

Status SceneParser::parse_performer(const json& object, const std::string& path, const Scene& scene,
                                    Performer& performer) {
  if (auto ok = reader_.json().check_keys(
          object, path,
          {"name", "instrument", "part", "voice", "music_file", "position_m", "facing_deg",
           "stance", "music_stand", "lead", "seed", "variation", "character", "instrument_model",
           "breaths", "expressions"});
      !ok) {
    return ok;
  }
  auto name = reader_.string(object, path, "name");
  if (!name) return name.error();
  performer.name = *name;

  auto instrument = reader_.string(object, path, "instrument");
  if (!instrument) return instrument.error();
  const auto& ids = instrument_ids();
  if (std::find(ids.begin(), ids.end(), *instrument) == ids.end()) {
    return reader_.error(join_path(path, "instrument"),
                         "unknown instrument \"" + *instrument + "\" (known: " + join(ids) + ")");
  }
  performer.instrument = *instrument;

  auto part = reader_.string(object, path, "part");
  if (!part) return part.error();
  performer.part = *part;
  auto voice = reader_.integer_or(object, path, "voice", 1, 16, 1);
  if (!voice) return voice.error();
  performer.voice = static_cast<int>(*voice);
  auto music_file = music_index(object, path, scene);
  if (!music_file) return music_file.error();
  performer.music_file = *music_file;

  auto position = reader_.vec3(object, path, "position_m", 100.0);
  if (!position) return position.error();
  performer.position_m = *position;
  auto facing = reader_.number_or(object, path, "facing_deg", -360.0, 360.0, 0.0);
  if (!facing) return facing.error();
  performer.facing_deg = *facing;
  auto stance = reader_.string_or(object, path, "stance", "standing");
  if (!stance) return stance.error();
  if (*stance == "standing") {
    performer.stance = Stance::standing;
  } else if (*stance == "seated") {
    performer.stance = Stance::seated;
  } else {
    return reader_.error(join_path(path, "stance"), "must be \"standing\" or \"seated\"");
  }
  auto stand = reader_.boolean_or(object, path, "music_stand", true);
  if (!stand) return stand.error();
  performer.music_stand = *stand;
  auto lead = reader_.boolean_or(object, path, "lead", false);
  if (!lead) return lead.error();
  performer.lead = *lead;
  if (object.contains("seed")) {
    auto seed = reader_.seed(object, path, "seed");
    if (!seed) return seed.error();
    performer.seed = *seed;
    performer.seed_given = true;
  }
  if (object.contains("variation")) {
    if (auto ok = parse_variation(object.at("variation"), path + "/variation", performer.variation);
        !ok) {
      return ok;
    }
  }
  if (auto ok = parse_mapping(object, path, "character", AssetKind::character,
                              performer.character_mapping);
      !ok) {
    return ok;
  }
  if (auto ok = parse_performer_marks(reader_, object, path, performer); !ok) return ok;
  return parse_instrument_mapping(object, path, performer.instrument, performer.instrument_mapping);
}

Status SceneParser::parse_pianist(const json& object, const Scene& scene, Pianist& pianist) const {
  const std::string& path = pianist.pointer;
  if (!object.is_object()) return reader_.error(path, "expected an object");
  if (auto ok = reader_.json().check_keys(
          object, path,
          {"name", "instrument", "parts", "music_file", "hand_size", "position_m", "facing_deg", "seed", "variation",
           "character", "hands", "pins", "style", "sound"});
      !ok) {
    return ok;
  }
  if (object.contains("name")) {
    auto name = reader_.string(object, path, "name");
    if (!name) return name.error();
    pianist.name = *name;
  }
  if (!object.contains("parts")) return reader_.error(path + "/parts", "missing");
  const json& parts = object.at("parts");
  if (!parts.is_array()) return reader_.error(path + "/parts", "expected an array of part names");
  if (parts.empty()) return reader_.error(path + "/parts", "must name at least one part");
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string where = path + "/parts/" + std::to_string(i);
    if (!parts[i].is_string()) return reader_.error(where, "expected a string");
    if (parts[i].get<std::string>().empty()) return reader_.error(where, "must not be empty");
    pianist.parts.push_back(parts[i].get<std::string>());
  }
  auto music_file = music_index(object, path, scene);
  if (!music_file) return music_file.error();
  pianist.music_file = *music_file;

  // Hand sizes are the presets of content/piano/hands.json.
  const fs::path hands_file = content_dir_ / "piano" / "hands.json";
  auto hands = read_scene_json(hands_file);
  if (!hands) return hands.error();
  std::vector<std::string> presets;
  if (hands->contains("presets") && hands->at("presets").is_object()) {
    for (const auto& item : hands->at("presets").items()) presets.push_back(item.key());
  }
  std::string fallback = presets.empty() ? "" : presets.front();
  if (hands->contains("default_preset") && hands->at("default_preset").is_string()) {
    fallback = hands->at("default_preset").get<std::string>();
  }
  auto hand_size = reader_.string_or(object, path, "hand_size", fallback);
  if (!hand_size) return hand_size.error();
  if (std::find(presets.begin(), presets.end(), *hand_size) == presets.end()) {
    return reader_.error(path + "/hand_size", "unknown hand size \"" + *hand_size +
                                                   "\" (hands.json has: " + join(presets) + ")");
  }
  pianist.hand_size = *hand_size;

  // Instruments are those of content/piano/instruments.json.
  auto instruments = read_scene_json(content_dir_ / "piano" / "instruments.json");
  if (!instruments) return instruments.error();
  std::vector<std::string> ids;
  if (instruments->contains("instruments") && instruments->at("instruments").is_object()) {
    for (const auto& item : instruments->at("instruments").items()) ids.push_back(item.key());
  }
  auto instrument = reader_.string_or(object, path, "instrument", "piano");
  if (!instrument) return instrument.error();
  if (std::find(ids.begin(), ids.end(), *instrument) == ids.end()) {
    const std::vector<std::string_view> names(ids.begin(), ids.end());
    return reader_.error(path + "/instrument", "unknown keyboard instrument \"" + *instrument +
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

  auto position = reader_.vec3_or(object, path, "position_m", 100.0, pianist.position_m);
  if (!position) return position.error();
  pianist.position_m = *position;
  auto facing = reader_.number_or(object, path, "facing_deg", -360.0, 360.0, pianist.facing_deg);
  if (!facing) return facing.error();
  pianist.facing_deg = *facing;
  if (object.contains("seed")) {
    auto seed = reader_.seed(object, path, "seed");
    if (!seed) return seed.error();
    pianist.seed = *seed;
    pianist.seed_given = true;
  }
  if (object.contains("variation")) {
    if (auto ok = parse_variation(object.at("variation"), path + "/variation", pianist.variation);
        !ok) {
      return ok;
    }
  }
  if (auto ok =
          parse_mapping(object, path, "character", AssetKind::character, pianist.character_mapping);
      !ok) {
    return ok;
  }
  if (auto ok = parse_finger_pins(reader_, object, path, pianist.pins); !ok) return ok;
  if (auto ok = parse_pianist_style(object, pianist); !ok) return ok;
  return parse_mapping(object, path, "hands", AssetKind::hand, pianist.hands_mapping);
}

// "style": a style of content/piano/styles.json; "sound": "score" (as written) or "keys" (as
// the simulated keys sound it).
Status SceneParser::parse_pianists(const json& document, Scene& scene) const {
  if (document.contains("pianist") && document.contains("pianists")) {
    return reader_.error("/pianists", "give \"pianists\" or the older \"pianist\", not both");
  }
  std::vector<const json*> objects;
  std::vector<std::string> pointers;
  if (document.contains("pianist")) {
    objects.push_back(&document.at("pianist"));
    pointers.emplace_back("/pianist");
  } else if (document.contains("pianists")) {
    const json& pianists = document.at("pianists");
    if (!pianists.is_array()) return reader_.error("/pianists", "expected an array");
    if (pianists.empty()) return reader_.error("/pianists", "must list at least one pianist");
    for (std::size_t i = 0; i < pianists.size(); ++i) {
      objects.push_back(&pianists[i]);
      pointers.push_back("/pianists/" + std::to_string(i));
    }
  }
  for (std::size_t i = 0; i < objects.size(); ++i) {
    Pianist pianist;
    pianist.pointer = pointers[i];
    if (auto ok = parse_pianist(*objects[i], scene, pianist); !ok) return ok;
    // Unnamed players are called for their instrument: "pianist", "pianist 2", "organist", ...
    if (objects[i]->is_object() && !objects[i]->contains("name")) {
      const std::string base = pianist.name;
      const auto taken = [&](const std::string& name) {
        return std::any_of(scene.pianists.begin(), scene.pianists.end(),
                           [&](const Pianist& other) { return other.name == name; });
      };
      for (int k = 2; taken(pianist.name); ++k) pianist.name = base + " " + std::to_string(k);
    }
    for (const Pianist& other : scene.pianists) {
      if (other.name == pianist.name) {
        return reader_.error(pianist.pointer + "/name", "duplicate pianist name \"" +
                                                            pianist.name + "\" (also " +
                                                            other.pointer + ")");
      }
      if (floor_distance_m(other.position_m, pianist.position_m) < kPianoSpacing_m) {
        return reader_.error(pianist.pointer + "/position_m",
                             "the piano stands on " + other.pointer + "'s (benches " +
                                 format_number(floor_distance_m(other.position_m, pianist.position_m)) +
                                 " m apart; two pianos need " + format_number(kPianoSpacing_m) +
                                 " m)");
      }
    }
    if (!pianist.seed_given) pianist.seed = derive_seed(scene.seed, pianist_seed_stream(i));
    scene.pianists.push_back(std::move(pianist));
  }
  return {};
}

Status SceneParser::parse_pianist_style(const json& object, Pianist& pianist) const {
  const std::string& path = pianist.pointer;
  auto sound = reader_.string_or(object, path, "sound", "score");
  if (!sound) return sound.error();
  if (*sound != "score" && *sound != "keys") {
    return reader_.error(path + "/sound",
                         "expected \"score\" or \"keys\", not \"" + *sound + "\"");
  }
  pianist.sound_from_keys = *sound == "keys";
  if (!object.contains("style")) return Status::success();
  auto style = reader_.string_or(object, path, "style", "");
  if (!style) return style.error();
  const fs::path styles_file = content_dir_ / "piano" / "styles.json";
  auto styles = read_scene_json(styles_file);
  if (!styles) return styles.error();
  std::vector<std::string> names;
  if (styles->contains("styles") && styles->at("styles").is_object()) {
    for (const auto& item : styles->at("styles").items()) names.push_back(item.key());
  }
  if (std::find(names.begin(), names.end(), *style) == names.end()) {
    return reader_.error(path + "/style", "unknown performance style \"" + *style +
                                               "\" (styles.json has: " + join(names) + ")");
  }
  pianist.style = *style;
  return Status::success();
}

Status SceneParser::parse_cameras(const json& document, Scene& scene) const {
  if (!document.contains("cameras")) return reader_.error("/cameras", "missing");
  const json& cameras = document.at("cameras");
  if (!cameras.is_array()) return reader_.error("/cameras", "expected an array");
  if (cameras.empty()) return reader_.error("/cameras", "a scene needs at least one camera");
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    const std::string path = "/cameras/" + std::to_string(i);
    const json& object = cameras[i];
    if (auto ok =
            reader_.json().check_keys(object, path, {"name", "position_m", "target_m", "fov_deg"});
        !ok) {
      return ok;
    }
    Camera camera;
    auto name = reader_.string(object, path, "name");
    if (!name) return name.error();
    if (const int other = scene.find_camera(*name); other >= 0) {
      return reader_.error(path + "/name", "duplicate camera name \"" + *name +
                                               "\" (also /cameras/" + std::to_string(other) + ")");
    }
    camera.name = *name;
    auto position = reader_.vec3(object, path, "position_m", 1000.0);
    if (!position) return position.error();
    camera.position_m = *position;
    auto target = reader_.vec3(object, path, "target_m", 1000.0);
    if (!target) return target.error();
    camera.target_m = *target;
    if (camera.target_m == camera.position_m) {
      return reader_.error(path + "/target_m", "must differ from position_m");
    }
    auto fov = reader_.number_or(object, path, "fov_deg", 5.0, 120.0, camera.fov_deg);
    if (!fov) return fov.error();
    camera.fov_deg = *fov;
    scene.cameras.push_back(std::move(camera));
  }
  return {};
}

Status SceneParser::parse_shots(const json& document, Scene& scene) const {
  if (!document.contains("shots")) {
    scene.shots.push_back({0, 0.0});  // no shot list: the first camera throughout
    return {};
  }
  const json& shots = document.at("shots");
  if (!shots.is_array()) return reader_.error("/shots", "expected an array");
  if (shots.empty()) return reader_.error("/shots", "must list at least one shot (or be left out)");
  std::vector<std::string> camera_names;
  for (const Camera& camera : scene.cameras) camera_names.push_back(camera.name);
  for (std::size_t i = 0; i < shots.size(); ++i) {
    const std::string path = "/shots/" + std::to_string(i);
    const json& object = shots[i];
    if (auto ok = reader_.json().check_keys(object, path, {"camera", "start_s"}); !ok) return ok;
    auto name = reader_.string(object, path, "camera");
    if (!name) return name.error();
    const int camera = scene.find_camera(*name);
    if (camera < 0) {
      return reader_.error(path + "/camera", "no camera named \"" + *name +
                                                 "\" (cameras: " + join(camera_names) + ")");
    }
    auto start = reader_.number(object, path, "start_s", 0.0, 86400.0);
    if (!start) return start.error();
    if (i == 0 && *start != 0.0) {
      return reader_.error(path + "/start_s", "the first shot must start at 0");
    }
    if (i > 0 && *start <= scene.shots.back().start_s) {
      return reader_.error(path + "/start_s", "must be later than the previous shot's start (" +
                                                  format_number(scene.shots.back().start_s) +
                                                  " s)");
    }
    scene.shots.push_back({static_cast<std::size_t>(camera), *start});
  }
  return {};
}

Status SceneParser::parse_light(const json& object, const std::string& path,
                                DirectionalLight& light) const {
  if (auto ok = reader_.json().check_keys(object, path, {"direction", "color", "intensity"}); !ok) {
    return ok;
  }
  auto direction = reader_.vec3_or(object, path, "direction", 1e6, light.direction);
  if (!direction) return direction.error();
  const double length = std::sqrt(direction->x * direction->x + direction->y * direction->y +
                                  direction->z * direction->z);
  if (!(length > 1e-9)) return reader_.error(path + "/direction", "must not be zero");
  light.direction = {direction->x / length, direction->y / length, direction->z / length};
  auto color = reader_.color_or(object, path, "color", light.color);
  if (!color) return color.error();
  light.color = *color;
  auto intensity = reader_.number_or(object, path, "intensity", 0.0, 100.0, light.intensity);
  if (!intensity) return intensity.error();
  light.intensity = *intensity;
  return {};
}

Status SceneParser::parse_lights(const json& document, Lights& lights) const {
  if (!document.contains("lights")) return {};
  const json& object = document.at("lights");
  if (auto ok = reader_.json().check_keys(object, "/lights", {"key", "fill", "ambient"}); !ok) {
    return ok;
  }
  if (object.contains("key")) {
    if (auto ok = parse_light(object.at("key"), "/lights/key", lights.key); !ok) return ok;
  }
  if (object.contains("fill")) {
    if (auto ok = parse_light(object.at("fill"), "/lights/fill", lights.fill); !ok) return ok;
  }
  if (object.contains("ambient")) {
    const json& ambient = object.at("ambient");
    if (auto ok = reader_.json().check_keys(ambient, "/lights/ambient", {"sky", "ground"}); !ok) {
      return ok;
    }
    auto sky = reader_.color_or(ambient, "/lights/ambient", "sky", lights.ambient_sky);
    if (!sky) return sky.error();
    lights.ambient_sky = *sky;
    auto ground = reader_.color_or(ambient, "/lights/ambient", "ground", lights.ambient_ground);
    if (!ground) return ground.error();
    lights.ambient_ground = *ground;
  }
  return {};
}

Status SceneParser::parse_output(const json& document, Output& output) const {
  if (!document.contains("output")) return {};
  const json& object = document.at("output");
  const std::string path = "/output";
  if (auto ok = reader_.json().check_keys(
          object, path,
          {"width", "height", "fps", "msaa", "shadows", "background", "start_s", "end_s"});
      !ok) {
    return ok;
  }
  auto width = reader_.integer_or(object, path, "width", 16, 7680, output.width);
  if (!width) return width.error();
  if (*width % 2 != 0) return reader_.error("/output/width", "must be even (for video encoders)");
  output.width = static_cast<int>(*width);
  auto height = reader_.integer_or(object, path, "height", 16, 4320, output.height);
  if (!height) return height.error();
  if (*height % 2 != 0) return reader_.error("/output/height", "must be even (for video encoders)");
  output.height = static_cast<int>(*height);
  auto fps = reader_.integer_or(object, path, "fps", 1, 240, output.fps);
  if (!fps) return fps.error();
  output.fps = static_cast<int>(*fps);
  auto msaa = reader_.integer_or(object, path, "msaa", 1, 8, output.msaa);
  if (!msaa) return msaa.error();
  if (*msaa != 1 && *msaa != 2 && *msaa != 4 && *msaa != 8) {
    return reader_.error("/output/msaa", "must be 1, 2, 4 or 8");
  }
  output.msaa = static_cast<int>(*msaa);
  auto shadows = reader_.string_or(object, path, "shadows", output.soft_shadows ? "soft" : "hard");
  if (!shadows) return shadows.error();
  if (*shadows != "hard" && *shadows != "soft") {
    return reader_.error("/output/shadows", "must be \"hard\" or \"soft\"");
  }
  output.soft_shadows = *shadows == "soft";
  auto background = reader_.color_or(object, path, "background", output.background);
  if (!background) return background.error();
  output.background = *background;
  // Negative: a pre-roll before the music (the lead's cue, the first breath).
  auto start = reader_.number_or(object, path, "start_s", -60.0, 86400.0, output.start_s);
  if (!start) return start.error();
  output.start_s = *start;
  if (object.contains("end_s") && !object.at("end_s").is_null()) {
    auto end = reader_.number(object, path, "end_s", -60.0, 86400.0);
    if (!end) return end.error();
    if (*end <= output.start_s) {
      return reader_.error("/output/end_s",
                           "must be later than start_s (" + format_number(output.start_s) + " s)");
    }
    output.end_s = *end;
  }
  return {};
}

Result<Scene> SceneParser::parse(const json& document) {
  if (auto ok = reader_.json().check_keys(document, "",
                                          {"description", "music", "seed", "performers", "pianist",
                                           "pianists", "cameras", "shots", "lights", "output", "cues"});
      !ok) {
    return ok.error();
  }
  Scene scene;
  scene.source = reader_.json().file();
  if (document.contains("description")) {
    auto description = reader_.string(document, "", "description", /*allow_empty=*/true);
    if (!description) return description.error();
    scene.description = *description;
  }
  if (auto ok = parse_music(document, scene); !ok) return ok.error();
  if (document.contains("seed")) {
    auto seed = reader_.seed(document, "", "seed");
    if (!seed) return seed.error();
    scene.seed = *seed;
  }

  if (document.contains("performers")) {
    const json& performers = document.at("performers");
    if (!performers.is_array()) return reader_.error("/performers", "expected an array");
    int lead = -1;
    for (std::size_t i = 0; i < performers.size(); ++i) {
      const std::string path = "/performers/" + std::to_string(i);
      Performer performer;
      if (auto ok = parse_performer(performers[i], path, scene, performer); !ok) {
        return ok.error();
      }
      for (std::size_t j = 0; j < scene.performers.size(); ++j) {
        if (scene.performers[j].name == performer.name) {
          return reader_.error(path + "/name", "duplicate performer name \"" + performer.name +
                                                   "\" (also /performers/" + std::to_string(j) +
                                                   ")");
        }
      }
      if (performer.lead) {
        if (lead >= 0) {
          return reader_.error(path + "/lead", "only one performer may lead (also /performers/" +
                                                   std::to_string(lead) + ")");
        }
        lead = static_cast<int>(i);
      }
      if (!performer.seed_given) performer.seed = derive_seed(scene.seed, i + 1);
      scene.performers.push_back(std::move(performer));
    }
  }
  if (auto ok = parse_pianists(document, scene); !ok) return ok.error();
  if (scene.performers.empty() && scene.pianists.empty()) {
    return reader_.error("", "a scene needs performers, a pianist, or both");
  }
  if (auto ok = parse_cameras(document, scene); !ok) return ok.error();
  if (auto ok = parse_shots(document, scene); !ok) return ok.error();
  if (auto ok = parse_lights(document, scene.lights); !ok) return ok.error();
  if (auto ok = parse_output(document, scene.output); !ok) return ok.error();
  if (auto ok = parse_cues(reader_, document, scene.cues_s); !ok) return ok.error();
  return scene;
}

}  // namespace

Result<nlohmann::json> read_scene_json(const std::filesystem::path& path) {
  auto bytes = read_file_bytes(path);
  if (!bytes) return bytes.error();
  const std::string name = path.filename().string();
  const bool blank = std::all_of(bytes->begin(), bytes->end(), [](std::uint8_t c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
  });
  if (blank) return Error{name + ": empty file"};
  try {
    return nlohmann::json::parse(bytes->begin(), bytes->end());
  } catch (const nlohmann::json::parse_error& e) {
    // e.what() = "[json.exception.parse_error.101] parse error at line 3, column 5: ...".
    std::string reason = e.what();
    const std::size_t at = reason.find("parse error ");
    if (at != std::string::npos) reason = reason.substr(at + 12);
    return Error{name + ": not valid JSON (" + reason + ")"};
  }
}

Result<Scene> load_scene(const std::filesystem::path& path, const LoadOptions& options) {
  auto document = read_scene_json(path);
  if (!document) return document.error();
  return parse_scene(*document, path.filename().string(), path.parent_path(), options);
}

Result<Scene> parse_scene(const nlohmann::json& document, const std::string& file_name,
                          const std::filesystem::path& base_dir, const LoadOptions& options) {
  SceneParser parser(file_name, base_dir, options.content_dir);
  return parser.parse(document);
}

int find_part(const music::Score& score, std::string_view wanted) {
  const std::string key = lower(wanted);
  for (std::size_t i = 0; i < score.parts.size(); ++i) {
    if (lower(score.parts[i].name) == key) return static_cast<int>(i);
  }
  for (std::size_t i = 0; i < score.parts.size(); ++i) {
    if (score.parts[i].id == wanted) return static_cast<int>(i);
  }
  return -1;
}

Status check_scene_parts(const Scene& scene, std::span<const music::Score> scores) {
  const content::JsonReader reader(scene.source);
  if (scores.size() != scene.music.size()) {
    return reader.error("/music", "expected " + std::to_string(scene.music.size()) +
                                      " loaded scores, got " + std::to_string(scores.size()));
  }
  auto check = [&](const std::string& part, std::size_t file, const std::string& where) -> Status {
    const music::Score& score = scores[file];
    if (find_part(score, part) >= 0) return {};
    std::vector<std::string> names;
    for (const music::Part& p : score.parts) names.push_back(p.name.empty() ? p.id : p.name);
    return reader.error(where, "no part \"" + part + "\" in " +
                                   scene.music[file].filename().string() +
                                   " (parts: " + join(names) + ")");
  };
  for (std::size_t i = 0; i < scene.performers.size(); ++i) {
    const Performer& performer = scene.performers[i];
    if (auto ok = check(performer.part, performer.music_file,
                        "/performers/" + std::to_string(i) + "/part");
        !ok) {
      return ok;
    }
  }
  // A note has one player: two pianists never share a part.
  std::map<std::pair<std::size_t, int>, std::string> played_by;
  for (const Pianist& pianist : scene.pianists) {
    for (std::size_t i = 0; i < pianist.parts.size(); ++i) {
      const std::string where = pianist.pointer + "/parts/" + std::to_string(i);
      if (auto ok = check(pianist.parts[i], pianist.music_file, where); !ok) return ok;
      const int part = find_part(scores[pianist.music_file], pianist.parts[i]);
      const auto [it, added] = played_by.emplace(std::pair{pianist.music_file, part}, where);
      if (!added && it->second.rfind(pianist.pointer + "/", 0) != 0) {
        return reader.error(where, "part \"" + pianist.parts[i] + "\" is already played by " +
                                       it->second);
      }
    }
  }
  return {};
}

Result<std::vector<music::Score>> load_scene_music(const Scene& scene) {
  std::vector<music::Score> scores;
  for (const std::filesystem::path& file : scene.music) {
    auto score = music::load_score(file);
    if (!score) return score.error();
    scores.push_back(std::move(*score));
  }
  if (auto ok = check_scene_parts(scene, scores); !ok) return ok.error();
  return scores;
}

}  // namespace tutti::scene
