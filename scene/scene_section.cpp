// SPDX-License-Identifier: MIT
#include <tutti/scene/scene_section.hpp>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>
#include <system_error>

#include <tutti/core/did_you_mean.hpp>
#include <tutti/scene/load_scene.hpp>

namespace tutti::scene {
namespace {

namespace fs = std::filesystem;

}  // namespace

bool is_existing_file(const std::filesystem::path& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

Result<std::size_t> SectionContext::music_index(const nlohmann::json& object,
                                                std::string_view path, const Scene& scene) const {
  auto index = fields_.integer_or(object, path, "music_file", 0,
                                  static_cast<std::int64_t>(scene.music.size()) - 1, 0);
  if (!index) return index.error();
  return static_cast<std::size_t>(*index);
}

Status SectionContext::variation(const nlohmann::json& object, std::string_view path,
                                 Variation& out) const {
  if (!object.is_object()) return error(path, "expected an object");
  for (const auto& item : object.items()) {
    const auto field = std::find_if(kVariationFields.begin(), kVariationFields.end(),
                                    [&](const VariationField& f) { return f.key == item.key(); });
    if (field == kVariationFields.end()) {
      std::vector<std::string_view> names;
      std::string known;
      for (const VariationField& f : kVariationFields) {
        names.push_back(f.key);
        known += (known.empty() ? "" : ", ") + std::string(f.key);
      }
      return error(join_path(path, item.key()),
                   "unknown key" + did_you_mean(item.key(), names) + " (known: " + known + ")");
    }
    auto value = fields_.number(object, path, item.key().c_str(), 0.0, 1.0);
    if (!value) return value.error();
    out.*(field->value) = *value;
  }
  return {};
}

Status SectionContext::mapping(const nlohmann::json& object, std::string_view path,
                               const char* key, const AssetKind& expected,
                               fs::path& out) const {
  if (!object.contains(key)) return {};
  auto written = fields_.string(object, path, key);
  if (!written) return written.error();
  const std::string where = join_path(path, key);
  const fs::path resolved = (base_dir_ / *written).lexically_normal();
  if (!is_existing_file(resolved)) return error(where, "no such file \"" + *written + "\"");
  // A character or a player's hands may be the model file itself: the stage recognises the
  // humanoid or the hands in it (engine/humanoid); instruments still need a mapping file.
  const std::string extension = resolved.extension().string();
  if (extension == ".glb" || extension == ".gltf" || extension == ".vrm") {
    if (!expected.recognised_by_itself) {
      return error(where, "\"" + *written + "\" is a model; a " + std::string(expected.name) +
                              " needs a mapping file (only characters and hands are recognised "
                              "by themselves)");
    }
    out = resolved;
    return {};
  }
  auto mapping = load_asset_mapping(resolved, instrument_kinds_);
  if (!mapping) return mapping.error();
  if (mapping->kind != expected.name) {
    return error(where, "\"" + *written + "\" maps a " + mapping->kind + ", expected a " +
                            std::string(expected.name));
  }
  out = resolved;
  return {};
}

Result<nlohmann::json> SectionContext::content_json(const fs::path& relative) const {
  return read_scene_json(content_dir_ / relative);
}

}  // namespace tutti::scene
