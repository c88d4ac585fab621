// SPDX-License-Identifier: MIT
#include <tutti/stage/family_draft.hpp>

#include <cctype>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

namespace tutti::stage {
namespace {

using json = nlohmann::ordered_json;

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace

std::string draft_part_reference(const music::Score& score, int p) {
  const music::Part& part = score.parts[static_cast<std::size_t>(p)];
  if (part.name.empty()) return part.id;
  int same = 0;
  for (const music::Part& other : score.parts) same += lower(other.name) == lower(part.name);
  return same == 1 ? part.name : part.id;
}

double draft_round_mm(double v) { return std::round(v * 1000.0) / 1000.0; }

json draft_vec3(double x, double y, double z) {
  return json::array({draft_round_mm(x), draft_round_mm(y), draft_round_mm(z)});
}

std::pair<double, double> draft_ahead(double x, double z, double angle_deg, double distance) {
  const double a = angle_deg * std::numbers::pi / 180.0;
  return {x + distance * std::sin(a), z + distance * std::cos(a)};
}

json draft_camera(const std::string& name, double px, double py, double pz, double tx, double ty,
                  double tz, double fov_deg) {
  return json{{"name", name},
              {"position_m", draft_vec3(px, py, pz)},
              {"target_m", draft_vec3(tx, ty, tz)},
              {"fov_deg", fov_deg}};
}

json draft_wide_camera(const std::string& name, double left, double right, double front_z,
                       double fov_deg) {
  const double aspect = 16.0 / 9.0;
  const double half_width = (right - left) / 2.0;
  const double tan_half = std::tan(fov_deg * std::numbers::pi / 360.0) * aspect;
  const double distance = half_width / tan_half + 0.8;
  const double cx = (left + right) / 2.0;
  return draft_camera(name, cx, 1.5 + 0.05 * distance, front_z + distance, cx, 0.95,
                      front_z - 0.3, fov_deg);
}

}  // namespace tutti::stage
