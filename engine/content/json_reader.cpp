// SPDX-License-Identifier: MIT
#include <tutti/content/json_reader.hpp>

#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <vector>

#include <tutti/core/did_you_mean.hpp>
#include <tutti/core/file_io.hpp>

namespace tutti::content {

Result<nlohmann::json> read_json_file(const std::filesystem::path& path) {
  auto bytes = read_file_bytes(path);
  if (!bytes) return bytes.error();
  nlohmann::json document =
      nlohmann::json::parse(bytes->begin(), bytes->end(), nullptr, /*allow_exceptions=*/false);
  if (document.is_discarded()) return Error{path.string() + ": not valid JSON"};
  return document;
}

Error JsonReader::error(std::string_view path, std::string_view reason) const {
  return Error{file_ + ": " + std::string(path.empty() ? "/" : path) + ": " + std::string(reason)};
}

Status JsonReader::check_keys(const nlohmann::json& object, std::string_view path,
                              std::initializer_list<std::string_view> allowed) const {
  if (!object.is_object()) return error(path, "expected an object");
  for (const auto& item : object.items()) {
    bool known = false;
    for (std::string_view key : allowed) known = known || key == item.key();
    if (!known) {
      const std::vector<std::string_view> names(allowed.begin(), allowed.end());
      return error(std::string(path) + "/" + item.key(),
                   "unknown key" + did_you_mean(item.key(), names));
    }
  }
  return Status::success();
}

Result<double> JsonReader::number(const nlohmann::json& object, std::string_view path,
                                  const char* key) const {
  const std::string where = std::string(path) + "/" + key;
  if (!object.contains(key)) return error(where, "missing");
  const nlohmann::json& value = object.at(key);
  if (!value.is_number()) return error(where, "expected a number");
  const double number = value.get<double>();
  if (!std::isfinite(number)) return error(where, "expected a finite number");
  return number;
}

Result<double> JsonReader::number_or(const nlohmann::json& object, std::string_view path,
                                     const char* key, double fallback) const {
  if (!object.contains(key)) return fallback;
  return number(object, path, key);
}

Result<double> JsonReader::number_or_inf(const nlohmann::json& object, std::string_view path,
                                         const char* key) const {
  if (object.contains(key) && object.at(key).is_string()) {
    if (object.at(key).get<std::string>() == "inf") return std::numeric_limits<double>::infinity();
    return error(std::string(path) + "/" + key, "expected a number or \"inf\"");
  }
  return number(object, path, key);
}

Status JsonReader::read_number_fields(const nlohmann::json& object, std::string_view path,
                                      std::span<const NumberField> fields, bool required) const {
  if (!object.is_object()) return error(path, "expected an object");
  for (const auto& item : object.items()) {
    bool known = item.key() == "description";
    for (const NumberField& f : fields) known = known || item.key() == f.key;
    if (!known) {
      std::vector<std::string_view> names{"description"};
      for (const NumberField& f : fields) names.push_back(f.key);
      return error(std::string(path) + "/" + item.key(),
                   "unknown key" + did_you_mean(item.key(), names));
    }
  }
  if (object.contains("description") && !object.at("description").is_string()) {
    return error(std::string(path) + "/description", "expected a string");
  }
  auto text = [](double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", value);
    return std::string(buffer);
  };
  for (const NumberField& f : fields) {
    auto value = required ? number(object, path, f.key) : number_or(object, path, f.key, *f.value);
    if (!value) return value.error();
    if (*value < f.lo || *value > f.hi) {
      return error(std::string(path) + "/" + f.key,
                   "must be in [" + text(f.lo) + ", " + text(f.hi) + "]");
    }
    *f.value = *value;
  }
  return {};
}

}  // namespace tutti::content
