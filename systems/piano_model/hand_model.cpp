// SPDX-License-Identifier: MIT
#include <tutti/piano_model/hand_model.hpp>

#include <nlohmann/json.hpp>

#include <tutti/piano_model/json_document.hpp>

namespace tutti::piano_model {

Result<HandModel> HandModel::load(const std::filesystem::path& path, std::string_view preset,
                                  double white_key_width_mm) {
  auto document = read_json_file(path);
  if (!document) return document.error();
  return from_json(*document, path.filename().string(), preset, white_key_width_mm);
}

Result<HandModel> HandModel::from_json(const nlohmann::json& document, const std::string& file_name,
                                       std::string_view preset, double white_key_width_mm) {
  const JsonReader reader(file_name);
  if (auto ok = reader.check_keys(document, "",
                                  {"description", "source", "right_hand_finger_ranges_white_keys",
                                   "presets", "default_preset"});
      !ok) {
    return ok.error();
  }
  if (!(white_key_width_mm > 0)) return reader.error("", "white key width must be positive");

  HandModel model;
  std::string chosen(preset);
  if (chosen.empty()) {
    if (!document.contains("default_preset") || !document.at("default_preset").is_string()) {
      return reader.error("/default_preset", "expected a preset name");
    }
    chosen = document.at("default_preset").get<std::string>();
  }
  if (!document.contains("presets")) return reader.error("/presets", "missing");
  const nlohmann::json& presets = document.at("presets");
  if (!presets.is_object()) return reader.error("/presets", "expected an object");
  if (!presets.contains(chosen)) {
    std::string known;
    for (const auto& item : presets.items()) known += (known.empty() ? "" : ", ") + item.key();
    return reader.error("/presets", "no preset '" + chosen + "' (have: " + known + ")");
  }
  const std::string preset_path = "/presets/" + chosen;
  const nlohmann::json& entry = presets.at(chosen);
  if (auto ok = reader.check_keys(entry, preset_path, {"description", "scale"}); !ok) {
    return ok.error();
  }
  auto scale = reader.number(entry, preset_path, "scale");
  if (!scale) return scale.error();
  if (*scale <= 0) return reader.error(preset_path + "/scale", "must be positive");
  model.preset_ = chosen;
  model.scale_ = *scale;

  const char* ranges_key = "right_hand_finger_ranges_white_keys";
  const std::string ranges_path = std::string("/") + ranges_key;
  if (!document.contains(ranges_key)) return reader.error(ranges_path, "missing");
  const nlohmann::json& ranges = document.at(ranges_key);
  if (auto ok = reader.check_keys(ranges, ranges_path, {"1", "2", "3", "4", "5"}); !ok) {
    return ok.error();
  }
  const double unit = white_key_width_mm * *scale;
  for (int finger = 1; finger <= 5; ++finger) {
    const std::string name = std::to_string(finger);
    const std::string where = ranges_path + "/" + name;
    if (!ranges.contains(name)) return reader.error(where, "missing");
    const nlohmann::json& pair = ranges.at(name);
    if (!pair.is_array() || pair.size() != 2 || !pair[0].is_number() || !pair[1].is_number()) {
      return reader.error(where, "expected [lo, hi] in white keys");
    }
    const double lo = pair[0].get<double>();
    const double hi = pair[1].get<double>();
    if (!(lo <= hi)) return reader.error(where, "lo must not exceed hi");
    const auto index = static_cast<std::size_t>(finger - 1);
    model.right_[index] = {lo * unit, hi * unit};
    model.left_[index] = {-hi * unit, -lo * unit};
  }
  return model;
}

}  // namespace tutti::piano_model
