// SPDX-License-Identifier: MIT
#include <tutti/brass/brass_scene_section.hpp>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>
#include <system_error>
#include <vector>

#include <tutti/brass/brass_players.hpp>
#include <tutti/brass_model/instrument.hpp>
#include <tutti/scene/performance_marks.hpp>

namespace tutti::brass {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using scene::AssetKind;
using scene::join_path;
using scene::Scene;
using scene::SectionContext;

std::string join(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

// The ids of content/instruments/*.json, sorted.
std::vector<std::string> instrument_ids(const fs::path& content_dir) {
  std::vector<std::string> ids;
  std::error_code ec;
  for (fs::directory_iterator it(content_dir / "instruments", ec), end; !ec && it != end;
       it.increment(ec)) {
    if (it->path().extension() == ".json") ids.push_back(it->path().stem().string());
  }
  std::sort(ids.begin(), ids.end());
  return ids;
}

// "instrument_model": a mapping of kind "trumpet" (three valves) or "trombone" (a slide).
Status parse_instrument_mapping(const SectionContext& context, const json& object,
                                const std::string& path, const std::string& instrument,
                                fs::path& out) {
  if (!object.contains("instrument_model")) return {};
  auto loaded =
      brass_model::load_instrument(context.content_dir() / "instruments" / (instrument + ".json"));
  if (!loaded) return loaded.error();
  const AssetKind* kind = &trombone_kind();
  if (loaded->mechanism == brass_model::Mechanism::valves) {
    if (loaded->valves.size() != 3) {
      return context.error(
          join_path(path, "instrument_model"),
          "user models exist for trumpets and trombones only, not " + loaded->display_name);
    }
    kind = &trumpet_kind();
  }
  return context.mapping(object, path, "instrument_model", *kind, out);
}

Status parse_performer(const SectionContext& context, const std::vector<std::string>& ids,
                       const json& object, const std::string& path, const Scene& scene,
                       BrassPlayer& performer) {
  const scene::FieldReader& reader = context.fields();
  if (auto ok = reader.json().check_keys(
          object, path,
          {"name", "instrument", "part", "voice", "music_file", "position_m", "facing_deg",
           "stance", "music_stand", "lead", "seed", "variation", "character", "instrument_model",
           "breaths", "expressions"});
      !ok) {
    return ok;
  }
  auto name = reader.string(object, path, "name");
  if (!name) return name.error();
  performer.name = *name;

  auto instrument = reader.string(object, path, "instrument");
  if (!instrument) return instrument.error();
  if (std::find(ids.begin(), ids.end(), *instrument) == ids.end()) {
    return context.error(join_path(path, "instrument"),
                         "unknown instrument \"" + *instrument + "\" (known: " + join(ids) + ")");
  }
  performer.instrument = *instrument;

  auto part = reader.string(object, path, "part");
  if (!part) return part.error();
  performer.part = *part;
  auto voice = reader.integer_or(object, path, "voice", 1, 16, 1);
  if (!voice) return voice.error();
  performer.voice = static_cast<int>(*voice);
  auto music_file = context.music_index(object, path, scene);
  if (!music_file) return music_file.error();
  performer.music_file = *music_file;

  auto position = reader.vec3(object, path, "position_m", 100.0);
  if (!position) return position.error();
  performer.position_m = *position;
  auto facing = reader.number_or(object, path, "facing_deg", -360.0, 360.0, 0.0);
  if (!facing) return facing.error();
  performer.facing_deg = *facing;
  auto stance = reader.string_or(object, path, "stance", "standing");
  if (!stance) return stance.error();
  if (*stance == "standing") {
    performer.stance = scene::Stance::standing;
  } else if (*stance == "seated") {
    performer.stance = scene::Stance::seated;
  } else {
    return context.error(join_path(path, "stance"), "must be \"standing\" or \"seated\"");
  }
  auto stand = reader.boolean_or(object, path, "music_stand", true);
  if (!stand) return stand.error();
  performer.music_stand = *stand;
  auto lead = reader.boolean_or(object, path, "lead", false);
  if (!lead) return lead.error();
  performer.lead = *lead;
  if (object.contains("seed")) {
    auto seed = reader.seed(object, path, "seed");
    if (!seed) return seed.error();
    performer.seed = *seed;
    performer.seed_given = true;
  }
  if (object.contains("variation")) {
    if (auto ok = context.variation(object.at("variation"), path + "/variation",
                                    performer.variation);
        !ok) {
      return ok;
    }
  }
  if (auto ok = context.mapping(object, path, "character", scene::character_kind(),
                                performer.character_mapping);
      !ok) {
    return ok;
  }
  if (auto ok = scene::parse_performer_marks(reader, object, path, performer.breaths,
                                             performer.expressions);
      !ok)
    return ok;
  return parse_instrument_mapping(context, object, path, performer.instrument,
                                  performer.instrument_mapping);
}

}  // namespace

Status BrassSceneSection::read(const json& document, const SectionContext& context,
                               Scene& scene) const {
  if (!document.contains("performers")) return {};
  const json& performers = document.at("performers");
  if (!performers.is_array()) return context.error("/performers", "expected an array");
  const std::vector<std::string> ids = instrument_ids(context.content_dir());
  std::vector<BrassPlayer>& players = edit_brass_players(scene);
  int lead = -1;
  for (std::size_t i = 0; i < performers.size(); ++i) {
    const std::string path = "/performers/" + std::to_string(i);
    BrassPlayer performer;
    if (auto ok = parse_performer(context, ids, performers[i], path, scene, performer); !ok) {
      return ok;
    }
    for (std::size_t j = 0; j < players.size(); ++j) {
      if (players[j].name == performer.name) {
        return context.error(path + "/name", "duplicate performer name \"" + performer.name +
                                                 "\" (also /performers/" + std::to_string(j) +
                                                 ")");
      }
    }
    if (performer.lead) {
      if (lead >= 0) {
        return context.error(path + "/lead", "only one performer may lead (also /performers/" +
                                                  std::to_string(lead) + ")");
      }
      lead = static_cast<int>(i);
    }
    if (!performer.seed_given) performer.seed = scene::derive_seed(scene.seed, i + 1);
    // Players share a part by voice, so brass claims are not exclusive.
    scene.part_claims.push_back(
        {performer.part, performer.music_file, path + "/part", path, /*exclusive=*/false});
    players.push_back(std::move(performer));
  }
  return {};
}

}  // namespace tutti::brass
