// SPDX-License-Identifier: MIT
#pragma once
// A family's section of a scene file (Bevy's plugins own their settings the same way): the
// top-level keys an instrument family reads (each family's README names its own). The loader (load_scene.hpp) knows only the scene's own keys (music,
// cameras, shots, lights, output, cues, ...); it hands the document to each SceneSection in
// LoadOptions::sections, and a key no section registers is an error with a did-you-mean over
// all of them. A family stores what it read in Scene::sections (its own struct) and says which
// score parts its players play (Scene::part_claims), so that the parts are checked against the
// music before anything is planned.
//
// SectionContext gives a section the readers every family shares: typed fields with one-line
// "FILE: /json/path: reason" errors, the music file index, the expression controls, asset
// mapping files, the content folder.

#include <cstddef>
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/scene/asset_mapping.hpp>
#include <tutti/scene/json_fields.hpp>
#include <tutti/scene/scene.hpp>

namespace tutti::scene {

// Whether `path` names an existing regular file (an error reading it counts as no).
bool is_existing_file(const std::filesystem::path& path);

class SectionContext {
 public:
  SectionContext(const FieldReader& fields, std::filesystem::path base_dir,
                 std::filesystem::path content_dir, std::span<const AssetKind> instrument_kinds)
      : fields_(fields),
        base_dir_(std::move(base_dir)),
        content_dir_(std::move(content_dir)),
        instrument_kinds_(instrument_kinds) {}

  const FieldReader& fields() const { return fields_; }
  Error error(std::string_view path, std::string_view reason) const {
    return fields_.error(path, reason);
  }
  // Where relative paths in the scene resolve, and the content the scene is checked against.
  const std::filesystem::path& base_dir() const { return base_dir_; }
  const std::filesystem::path& content_dir() const { return content_dir_; }

  // object's "music_file": an index into scene.music (default 0).
  Result<std::size_t> music_index(const nlohmann::json& object, std::string_view path,
                                  const Scene& scene) const;
  // A performer's "variation" object: the keys of kVariationFields, each in [0, 1].
  Status variation(const nlohmann::json& object, std::string_view path, Variation& out) const;
  // object[key]: an existing file, resolved against base_dir(): an asset mapping file of kind
  // `expected` (a body kind, or one a section registers), or the model file itself where the
  // kind is recognised by itself (characters, hands). Absent: out unchanged.
  Status mapping(const nlohmann::json& object, std::string_view path, const char* key,
                 const AssetKind& expected, std::filesystem::path& out) const;
  // A JSON file of the content folder (e.g. "<family>/settings.json"), with one-line errors.
  Result<nlohmann::json> content_json(const std::filesystem::path& relative) const;

 private:
  const FieldReader& fields_;
  std::filesystem::path base_dir_;
  std::filesystem::path content_dir_;
  std::span<const AssetKind> instrument_kinds_;  // every section's
};

class SceneSection {
 public:
  virtual ~SceneSection() = default;

  // The family it belongs to (its FamilyPlugin's name), for messages.
  virtual std::string_view family() const = 0;
  // The top-level keys it reads; unique across the sections a program registers.
  virtual std::vector<std::string_view> keys() const = 0;
  // The kinds of asset mapping files its instruments take (a user's instrument model), each with
  // its roles; none by default. Names unique across the sections a program registers.
  virtual std::span<const AssetKind> asset_kinds() const { return {}; }
  // Reads its keys from `document` (called whether or not they are present; the scene's own
  // keys, music and seed, are already in `scene`), adds its players to `scene` and their parts
  // to scene.part_claims. Errors name the file and the JSON path.
  virtual Status read(const nlohmann::json& document, const SectionContext& context,
                      Scene& scene) const = 0;
};

}  // namespace tutti::scene
