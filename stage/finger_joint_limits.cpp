// SPDX-License-Identifier: MIT
#include <tutti/stage/finger_joint_limits.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include <nlohmann/json.hpp>

#include <tutti/content/content_dir.hpp>
#include <tutti/content/json_reader.hpp>

namespace tutti::stage {
namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;
constexpr const char* kFingerNames[5] = {"thumb", "index", "middle", "ring", "little"};

glm::vec3 flexion_axis(int side) { return side == 0 ? glm::vec3(0, 0, -1) : glm::vec3(0, 0, 1); }

}  // namespace

Result<FingerJointLimits> load_finger_joint_limits(const std::filesystem::path& content_dir) {
  const std::filesystem::path file =
      (content_dir.empty() ? content::default_content_dir() : content_dir) / "generator" /
      "hand_rig.json";
  auto doc = content::read_json_file(file);
  if (!doc) return doc.error();
  if (!doc->contains("joint_limits_deg") || !doc->at("joint_limits_deg").is_object()) {
    return Error{file.string() + ": /joint_limits_deg: missing"};
  }
  const nlohmann::json& all = doc->at("joint_limits_deg");
  FingerJointLimits limits{};
  for (std::size_t f = 0; f < 5; ++f) {
    for (std::size_t s = 0; s < 3; ++s) {
      const std::string key = std::string(kFingerNames[f]) + "_" + std::to_string(s + 1);
      if (!all.contains(key)) continue;
      const nlohmann::json& joint = all.at(key);
      if (!joint.is_object()) {
        return Error{file.string() + ": /joint_limits_deg/" + key + ": expected an object"};
      }
      const auto get = [&](const char* name, double fallback) -> Result<double> {
        if (!joint.contains(name)) return fallback;
        if (!joint.at(name).is_number()) {
          return Error{file.string() + ": /joint_limits_deg/" + key + "/" + name +
                       ": expected a number of degrees"};
        }
        return joint.at(name).get<double>();
      };
      FingerJointLimit& limit = limits[f][s];
      for (auto [slot, name, fallback] :
           {std::tuple{&limit.flexion_min_deg, "flexion_min_deg", -180.0},
            std::tuple{&limit.flexion_max_deg, "flexion_max_deg", 180.0},
            std::tuple{&limit.spread_min_deg, "spread_min_deg", 0.0},
            std::tuple{&limit.spread_max_deg, "spread_max_deg", 0.0}}) {
        auto value = get(name, fallback);
        if (!value) return value.error();
        *slot = *value;
      }
      if (limit.flexion_min_deg > limit.flexion_max_deg ||
          limit.spread_min_deg > limit.spread_max_deg) {
        return Error{file.string() + ": /joint_limits_deg/" + key + ": a minimum above its maximum"};
      }
    }
  }
  return limits;
}

FlexionSpread flexion_and_spread(const glm::quat& rotation, const glm::vec3& child_rest, int side) {
  const glm::vec3 axis = flexion_axis(side);
  const glm::vec3 rest = glm::normalize(child_rest);
  const glm::vec3 posed = glm::normalize(rotation * child_rest);
  const glm::vec3 rest_in_plane = rest - glm::dot(rest, axis) * axis;
  const glm::vec3 posed_in_plane = posed - glm::dot(posed, axis) * axis;
  FlexionSpread read;
  read.flexion_deg =
      std::atan2(static_cast<double>(glm::dot(axis, glm::cross(rest_in_plane, posed_in_plane))),
                 static_cast<double>(glm::dot(rest_in_plane, posed_in_plane))) /
      kDegree;
  // Spread > 0 turns toward the little finger (local -Z on both hands).
  read.spread_deg = -(std::asin(std::clamp(static_cast<double>(posed.z), -1.0, 1.0)) -
                      std::asin(std::clamp(static_cast<double>(rest.z), -1.0, 1.0))) /
                    kDegree;
  return read;
}

double past_limit(const glm::quat& rotation, const glm::vec3& child_rest, int side,
                  const FingerJointLimit& limit) {
  const FlexionSpread read = flexion_and_spread(rotation, child_rest, side);
  return std::max({0.0, limit.flexion_min_deg - read.flexion_deg,
                   read.flexion_deg - limit.flexion_max_deg, limit.spread_min_deg - read.spread_deg,
                   read.spread_deg - limit.spread_max_deg});
}

glm::quat clamp_to_limit(const glm::quat& rotation, const glm::vec3& child_rest, int side,
                         const FingerJointLimit& limit) {
  glm::quat clamped = rotation;
  const FlexionSpread read = flexion_and_spread(rotation, child_rest, side);
  const double spread =
      std::clamp(read.spread_deg, limit.spread_min_deg, limit.spread_max_deg);
  if (spread != read.spread_deg) {
    // Turning the bone about (bone × +Z) raises it toward +Z, which is spread's negative, and
    // leaves its heading in the flexion plane as it was.
    const glm::vec3 bone = glm::normalize(clamped * child_rest);
    const glm::vec3 raise = glm::cross(bone, glm::vec3(0, 0, 1));
    if (glm::length(raise) > 1e-6f) {
      clamped = glm::angleAxis(static_cast<float>((read.spread_deg - spread) * kDegree),
                               glm::normalize(raise)) *
                clamped;
    }
  }
  const double flexion =
      std::clamp(read.flexion_deg, limit.flexion_min_deg, limit.flexion_max_deg);
  if (flexion != read.flexion_deg) {
    clamped = glm::angleAxis(static_cast<float>((flexion - read.flexion_deg) * kDegree),
                             flexion_axis(side)) *
              clamped;
  }
  return glm::normalize(clamped);
}

}  // namespace tutti::stage
