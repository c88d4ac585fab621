// SPDX-License-Identifier: MIT
#include <algorithm>
#include <cmath>
#include <tutti/components/performer.hpp>
#include <tutti/model/model_asset.hpp>
#include <tutti/stage/pose_checker.hpp>

namespace tutti::stage {
namespace {

using pose::distance_to_segment;

// The head as a capsule: from the head node up its local +Y, and its radius.
constexpr float kHeadLengthM = 0.12f;
constexpr float kHeadRadiusM = 0.095f;
// The torso as a capsule from the hips to the neck, as thick as the mannequin's chest is deep.
constexpr float kTorsoRadiusM = 0.10f;
// The sleeves as capsules (content/generator/performer_asset.cpp): the upper arm's is 50 to 41 mm,
// the forearm's 40 to 35 mm and ends 30 mm short of the wrist, where the hand begins to hold.
constexpr float kUpperArmRadiusM = 0.045f;
constexpr float kForearmRadiusM = 0.037f;
constexpr float kSleeveShortOfWristM = 0.03f;
// How fast a joint may turn, from one sampled frame to the next (deg/s; at check-pose's default
// 30 frames a second, the mean over 33 ms). Outside strokes, 1000: issue 29's figure, above what
// a player's sway, breathing, cues and hand shifts need (a keyboard player's arms reach 509 on
// third-party music, a horn player's 176) and below a one-frame snap (a 43 deg turn in one frame
// is 1290). A finger striking a key or pressing a valve moves faster: 2500 (a little finger
// reaches 2176 in third-party octave studies). An arm making a stroke, as the trombonist's slide
// arm moving the slide, a stroke as quick as the slide's top speed (4
// m/s, content/instruments/trombone_tenor.json), bends the elbow at up to 1620: 2000.
constexpr double kBodyJointSpeedLimitDegPerS = 1000.0;
constexpr double kFingerJointSpeedLimitDegPerS = 2500.0;
constexpr double kStrokeArmJointSpeedLimitDegPerS = 2000.0;

// How far inside the box [lo, hi]'s outline across x and y the segment [a, b] passes, where it
// crosses the box (slab clipping); 0 when it misses the box.
double edge_into_box(const glm::vec3& a, const glm::vec3& b, const glm::vec3& lo,
                     const glm::vec3& hi) {
  float enter = 0.0f, leave = 1.0f;
  const glm::vec3 d = b - a;
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(d[axis]) < 1e-9f) {
      if (a[axis] < lo[axis] || a[axis] > hi[axis]) return 0.0;
      continue;
    }
    float t0 = (lo[axis] - a[axis]) / d[axis], t1 = (hi[axis] - a[axis]) / d[axis];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
    if (enter > leave) return 0.0;
  }
  const glm::vec3 mid = a + d * (0.5f * (enter + leave));
  return static_cast<double>(std::min({mid.x - lo.x, hi.x - mid.x, mid.y - lo.y, hi.y - mid.y}));
}

}  // namespace

namespace pose {

// World matrices of a placed model's nodes as posed.
void world_of(const PlacedModel& placed, std::vector<glm::mat4>& out) {
  out.resize(placed.asset->nodes.size());
  model::compute_world_matrices(*placed.asset, placed.pose, placed.root, out);
}

double distance_to_line(const glm::vec3& p, const glm::vec3& on_line, const glm::vec3& direction) {
  const glm::vec3 d = glm::normalize(direction);
  const glm::vec3 v = p - on_line;
  return static_cast<double>(glm::length(v - glm::dot(v, d) * d));
}

double distance_to_segment(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
  const glm::vec3 ab = b - a;
  const float t = std::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-12f), 0.0f, 1.0f);
  return static_cast<double>(glm::length(p - (a + t * ab)));
}

}  // namespace pose

double PoseMeasure::percentile(double p) const {
  if (samples.empty()) return 0.0;
  std::vector<double> sorted = samples;
  std::sort(sorted.begin(), sorted.end());
  const double at = std::clamp(p, 0.0, 1.0) * static_cast<double>(sorted.size() - 1);
  return sorted[static_cast<std::size_t>(std::ceil(at))];
}

void PoseMeasure::add(double value, double t_s, const std::string& of) {
  const auto size = [&](double x) { return two_sided ? std::abs(x) : x; };
  if (samples.empty() || size(value) > size(samples[worst_index_])) {
    worst_index_ = samples.size();
    worst_at_s = t_s;
    worst_of = of;
  }
  samples.push_back(value);
}

bool PoseMeasure::within_limit() const {
  if (limit < 0.0) return true;
  if (two_sided) return std::max(-percentile(0.0), worst()) <= limit;
  return (by_p95 ? percentile(0.95) : worst()) <= limit;
}

const PoseMeasure* PoseReport::find(const std::string& name) const {
  for (const PoseMeasure& m : measures) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

PoseChecker::PoseChecker(ecs::World& world, PoseReport& report, const FingerJointLimits& limits)
    : world_(world), report_(report), limits_(limits) {
  world.view<const components::Note>().each(
      [&](ecs::Entity e, const components::Note& note) { notes_.emplace_back(e, &note); });
}

std::string PoseChecker::performer_name(ecs::Entity performer) const {
  const auto* about = world_.try_get<components::Performer>(performer);
  return about != nullptr ? about->name : std::string("?");
}

void PoseChecker::at_time(double t_s, double dt_s) {
  t_s_ = t_s;
  dt_s_ = dt_s;
}

PoseMeasure& PoseChecker::measure(const std::string& name, const char* unit, double limit,
                                  bool by_p95) {
  for (PoseMeasure& m : report_.measures) {
    if (m.name == name) return m;
  }
  PoseMeasure added;
  added.name = name;
  added.unit = unit;
  added.limit = limit;
  added.by_p95 = by_p95;
  report_.measures.push_back(std::move(added));
  return report_.measures.back();
}

void PoseChecker::joint_speeds(const std::string& who, const PlacedModel& placed,
                               const FingerNodes& fingers, const TwoBoneChain* stroke_arm,
                               std::string_view stroke_name) {
  std::vector<glm::quat>& last = last_rotations_[&placed];
  const std::vector<model::NodeTransform>& now = placed.pose.local;
  if (last.size() == now.size()) {
    enum Kind : std::uint8_t { kBody, kFinger, kStrokeArm, kKinds };
    joint_kind_.assign(now.size(), kBody);
    const auto mark = [&](int node, Kind kind) {
      if (node >= 0 && static_cast<std::size_t>(node) < now.size()) {
        joint_kind_[static_cast<std::size_t>(node)] = kind;
      }
    };
    for (const auto& hand : fingers) {
      for (const auto& finger : hand) {
        for (const int node : finger) mark(node, kFinger);
      }
    }
    if (stroke_arm != nullptr) {
      for (const int node : {stroke_arm->upper, stroke_arm->lower, stroke_arm->end}) {
        mark(node, kStrokeArm);
      }
    }
    std::array<double, kKinds> fastest{};
    std::array<std::size_t, kKinds> fastest_node{};
    for (std::size_t n = 0; n < now.size(); ++n) {
      const double cos_half =
          std::min(1.0, static_cast<double>(std::abs(glm::dot(last[n], now[n].rotation))));
      const double degrees = 2.0 * std::acos(cos_half) * 180.0 / 3.14159265358979323846;
      const auto kind = static_cast<Kind>(joint_kind_[n]);
      if (degrees > fastest[kind]) fastest[kind] = degrees, fastest_node[kind] = n;
    }
    const std::string names[kKinds] = {": fastest joint's angular speed outside strokes",
                                       ": fastest finger joint's angular speed",
                                       ": " + std::string(stroke_name)};
    static constexpr double kLimits[kKinds] = {kBodyJointSpeedLimitDegPerS,
                                               kFingerJointSpeedLimitDegPerS,
                                               kStrokeArmJointSpeedLimitDegPerS};
    for (std::size_t kind = 0; kind < kKinds; ++kind) {
      if (kind == kStrokeArm && stroke_arm == nullptr) continue;
      measure(who + names[kind], "deg/s", kLimits[kind])
          .add(fastest[kind] / dt_s_, t_s_,
               fastest[kind] > 0.0 ? placed.asset->nodes[fastest_node[kind]].name : std::string());
    }
  }
  last.resize(now.size());
  for (std::size_t n = 0; n < now.size(); ++n) last[n] = now[n].rotation;
}

// How deep the deepest of `points` is inside the head's capsule (0 = all outside).
void PoseChecker::head_clearance(const std::string& who, int head,
                                 const std::vector<glm::vec3>& points) {
  if (head < 0) return;
  const glm::mat4& h = body_world_[static_cast<std::size_t>(head)];
  const glm::vec3 bottom = origin(h);
  const glm::vec3 top = bottom + glm::normalize(glm::vec3(h[1])) * kHeadLengthM;
  double clearance = 1e9;
  for (const glm::vec3& p : points) {
    clearance = std::min(clearance, distance_to_segment(p, bottom, top) - kHeadRadiusM);
  }
  measure(who + ": hands and fingertips inside the head (depth; 0 = outside)", "mm", 0.0)
      .add(std::max(0.0, -clearance) * 1000.0, t_s_);
}

// How deep the deepest of `points` is inside the torso's capsule (hips to neck).
void PoseChecker::torso_clearance(const std::string& who, int hips, int neck,
                                  const std::vector<glm::vec3>& points) {
  if (hips < 0 || neck < 0) return;
  const glm::vec3 bottom = origin(body_world_[static_cast<std::size_t>(hips)]);
  const glm::vec3 top = origin(body_world_[static_cast<std::size_t>(neck)]);
  double clearance = 1e9;
  for (const glm::vec3& p : points) {
    clearance = std::min(clearance, distance_to_segment(p, bottom, top) - kTorsoRadiusM);
  }
  measure(who + ": hands, fingertips and elbows inside the torso (depth; 0 = outside)", "mm", 0.0)
      .add(std::max(0.0, -clearance) * 1000.0, t_s_);
}

// How deep the instrument's surface reaches into either arm's sleeve (shoulder to elbow, elbow to
// the cuff): an arm passing through a tube or the bell shows here. Hands are left out: they hold.
void PoseChecker::arms_clear_of_instrument(const std::string& who, const PlacedModel& horn,
                                           const BodyNodes& nodes) {
  struct Capsule {
    glm::vec3 a, b;
    float radius;
    const char* name;
  };
  std::vector<Capsule> arms;
  for (const TwoBoneChain* arm : {&nodes.arm_left, &nodes.arm_right}) {
    if (arm->upper < 0 || arm->lower < 0 || arm->end < 0) continue;
    const bool left = arm == &nodes.arm_left;
    const glm::vec3 shoulder = origin(body_world_[static_cast<std::size_t>(arm->upper)]);
    const glm::vec3 elbow = origin(body_world_[static_cast<std::size_t>(arm->lower)]);
    const glm::vec3 wrist = origin(body_world_[static_cast<std::size_t>(arm->end)]);
    const float forearm = glm::distance(elbow, wrist);
    if (forearm <= kSleeveShortOfWristM) continue;
    const glm::vec3 cuff = elbow + (wrist - elbow) * ((forearm - kSleeveShortOfWristM) / forearm);
    arms.push_back(
        {shoulder, elbow, kUpperArmRadiusM, left ? "left upper arm" : "right upper arm"});
    arms.push_back({elbow, cuff, kForearmRadiusM, left ? "left forearm" : "right forearm"});
  }
  if (arms.empty()) return;
  double depth = 0.0;
  const Capsule* deepest_arm = nullptr;
  std::size_t deepest_node = 0;
  const model::ModelAsset& asset = *horn.asset;
  for (std::size_t n = 0; n < asset.nodes.size(); ++n) {
    const model::Node& node = asset.nodes[n];
    if (node.mesh < 0 || node.skin >= 0) continue;
    const glm::mat4& world = instrument_world_[n];
    for (const model::Primitive& primitive :
         asset.meshes[static_cast<std::size_t>(node.mesh)].primitives) {
      for (std::uint32_t v = 0; v < primitive.vertex_count; ++v) {
        const glm::vec3 p =
            world * glm::vec4(asset.vertices[primitive.first_vertex + v].position, 1.0f);
        for (const Capsule& arm : arms) {
          const double into =
              static_cast<double>(arm.radius) - distance_to_segment(p, arm.a, arm.b);
          if (into > depth) depth = into, deepest_arm = &arm, deepest_node = n;
        }
      }
    }
  }
  measure(who + ": instrument inside an arm's sleeve (depth; 0 = clear)", "mm", 0.0)
      .add(depth * 1000.0, t_s_,
           deepest_arm == nullptr
               ? std::string()
               : asset.nodes[deepest_node].name + " in the " + deepest_arm->name);
}

const PoseChecker::DeskPanel& PoseChecker::desk_panel(const model::ModelAsset& asset) {
  auto [it, added] = desk_panels_.try_emplace(&asset);
  if (!added) return it->second;
  const int desk = asset.find_node("desk");
  if (desk < 0 || asset.nodes[static_cast<std::size_t>(desk)].mesh < 0) return it->second;
  glm::vec3 lo(1e9f), hi(-1e9f);
  const int mesh = asset.nodes[static_cast<std::size_t>(desk)].mesh;
  for (const model::Primitive& primitive :
       asset.meshes[static_cast<std::size_t>(mesh)].primitives) {
    for (std::uint32_t v = 0; v < primitive.vertex_count; ++v) {
      const glm::vec3& p = asset.vertices[primitive.first_vertex + v].position;
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  }
  hi.z = std::min(hi.z, 0.0f);
  if (lo.x < hi.x && lo.y < hi.y && lo.z < hi.z) it->second = {desk, lo, hi};
  return it->second;
}

// How far the instrument passes through its music stand's desk (a slide dipped too far goes
// through the music): any edge of the instrument's triangles crossing the desk's panel, measured
// inward from the panel's nearest side (0 = clear). The panel is the desk mesh's outline with
// its face at z = 0 of the desk's frame, the thickness behind it
// (content/generator/props.hpp); the ledge in front of it is left out.
void PoseChecker::instrument_clear_of_desk(const std::string& who, const PlacedModel& horn,
                                           const PlacedModel& stand) {
  const DeskPanel& panel = desk_panel(*stand.asset);
  if (panel.node < 0) return;
  const glm::vec3 lo = panel.lo, hi = panel.hi;
  pose::world_of(stand, stand_world_);
  const glm::mat4 into_desk = glm::inverse(stand_world_[static_cast<std::size_t>(panel.node)]);
  double depth = 0.0;
  std::size_t deepest_node = 0;
  const model::ModelAsset& asset = *horn.asset;
  for (std::size_t n = 0; n < asset.nodes.size(); ++n) {
    const model::Node& node = asset.nodes[n];
    if (node.mesh < 0 || node.skin >= 0) continue;
    const glm::mat4 to_desk = into_desk * instrument_world_[n];
    for (const model::Primitive& primitive :
         asset.meshes[static_cast<std::size_t>(node.mesh)].primitives) {
      local_points_.resize(primitive.vertex_count);
      for (std::uint32_t v = 0; v < primitive.vertex_count; ++v) {
        local_points_[v] =
            to_desk * glm::vec4(asset.vertices[primitive.first_vertex + v].position, 1.0f);
      }
      for (std::uint32_t i = 0; i + 2 < primitive.index_count; i += 3) {
        const std::uint32_t* corner = &asset.indices[primitive.first_index + i];
        for (int e = 0; e < 3; ++e) {
          const double inward =
              edge_into_box(local_points_[corner[e]], local_points_[corner[(e + 1) % 3]], lo, hi);
          if (inward > depth) depth = inward, deepest_node = n;
        }
      }
    }
  }
  measure(who + ": instrument through the music stand's desk (depth; 0 = clear)", "mm", 0.0)
      .add(depth * 1000.0, t_s_, depth > 0.0 ? asset.nodes[deepest_node].name : std::string());
}

// The worst finger joint (index .. little) of a posed hand past its limits.
void PoseChecker::finger_limits(const std::string& who, const model::ModelAsset& asset,
                                const model::ModelPose& pose, const BodyNodes& nodes) {
  double worst = 0.0;
  int worst_node = -1;
  for (std::size_t side = 0; side < 2; ++side) {
    for (std::size_t f = 1; f < 5; ++f) {
      for (std::size_t j = 0; j < 3; ++j) {
        const int node = nodes.fingers[side][f][j];
        const int child = j < 2 ? nodes.fingers[side][f][j + 1] : nodes.fingertips[side][f];
        if (node < 0 || child < 0) continue;
        const double past =
            past_limit(pose.local[static_cast<std::size_t>(node)].rotation,
                       asset.nodes[static_cast<std::size_t>(child)].rest.translation,
                       static_cast<int>(side), limits_[f][j]);
        if (past > worst) worst = past, worst_node = node;
      }
    }
  }
  measure(who + ": finger joints past their limits (worst joint)", "deg", 0.5)
      .add(worst, t_s_,
           worst_node < 0 ? std::string() : asset.nodes[static_cast<std::size_t>(worst_node)].name);
}

}  // namespace tutti::stage
