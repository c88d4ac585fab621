// SPDX-License-Identifier: MIT
#include <tutti/brass/hold.hpp>

#include <cmath>
#include <nlohmann/json.hpp>

#include <tutti/content/json_reader.hpp>

namespace tutti::brass {
namespace {

using nlohmann::json;
constexpr float kDegree = 3.14159265f / 180.0f;
constexpr const char* kFingers[5] = {"thumb", "index", "middle", "ring", "little"};

Result<std::array<float, 3>> curl(const content::JsonReader& r, const json& value,
                                  const std::string& path) {
  if (!value.is_array() || value.size() != 3) {
    return r.error(path, "expected [MCP, PIP, DIP] in degrees");
  }
  std::array<float, 3> out{};
  for (std::size_t i = 0; i < 3; ++i) {
    if (!value[i].is_number() || !std::isfinite(value[i].get<double>()) ||
        std::abs(value[i].get<double>()) > 120.0) {
      return r.error(path + "/" + std::to_string(i), "expected degrees in -120..120");
    }
    out[i] = value[i].get<float>() * kDegree;
  }
  return out;
}

// Where an elbow points: down, out to the player's side, back (each a weight of that direction).
Result<glm::vec3> read_elbow_pole(const content::JsonReader& r, const json& object,
                                  const std::string& path) {
  double down = 1.0, out = 0.8, back = 0.3;
  const content::NumberField pole[] = {
      {"down", &down, 0.0, 2.0}, {"out", &out, -1.0, 2.0}, {"back", &back, -1.0, 2.0}};
  if (auto ok = r.read_number_fields(object, path, pole, true); !ok) return ok.error();
  return glm::vec3(static_cast<float>(down), static_cast<float>(out), static_cast<float>(back));
}

Result<HandHold> read_hand(const content::JsonReader& r, const json& object,
                           const std::string& path) {
  if (auto ok = r.check_keys(object, path,
                             {"palm_at", "fingertips_on", "pad_above_button_mm",
                              "metacarpal_lean_deg", "finger_curl_deg", "little_curl_deg",
                              "thumb_curl_deg", "thumb_adduct_deg", "wraps_valves", "elbow"});
      !ok) {
    return ok.error();
  }
  HandHold hand;
  if (object.contains("palm_at")) {
    if (!object.at("palm_at").is_string() || object.at("palm_at").get<std::string>().empty()) {
      return r.error(path + "/palm_at", "expected an instrument node's name");
    }
    hand.palm_at = object.at("palm_at").get<std::string>();
  }
  if (object.contains("fingertips_on")) {
    const json& tips = object.at("fingertips_on");
    if (auto ok = r.check_keys(tips, path + "/fingertips_on",
                               {"thumb", "index", "middle", "ring", "little"});
        !ok) {
      return ok.error();
    }
    for (std::size_t f = 0; f < 5; ++f) {
      if (!tips.contains(kFingers[f])) continue;
      if (!tips.at(kFingers[f]).is_string()) {
        return r.error(path + "/fingertips_on/" + kFingers[f], "expected an instrument node's name");
      }
      hand.fingertip_on[f] = tips.at(kFingers[f]).get<std::string>();
    }
  }
  if (hand.palm_at.empty() == (hand.fingertip_on == std::array<std::string, 5>{})) {
    return r.error(path, "give either palm_at or fingertips_on");
  }
  auto pad = r.number_or(object, path, "pad_above_button_mm", 6.0);
  if (!pad) return pad.error();
  if (*pad < 0.0 || *pad > 30.0) return r.error(path + "/pad_above_button_mm", "must be in 0..30");
  hand.pad_above_button_m = static_cast<float>(*pad / 1000.0);
  auto lean = r.number_or(object, path, "metacarpal_lean_deg", 0.0);
  if (!lean) return lean.error();
  if (std::abs(*lean) > 90.0) return r.error(path + "/metacarpal_lean_deg", "must be in -90..90");
  hand.metacarpal_lean_rad = static_cast<float>(*lean) * kDegree;
  if (!object.contains("finger_curl_deg")) return r.error(path + "/finger_curl_deg", "missing");
  auto fingers = curl(r, object.at("finger_curl_deg"), path + "/finger_curl_deg");
  if (!fingers) return fingers.error();
  hand.finger_curl_rad = *fingers;
  hand.little_curl_rad = *fingers;
  if (object.contains("little_curl_deg")) {
    auto little = curl(r, object.at("little_curl_deg"), path + "/little_curl_deg");
    if (!little) return little.error();
    hand.little_curl_rad = *little;
    hand.little_own_curl = true;
  }
  if (object.contains("wraps_valves")) {
    if (!object.at("wraps_valves").is_boolean()) {
      return r.error(path + "/wraps_valves", "expected true or false");
    }
    hand.wraps_valves = object.at("wraps_valves").get<bool>();
  }
  auto thumb = r.number_or(object, path, "thumb_curl_deg", 0.0);
  if (!thumb) return thumb.error();
  if (std::abs(*thumb) > 90.0) return r.error(path + "/thumb_curl_deg", "must be in -90..90");
  hand.thumb_curl_rad = static_cast<float>(*thumb) * kDegree;
  auto adduct = r.number_or(object, path, "thumb_adduct_deg", 0.0);
  if (!adduct) return adduct.error();
  if (std::abs(*adduct) > 60.0) return r.error(path + "/thumb_adduct_deg", "must be in -60..60");
  hand.thumb_adduct_rad = static_cast<float>(*adduct) * kDegree;
  if (object.contains("elbow")) {
    auto pole = read_elbow_pole(r, object.at("elbow"), path + "/elbow");
    if (!pole) return pole.error();
    hand.elbow_pole = *pole;
  }
  return hand;
}

}  // namespace

Result<Hold> load_hold(const std::filesystem::path& file) {
  auto doc = content::read_json_file(file);
  if (!doc) return doc.error();
  const content::JsonReader r(file.filename().string());
  if (auto ok = r.check_keys(*doc, "",
                             {"description", "carriage", "elbows", "left_hand", "right_hand",
                              "rest", "music_stand"});
      !ok) {
    return ok.error();
  }
  Hold hold;
  for (const char* key : {"carriage", "elbows", "left_hand", "right_hand"}) {
    if (!doc->contains(key)) return r.error(std::string("/") + key, "missing");
  }
  const json& carriage = doc->at("carriage");
  if (auto ok = r.check_keys(carriage, "/carriage", {"standing", "seated", "reach_dip_deg"}); !ok) {
    return ok.error();
  }
  if (carriage.contains("reach_dip_deg")) {
    const json& dip = carriage.at("reach_dip_deg");
    if (!dip.is_number() || dip.get<double>() < 0.0 || dip.get<double>() > 30.0) {
      return r.error("/carriage/reach_dip_deg", "expected degrees in 0..30");
    }
    hold.reach_dip_rad = dip.get<float>() * kDegree;
  }
  for (const char* stance : {"standing", "seated"}) {
    const std::string path = std::string("/carriage/") + stance;
    if (!carriage.contains(stance)) return r.error(path, "missing");
    double tilt = 0.0;
    const content::NumberField fields[] = {{"bell_tilt_deg", &tilt, -60.0, 60.0}};
    if (auto ok = r.read_number_fields(carriage.at(stance), path, fields, true); !ok) {
      return ok.error();
    }
    (std::string(stance) == "standing" ? hold.bell_tilt_standing_rad : hold.bell_tilt_seated_rad) =
        static_cast<float>(tilt) * kDegree;
  }
  auto pole = read_elbow_pole(r, doc->at("elbows"), "/elbows");
  if (!pole) return pole.error();
  hold.elbow_pole = *pole;
  if (doc->contains("rest")) {
    double below = 0.0, forward = 0.0, tilt = 0.0;
    const content::NumberField rest[] = {{"below_lips_m", &below, 0.0, 1.0},
                                         {"forward_m", &forward, -0.3, 0.6},
                                         {"bell_tilt_deg", &tilt, -90.0, 90.0}};
    if (auto ok = r.read_number_fields(doc->at("rest"), "/rest", rest, true); !ok) {
      return ok.error();
    }
    hold.has_rest = true;
    hold.rest_below_lips_m = static_cast<float>(below);
    hold.rest_forward_m = static_cast<float>(forward);
    hold.rest_bell_tilt_rad = static_cast<float>(tilt) * kDegree;
  }
  if (doc->contains("music_stand")) {
    double forward = hold.stand_forward_m, left = hold.stand_left_m;
    const content::NumberField stand[] = {{"forward_m", &forward, 0.3, 2.0},
                                          {"left_m", &left, -1.0, 1.0}};
    if (auto ok = r.read_number_fields(doc->at("music_stand"), "/music_stand", stand, false); !ok) {
      return ok.error();
    }
    hold.stand_forward_m = static_cast<float>(forward);
    hold.stand_left_m = static_cast<float>(left);
  }
  for (std::size_t side = 0; side < 2; ++side) {
    const std::string key = side == 0 ? "left_hand" : "right_hand";
    auto hand = read_hand(r, doc->at(key), "/" + key);
    if (!hand) return hand.error();
    hold.hands[side] = std::move(*hand);
  }
  return hold;
}

}  // namespace tutti::brass
