// SPDX-License-Identifier: MIT
#include <tutti/scene/json_fields.hpp>

#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>

namespace tutti::scene {

std::string format_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

std::string join_path(std::string_view path, std::string_view key) {
  return std::string(path) + "/" + std::string(key);
}

Result<double> FieldReader::check_range(double value, std::string_view where, double lo,
                                        double hi) const {
  if (value < lo || value > hi) {
    return error(where, "must be in [" + format_number(lo) + ", " + format_number(hi) + "]");
  }
  return value;
}

Result<double> FieldReader::number(const nlohmann::json& object, std::string_view path,
                                   const char* key, double lo, double hi) const {
  auto value = json_.number(object, path, key);
  if (!value) return value.error();
  return check_range(*value, join_path(path, key), lo, hi);
}

Result<double> FieldReader::number_or(const nlohmann::json& object, std::string_view path,
                                      const char* key, double lo, double hi,
                                      double fallback) const {
  if (!object.contains(key)) return fallback;
  return number(object, path, key, lo, hi);
}

Result<std::int64_t> FieldReader::integer_or(const nlohmann::json& object, std::string_view path,
                                             const char* key, std::int64_t lo, std::int64_t hi,
                                             std::int64_t fallback) const {
  if (!object.contains(key)) return fallback;
  const std::string where = join_path(path, key);
  const nlohmann::json& value = object.at(key);
  if (!value.is_number_integer()) return error(where, "expected an integer");
  if (value.is_number_unsigned() &&
      value.get<std::uint64_t>() >
          static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
    return error(where, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
  const auto number = value.get<std::int64_t>();
  if (number < lo || number > hi) {
    return error(where, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
  return number;
}

Result<std::uint64_t> FieldReader::seed(const nlohmann::json& object, std::string_view path,
                                        const char* key) const {
  const std::string where = join_path(path, key);
  if (!object.contains(key)) return error(where, "missing");
  const nlohmann::json& value = object.at(key);
  if (!value.is_number_unsigned()) {
    return error(where, "expected a non-negative integer (at most 18446744073709551615)");
  }
  return value.get<std::uint64_t>();
}

Result<bool> FieldReader::boolean_or(const nlohmann::json& object, std::string_view path,
                                     const char* key, bool fallback) const {
  if (!object.contains(key)) return fallback;
  const nlohmann::json& value = object.at(key);
  if (!value.is_boolean()) return error(join_path(path, key), "expected true or false");
  return value.get<bool>();
}

Result<std::string> FieldReader::string(const nlohmann::json& object, std::string_view path,
                                        const char* key, bool allow_empty) const {
  const std::string where = join_path(path, key);
  if (!object.contains(key)) return error(where, "missing");
  const nlohmann::json& value = object.at(key);
  if (!value.is_string()) return error(where, "expected a string");
  std::string text = value.get<std::string>();
  if (!allow_empty && text.empty()) return error(where, "must not be empty");
  return text;
}

Result<std::string> FieldReader::string_or(const nlohmann::json& object, std::string_view path,
                                           const char* key, std::string fallback) const {
  if (!object.contains(key)) return fallback;
  return string(object, path, key);
}

Result<Vec3> FieldReader::vec3(const nlohmann::json& object, std::string_view path, const char* key,
                               double limit) const {
  const std::string where = join_path(path, key);
  if (!object.contains(key)) return error(where, "missing");
  const nlohmann::json& value = object.at(key);
  if (!value.is_array() || value.size() != 3) return error(where, "expected [x, y, z]");
  double v[3];
  for (std::size_t i = 0; i < 3; ++i) {
    const std::string item = where + "/" + std::to_string(i);
    if (!value[i].is_number()) return error(item, "expected a number");
    v[i] = value[i].get<double>();
    if (!std::isfinite(v[i])) return error(item, "expected a finite number");
    if (auto ok = check_range(v[i], item, -limit, limit); !ok) return ok.error();
  }
  return Vec3{v[0], v[1], v[2]};
}

Result<Vec3> FieldReader::vec3_or(const nlohmann::json& object, std::string_view path,
                                  const char* key, double limit, Vec3 fallback) const {
  if (!object.contains(key)) return fallback;
  return vec3(object, path, key, limit);
}

Result<Color> FieldReader::color_or(const nlohmann::json& object, std::string_view path,
                                    const char* key, Color fallback) const {
  if (!object.contains(key)) return fallback;
  const std::string where = join_path(path, key);
  const nlohmann::json& value = object.at(key);
  if (!value.is_array() || value.size() != 3) return error(where, "expected [r, g, b]");
  double c[3];
  for (std::size_t i = 0; i < 3; ++i) {
    const std::string item = where + "/" + std::to_string(i);
    if (!value[i].is_number()) return error(item, "expected a number");
    c[i] = value[i].get<double>();
    if (auto ok = check_range(c[i], item, 0.0, 1.0); !ok) return ok.error();
  }
  return Color{c[0], c[1], c[2]};
}

}  // namespace tutti::scene
