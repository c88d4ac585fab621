// SPDX-License-Identifier: MIT
#include <tutti/scene/load_scene.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <string_view>
#include <system_error>

#include <tutti/content/content_dir.hpp>
#include <tutti/core/did_you_mean.hpp>
#include <tutti/core/file_io.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/scene/json_fields.hpp>
#include <tutti/scene/performance_marks.hpp>

namespace tutti::scene {
namespace {

namespace fs = std::filesystem;

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

class SceneParser {
 public:
  SceneParser(const std::string& file_name, fs::path base_dir, fs::path content_dir,
              std::vector<const SceneSection*> sections)
      : reader_(file_name),
        base_dir_(std::move(base_dir)),
        content_dir_(content_dir.empty() ? content::default_content_dir() : std::move(content_dir)),
        sections_(std::move(sections)) {}

  Result<Scene> parse(const json& document);

 private:
  Status check_top_level_keys(const json& document) const;
  Status parse_music(const json& document, Scene& scene) const;
  Status parse_cameras(const json& document, Scene& scene) const;
  Status parse_shots(const json& document, Scene& scene) const;
  Status parse_light(const json& object, const std::string& path, DirectionalLight& light) const;
  Status parse_lights(const json& document, Lights& lights) const;
  Status parse_output(const json& document, Output& output) const;

  FieldReader reader_;
  fs::path base_dir_;
  fs::path content_dir_;
  std::vector<const SceneSection*> sections_;
};

// The scene's own keys; each family's section adds its own.
constexpr std::array<std::string_view, 8> kSceneKeys{
    "description", "music", "seed", "cameras", "shots", "lights", "output", "cues"};

Status SceneParser::check_top_level_keys(const json& document) const {
  if (!document.is_object()) return reader_.error("", "expected an object");
  std::vector<std::string_view> known(kSceneKeys.begin(), kSceneKeys.end());
  for (const SceneSection* section : sections_) {
    for (std::string_view key : section->keys()) known.push_back(key);
  }
  for (const auto& item : document.items()) {
    if (std::find(known.begin(), known.end(), item.key()) != known.end()) continue;
    return reader_.error("/" + item.key(), "unknown key" + did_you_mean(item.key(), known));
  }
  return {};
}

Status SceneParser::parse_music(const json& document, Scene& scene) const {
  if (!document.contains("music")) return reader_.error("/music", "missing");
  const json& music = document.at("music");
  auto add = [&](const json& entry, const std::string& where) -> Status {
    if (!entry.is_string()) return reader_.error(where, "expected a string (a file path)");
    const std::string written = entry.get<std::string>();
    if (written.empty()) return reader_.error(where, "must not be empty");
    const fs::path resolved = (base_dir_ / written).lexically_normal();
    if (!is_existing_file(resolved)) {
      return reader_.error(where, "no such file \"" + written + "\"");
    }
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
  if (auto ok = check_top_level_keys(document); !ok) return ok.error();
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
  std::vector<AssetKind> instrument_kinds;
  for (const SceneSection* section : sections_) {
    for (const AssetKind& kind : section->asset_kinds()) instrument_kinds.push_back(kind);
  }
  const SectionContext context(reader_, base_dir_, content_dir_, instrument_kinds);
  for (const SceneSection* section : sections_) {
    if (auto ok = section->read(document, context, scene); !ok) return ok.error();
  }
  if (scene.part_claims.empty()) {
    std::string keys;
    for (const SceneSection* section : sections_) {
      for (std::string_view key : section->keys()) {
        keys += (keys.empty() ? "" : ", ") + std::string(key);
      }
    }
    return reader_.error("", "a scene needs at least one player (" +
                                 (keys.empty() ? std::string("no family's section is registered")
                                               : keys) +
                                 ")");
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
  SceneParser parser(file_name, base_dir, options.content_dir, options.sections);
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
  // A note has one player: the first player claiming an exclusive part, by (music, part).
  std::map<std::pair<std::size_t, int>, const PartClaim*> exclusive_owner;
  for (const PartClaim& claim : scene.part_claims) {
    if (claim.music_file >= scores.size()) {
      return reader.error(claim.pointer, "music_file " + std::to_string(claim.music_file) +
                                             " is not one of the scene's music files");
    }
    const music::Score& score = scores[claim.music_file];
    const int part = find_part(score, claim.part);
    if (part < 0) {
      std::vector<std::string> names;
      for (const music::Part& p : score.parts) names.push_back(p.name.empty() ? p.id : p.name);
      return reader.error(claim.pointer, "no part \"" + claim.part + "\" in " +
                                             scene.music[claim.music_file].filename().string() +
                                             " (parts: " + join(names) + ")");
    }
    if (!claim.exclusive) continue;
    const auto [it, added] = exclusive_owner.emplace(std::pair{claim.music_file, part}, &claim);
    if (!added && it->second->player != claim.player) {
      return reader.error(claim.pointer, "part \"" + claim.part + "\" is already played by " +
                                             it->second->pointer);
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
