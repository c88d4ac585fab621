// SPDX-License-Identifier: MIT
#include <tutti/key_action/performance_style.hpp>

#include <nlohmann/json.hpp>

#include <tutti/content/json_reader.hpp>

namespace tutti::key_action {
namespace {

using content::JsonReader;
using content::NumberField;

Result<PerformanceStyle> read_style(const JsonReader& reader, const nlohmann::json& object,
                                    const std::string& name) {
  const std::string path = "/styles/" + name;
  PerformanceStyle style;
  style.name = name;
  if (!object.is_object()) return reader.error(path, "expected an object");
  if (object.contains("description")) {
    if (!object.at("description").is_string()) {
      return reader.error(path + "/description", "expected a string");
    }
    style.description = object.at("description").get<std::string>();
  }
  nlohmann::json numbers = object;
  numbers.erase("description");
  if (!numbers.contains("finger_speed")) return reader.error(path + "/finger_speed", "missing");
  const nlohmann::json& speeds = numbers.at("finger_speed");
  if (!speeds.is_array() || speeds.size() != 5) {
    return reader.error(path + "/finger_speed", "expected 5 numbers (thumb .. little finger)");
  }
  for (std::size_t f = 0; f < 5; ++f) {
    if (!speeds[f].is_number() || !(speeds[f].get<double>() >= 0.1) ||
        !(speeds[f].get<double>() <= 10.0)) {
      return reader.error(path + "/finger_speed/" + std::to_string(f),
                          "expected a number in [0.1, 10]");
    }
    style.finger_speed[f] = speeds[f].get<double>();
  }
  numbers.erase("finger_speed");
  const NumberField fields[] = {{"strength", &style.strength, 0.05, 4.0},
                                {"min_stroke_s", &style.min_stroke_s, 0.005, 1.0},
                                {"max_stroke_s", &style.max_stroke_s, 0.005, 2.0},
                                {"hover_lift_mm", &style.hover_lift_mm, 0.5, 40.0},
                                {"bend_scale", &style.bend_scale, 0.0, 1.5},
                                {"timing_spread_ms", &style.timing_spread_ms, 0.0, 100.0},
                                {"strength_spread", &style.strength_spread, 0.0, 1.0},
                                {"release_anticipation", &style.release_anticipation, 0.0, 1.0},
                                {"release_s", &style.release_s, 0.005, 1.0},
                                {"relax_time_constant_s", &style.relax_time_constant_s, 0.01, 5.0}};
  if (auto ok = reader.read_number_fields(numbers, path, fields, true); !ok) return ok.error();
  if (!(style.max_stroke_s >= style.min_stroke_s)) {
    return reader.error(path + "/max_stroke_s", "must not be below min_stroke_s");
  }
  return style;
}

}  // namespace

Result<PerformanceStyle> StyleBook::find(std::string_view name) const {
  std::string known;
  for (const PerformanceStyle& style : styles) {
    if (style.name == name) return style;
    known += (known.empty() ? "" : ", ") + style.name;
  }
  return Error{"unknown performance style '" + std::string(name) + "' (styles: " + known + ")"};
}

Result<StyleBook> styles_from_json(const nlohmann::json& document, const std::string& file_name) {
  const JsonReader reader(file_name);
  if (auto ok = reader.check_keys(document, "", {"description", "styles"}); !ok) {
    return ok.error();
  }
  if (!document.contains("styles") || !document.at("styles").is_object() ||
      document.at("styles").empty()) {
    return reader.error("/styles", "expected an object with at least one style");
  }
  StyleBook book;
  for (const auto& [name, object] : document.at("styles").items()) {
    auto style = read_style(reader, object, name);
    if (!style) return style.error();
    book.styles.push_back(std::move(*style));
  }
  return book;
}

Result<StyleBook> load_styles(const std::filesystem::path& path) {
  auto document = content::read_json_file(path);
  if (!document) return document.error();
  return styles_from_json(*document, path.filename().string());
}

std::filesystem::path styles_path(const std::filesystem::path& content_dir) {
  return content_dir / "piano" / "styles.json";
}

finger_motion::FingerMotionParams apply_style(finger_motion::FingerMotionParams params,
                                              const PerformanceStyle& style) {
  params.keys.hover_lift_mm = style.hover_lift_mm;
  for (finger_motion::FingerGeometry& g : params.fingers) {
    g.white_bend_rad *= style.bend_scale;
    g.black_bend_rad *= style.bend_scale;
  }
  params.timing.release_s = style.release_s;
  params.timing.relax_time_constant_s = style.relax_time_constant_s;
  return params;
}

}  // namespace tutti::key_action
