// SPDX-License-Identifier: MIT
#pragma once
// Typed field reads for the scene and mapping loaders, on top of content::JsonReader: each
// returns the value or a one-line "FILE: /path/key: reason" error. Absent optional fields keep
// the fallback. Shared with the families' scene sections (scene_section.hpp).

#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>
#include <utility>

#include <tutti/content/json_reader.hpp>
#include <tutti/scene/scene.hpp>

namespace tutti::scene {

std::string format_number(double value);  // "%g"
std::string join_path(std::string_view path, std::string_view key);

class FieldReader {
 public:
  explicit FieldReader(std::string file_name) : json_(std::move(file_name)) {}

  const content::JsonReader& json() const { return json_; }
  Error error(std::string_view path, std::string_view reason) const {
    return json_.error(path, reason);
  }

  // A number in [lo, hi]; required unless `fallback` is given.
  Result<double> number(const nlohmann::json& object, std::string_view path, const char* key,
                        double lo, double hi) const;
  Result<double> number_or(const nlohmann::json& object, std::string_view path, const char* key,
                           double lo, double hi, double fallback) const;
  // A JSON integer (not 2.0) in [lo, hi].
  Result<std::int64_t> integer_or(const nlohmann::json& object, std::string_view path,
                                  const char* key, std::int64_t lo, std::int64_t hi,
                                  std::int64_t fallback) const;
  // A non-negative JSON integer up to 2^64 - 1.
  Result<std::uint64_t> seed(const nlohmann::json& object, std::string_view path,
                             const char* key) const;
  Result<bool> boolean_or(const nlohmann::json& object, std::string_view path, const char* key,
                          bool fallback) const;
  // A string; `allow_empty` false: "must not be empty".
  Result<std::string> string(const nlohmann::json& object, std::string_view path, const char* key,
                             bool allow_empty = false) const;
  Result<std::string> string_or(const nlohmann::json& object, std::string_view path,
                                const char* key, std::string fallback) const;
  // [x, y, z], each finite and |v| <= limit.
  Result<Vec3> vec3(const nlohmann::json& object, std::string_view path, const char* key,
                    double limit) const;
  Result<Vec3> vec3_or(const nlohmann::json& object, std::string_view path, const char* key,
                       double limit, Vec3 fallback) const;
  // [r, g, b], each in [0, 1].
  Result<Color> color_or(const nlohmann::json& object, std::string_view path, const char* key,
                         Color fallback) const;

 private:
  Result<double> check_range(double value, std::string_view where, double lo, double hi) const;
  content::JsonReader json_;
};

}  // namespace tutti::scene
