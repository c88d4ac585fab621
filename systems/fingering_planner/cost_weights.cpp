// SPDX-License-Identifier: MIT
#include <tutti/fingering_planner/cost_weights.hpp>

#include <cmath>
#include <nlohmann/json.hpp>

#include <tutti/piano_model/json_document.hpp>

namespace tutti::fingering_planner {

// The piano model's names this planner uses (systems/piano_model).
using piano_model::JsonReader;
using piano_model::read_json_file;

namespace {

// Reads optional keys of one section into fields; absent keys keep their current value.
class SectionReader {
 public:
  SectionReader(const JsonReader& reader, const nlohmann::json& section, std::string path)
      : reader_(reader), section_(section), path_(std::move(path)) {}

  Status number(const char* key, double& field, bool allow_inf = false) {
    if (!section_.contains(key)) return Status::success();
    auto value = allow_inf ? reader_.number_or_inf(section_, path_, key)
                           : reader_.number(section_, path_, key);
    if (!value) return value.error();
    field = *value;
    return Status::success();
  }

  Status five(const char* key, std::array<double, 5>& field) {
    if (!section_.contains(key)) return Status::success();
    const nlohmann::json& array = section_.at(key);
    const std::string where = path_ + "/" + key;
    if (!array.is_array() || array.size() != 5) {
      return reader_.error(where, "expected 5 numbers (thumb .. little finger)");
    }
    for (std::size_t i = 0; i < 5; ++i) {
      if (!array[i].is_number() || !std::isfinite(array[i].get<double>())) {
        return reader_.error(where + "/" + std::to_string(i), "expected a finite number");
      }
      field[i] = array[i].get<double>();
    }
    return Status::success();
  }

 private:
  const JsonReader& reader_;
  const nlohmann::json& section_;
  std::string path_;
};

#define TUTTI_TRY(expr)          \
  do {                           \
    if (auto s_ = (expr); !s_) { \
      return s_.error();         \
    }                            \
  } while (false)

}  // namespace

Result<CostWeights> load_cost_weights(const std::filesystem::path& path) {
  auto document = read_json_file(path);
  if (!document) return document.error();
  return cost_weights_from_json(*document, path.filename().string());
}

Result<CostWeights> cost_weights_from_json(const nlohmann::json& document,
                                           const std::string& file_name) {
  const JsonReader reader(file_name);
  TUTTI_TRY(reader.check_keys(document, "",
                              {"name", "description", "hand_area", "fingers", "same_finger",
                               "spacing", "crossing", "other_hand", "events"}));
  CostWeights w;
  if (document.contains("name")) {
    if (!document.at("name").is_string()) return reader.error("/name", "expected a string");
    w.name = document.at("name").get<std::string>();
  }
  static const nlohmann::json kEmpty = nlohmann::json::object();
  auto section = [&](const char* key) -> const nlohmann::json& {
    return document.contains(key) ? document.at(key) : kEmpty;
  };

  const nlohmann::json& area = section("hand_area");
  TUTTI_TRY(reader.check_keys(
      area, "/hand_area",
      {"overlap", "gap_base", "gap_speed_per_white_key_per_s", "release_fraction", "shift_time_s",
       "shift_hold_fraction", "speed_limit_white_keys_per_s", "over_speed_per_white_key_per_s"}));
  SectionReader a(reader, area, "/hand_area");
  TUTTI_TRY(a.number("overlap", w.area_overlap));
  TUTTI_TRY(a.number("gap_base", w.gap_base));
  TUTTI_TRY(a.number("gap_speed_per_white_key_per_s", w.gap_speed));
  TUTTI_TRY(a.number("release_fraction", w.release_fraction));
  TUTTI_TRY(a.number("shift_time_s", w.shift_time_s));
  TUTTI_TRY(a.number("shift_hold_fraction", w.shift_hold_fraction));
  TUTTI_TRY(a.number("speed_limit_white_keys_per_s", w.speed_limit, /*allow_inf=*/true));
  TUTTI_TRY(a.number("over_speed_per_white_key_per_s", w.over_speed));
  if (w.release_fraction < 0 || w.release_fraction > 1) {
    return reader.error("/hand_area/release_fraction", "must be within 0..1");
  }
  if (w.shift_time_s < 0) return reader.error("/hand_area/shift_time_s", "must be >= 0");
  if (w.shift_hold_fraction < 0 || w.shift_hold_fraction > 1) {
    return reader.error("/hand_area/shift_hold_fraction", "must be within 0..1");
  }
  if (!(w.speed_limit > 0)) {
    return reader.error("/hand_area/speed_limit_white_keys_per_s", "must be positive");
  }
  if (w.over_speed < 0) {
    return reader.error("/hand_area/over_speed_per_white_key_per_s", "must be >= 0");
  }

  const nlohmann::json& fingers = section("fingers");
  TUTTI_TRY(reader.check_keys(fingers, "/fingers",
                              {"use", "black_key", "thumb_on_tonic", "thumb_on_fourth"}));
  SectionReader f(reader, fingers, "/fingers");
  TUTTI_TRY(f.five("use", w.finger_use));
  TUTTI_TRY(f.five("black_key", w.black_key));
  TUTTI_TRY(f.number("thumb_on_tonic", w.thumb_on_tonic));
  TUTTI_TRY(f.number("thumb_on_fourth", w.thumb_on_fourth));

  const nlohmann::json& same = section("same_finger");
  TUTTI_TRY(reader.check_keys(
      same, "/same_finger",
      {"other_key", "speed_per_white_key_per_s", "same_key", "repeat_finger_change"}));
  SectionReader s(reader, same, "/same_finger");
  TUTTI_TRY(s.number("other_key", w.same_finger_other_key, /*allow_inf=*/true));
  TUTTI_TRY(s.number("speed_per_white_key_per_s", w.same_finger_speed));
  TUTTI_TRY(s.number("same_key", w.same_finger_same_key));
  TUTTI_TRY(s.number("repeat_finger_change", w.repeat_finger_change));

  const nlohmann::json& spacing = section("spacing");
  TUTTI_TRY(reader.check_keys(
      spacing, "/spacing", {"per_finger", "stretch", "compress", "thumb_factor", "max_distance"}));
  SectionReader sp(reader, spacing, "/spacing");
  TUTTI_TRY(sp.number("per_finger", w.spacing_per_finger));
  TUTTI_TRY(sp.number("stretch", w.spacing_stretch));
  TUTTI_TRY(sp.number("compress", w.spacing_compress));
  TUTTI_TRY(sp.number("thumb_factor", w.spacing_thumb_factor));
  TUTTI_TRY(sp.number("max_distance", w.spacing_max_distance));

  const nlohmann::json& crossing = section("crossing");
  TUTTI_TRY(reader.check_keys(
      crossing, "/crossing",
      {"thumb", "thumb_by_finger", "thumb_distance", "thumb_on_black", "thumb_little", "other"}));
  SectionReader c(reader, crossing, "/crossing");
  TUTTI_TRY(c.number("thumb", w.cross_thumb));
  TUTTI_TRY(c.five("thumb_by_finger", w.cross_thumb_finger));
  TUTTI_TRY(c.number("thumb_distance", w.cross_thumb_distance));
  TUTTI_TRY(c.number("thumb_on_black", w.cross_thumb_black));
  TUTTI_TRY(c.number("thumb_little", w.cross_little));
  TUTTI_TRY(c.number("other", w.cross_other));

  const nlohmann::json& other = section("other_hand");
  TUTTI_TRY(reader.check_keys(other, "/other_hand",
                              {"separation_white_keys", "per_white_key", "lead_s"}));
  SectionReader o(reader, other, "/other_hand");
  TUTTI_TRY(o.number("separation_white_keys", w.other_hand_separation));
  TUTTI_TRY(o.number("per_white_key", w.other_hand_per_white_key));
  TUTTI_TRY(o.number("lead_s", w.other_hand_lead_s));
  if (w.other_hand_separation < 0) {
    return reader.error("/other_hand/separation_white_keys", "must be >= 0");
  }
  if (w.other_hand_per_white_key < 0) return reader.error("/other_hand/per_white_key", "must be >= 0");
  if (w.other_hand_lead_s < 0) return reader.error("/other_hand/lead_s", "must be >= 0");

  const nlohmann::json& events = section("events");
  TUTTI_TRY(reader.check_keys(events, "/events",
                              {"chord_tolerance_s", "unreachable_per_white_key", "impossible"}));
  SectionReader e(reader, events, "/events");
  TUTTI_TRY(e.number("chord_tolerance_s", w.chord_tolerance_s));
  TUTTI_TRY(e.number("unreachable_per_white_key", w.unreachable));
  TUTTI_TRY(e.number("impossible", w.impossible));
  if (w.chord_tolerance_s < 0) return reader.error("/events/chord_tolerance_s", "must be >= 0");
  if (w.impossible <= 0) return reader.error("/events/impossible", "must be positive");
  return w;
}

}  // namespace tutti::fingering_planner
