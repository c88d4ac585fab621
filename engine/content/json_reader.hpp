// SPDX-License-Identifier: MIT
#pragma once
// Small helpers for reading the data files under content/ (JSON) into values with one-line errors
// that name the file and the JSON path ("hands.json: /presets/small/scale: expected a number").
// Every object is checked for unknown keys, so a typo is an error instead of a silent default.

#include <filesystem>
#include <initializer_list>
#include <nlohmann/json_fwd.hpp>
#include <span>
#include <string>
#include <string_view>

#include <tutti/core/result.hpp>

namespace tutti::content {

// Reads and parses a JSON file (size-capped). Errors: missing file, "<file>: not JSON (...)".
Result<nlohmann::json> read_json_file(const std::filesystem::path& path);

// Reports problems relative to one file; `path` is a JSON pointer such as "/weights/thumb".
// One number of a flat parameter object: read into *value (kept when absent and not required),
// which must lie in [lo, hi].
struct NumberField {
  const char* key;
  double* value;
  double lo;
  double hi;
};

class JsonReader {
 public:
  explicit JsonReader(std::string file_name) : file_(std::move(file_name)) {}

  Error error(std::string_view path, std::string_view reason) const;

  // Error when `object` is not an object or has a key outside `allowed`.
  Status check_keys(const nlohmann::json& object, std::string_view path,
                    std::initializer_list<std::string_view> allowed) const;
  // A required finite number.
  Result<double> number(const nlohmann::json& object, std::string_view path, const char* key) const;
  // An optional finite number (fallback when absent).
  Result<double> number_or(const nlohmann::json& object, std::string_view path, const char* key,
                           double fallback) const;
  // A finite number or the string "inf" (+infinity), required.
  Result<double> number_or_inf(const nlohmann::json& object, std::string_view path,
                               const char* key) const;

  // A flat object of numbers (plus an optional "description" string): every key must be one of
  // `fields`; each field is read and range-checked. `required`: every field must be present.
  Status read_number_fields(const nlohmann::json& object, std::string_view path,
                            std::span<const NumberField> fields, bool required) const;

  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

}  // namespace tutti::content
