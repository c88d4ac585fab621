// SPDX-License-Identifier: MIT
#include <tutti/key_action/key_action_params.hpp>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include <tutti/content/json_reader.hpp>

namespace tutti::key_action {
namespace {

using content::JsonReader;
using content::NumberField;

constexpr double kHuge = 1e6;

Status read_lever(const JsonReader& reader, const nlohmann::json& document, const char* key,
                  KeyLever& lever) {
  const std::string path = std::string("/") + key;
  if (!document.contains(key)) return reader.error(path, "missing");
  const NumberField fields[] = {{"front_y_mm", &lever.front_y_mm, -kHuge, kHuge},
                                {"pivot_y_mm", &lever.pivot_y_mm, -kHuge, kHuge},
                                {"front_dip_mm", &lever.front_dip_mm, 1e-3, 100.0}};
  if (auto ok = reader.read_number_fields(document.at(key), path, fields, true); !ok) return ok;
  if (!(lever.pivot_y_mm > lever.front_y_mm + 10.0)) {
    return reader.error(path + "/pivot_y_mm", "must lie at least 10 mm behind front_y_mm");
  }
  return Status::success();
}

}  // namespace

double KeyLever::bed_angle_rad() const { return std::atan(front_dip_mm / length_mm()); }

double KeyLever::travel_at_mm(double y_mm) const {
  const double arm = pivot_y_mm - std::clamp(y_mm, front_y_mm, pivot_y_mm - 1.0);
  return arm * front_dip_mm / length_mm();
}

double KeyLever::angle_rad(double y_mm, double depth_mm) const {
  if (!(depth_mm > 0.0)) return 0.0;
  const double arm = pivot_y_mm - std::clamp(y_mm, front_y_mm, pivot_y_mm - 1.0);
  return std::min(std::atan(depth_mm / arm), bed_angle_rad());
}

int VelocityCurve::velocity_for(double speed_mm_s) const {
  if (fixed > 0.0) return static_cast<int>(fixed);
  const double u = std::log(std::max(speed_mm_s, 1e-9) / min_mm_s) / std::log(max_mm_s / min_mm_s);
  return 1 + static_cast<int>(std::lround(126.0 * std::clamp(u, 0.0, 1.0)));
}

double VelocityCurve::speed_for(int velocity) const {
  const double u = (std::clamp(velocity, 1, 127) - 1) / 126.0;
  return min_mm_s * std::pow(max_mm_s / min_mm_s, u);
}

Result<KeyAction> key_action_from_json(const nlohmann::json& document,
                                       const std::string& file_name) {
  const JsonReader reader(file_name);
  if (auto ok = reader.check_keys(document, "",
                                  {"description", "source", "white", "black", "escapement_fraction",
                                   "damper_fraction", "reset_fraction", "return_s", "velocity"});
      !ok) {
    return ok.error();
  }
  KeyAction action;
  if (auto ok = read_lever(reader, document, "white", action.white); !ok) return ok.error();
  if (auto ok = read_lever(reader, document, "black", action.black); !ok) return ok.error();
  const NumberField fractions[] = {{"escapement_fraction", &action.escapement_fraction, 0.05, 0.99},
                                   {"damper_fraction", &action.damper_fraction, 0.01, 0.99},
                                   {"reset_fraction", &action.reset_fraction, 0.01, 0.99},
                                   {"return_s", &action.return_s, 1e-3, 1.0}};
  for (const NumberField& field : fractions) {
    auto value = reader.number(document, "", field.key);
    if (!value) return value.error();
    if (*value < field.lo || *value > field.hi) {
      return reader.error(std::string("/") + field.key, "must lie in [" + std::to_string(field.lo) +
                                                            ", " + std::to_string(field.hi) + "]");
    }
    *field.value = *value;
  }
  if (!(action.damper_fraction < action.escapement_fraction)) {
    return reader.error("/damper_fraction", "must be below escapement_fraction");
  }
  if (!(action.reset_fraction >= action.damper_fraction &&
        action.reset_fraction < action.escapement_fraction)) {
    return reader.error("/reset_fraction", "must lie in [damper_fraction, escapement_fraction)");
  }
  if (!document.contains("velocity")) return reader.error("/velocity", "missing");
  VelocityCurve& curve = action.velocity;
  const NumberField speeds[] = {{"silent_below_mm_s", &curve.silent_below_mm_s, 0.0, kHuge},
                                {"min_mm_s", &curve.min_mm_s, 1e-3, kHuge},
                                {"max_mm_s", &curve.max_mm_s, 1e-3, kHuge}};
  nlohmann::json speeds_only = document.at("velocity");
  if (speeds_only.is_object()) speeds_only.erase("fixed");  // optional, read below
  if (auto ok = reader.read_number_fields(speeds_only, "/velocity", speeds, true); !ok) {
    return ok.error();
  }
  auto fixed = reader.number_or(document.at("velocity"), "/velocity", "fixed", 0.0);
  if (!fixed) return fixed.error();
  if (*fixed < 0.0 || *fixed > 127.0) {
    return reader.error("/velocity/fixed", "must lie in [0, 127] (0 = from the key's speed)");
  }
  curve.fixed = *fixed;
  if (!(curve.silent_below_mm_s <= curve.min_mm_s)) {
    return reader.error("/velocity/silent_below_mm_s", "must not exceed min_mm_s");
  }
  if (!(curve.max_mm_s > curve.min_mm_s)) {
    return reader.error("/velocity/max_mm_s", "must exceed min_mm_s");
  }
  if (curve.fixed != std::floor(curve.fixed)) {
    return reader.error("/velocity/fixed", "must be an integer (0 = from the key's speed)");
  }
  return action;
}

Result<KeyAction> load_key_action(const std::filesystem::path& path, const nlohmann::json& touch,
                                  const std::string& touch_name) {
  auto document = content::read_json_file(path);
  if (!document) return document.error();
  if (touch.is_null() || (touch.is_object() && touch.empty())) {
    return key_action_from_json(*document, path.filename().string());
  }
  if (!touch.is_object()) return Error{touch_name + ": expected an object"};
  document->merge_patch(touch);
  return key_action_from_json(*document, touch_name + " over " + path.filename().string());
}

Result<KeyAction> load_key_action(const std::filesystem::path& path) {
  auto document = content::read_json_file(path);
  if (!document) return document.error();
  return key_action_from_json(*document, path.filename().string());
}

std::filesystem::path key_action_path(const std::filesystem::path& content_dir) {
  return content_dir / "piano" / "key_action.json";
}

}  // namespace tutti::key_action
