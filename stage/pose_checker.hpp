// SPDX-License-Identifier: MIT
#pragma once
// Contacts and clearances as measured facts (`tutti check-pose`): the staged scene posed frame by
// frame and the posed skeletons read back. PoseChecker holds the report's measures and the
// measures every family can take of its performers (how fast joints turn, hands inside the head
// or the torso, an instrument inside an arm's sleeve or through its music stand's desk, fingers
// past their joint limits); each family adds its own in FamilyPlugin::check_pose (a fingertip on
// its valve button, a pad on its key, a toe on its pedal, ...). The program's frame loop is
// app/cli's check_pose.

#include <any>
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <tutti/components/note.hpp>
#include <tutti/ecs/world.hpp>
#include <tutti/stage/finger_joint_limits.hpp>
#include <tutti/stage/fingertip_reach.hpp>
#include <tutti/stage/performer_rig.hpp>
#include <tutti/stage/stage.hpp>
#include <tutti/stage/two_bone_ik.hpp>

namespace tutti::stage {

// One figure over the frames it applies to: a distance (mm) or a share (%).
struct PoseMeasure {
  std::string name;     // "Horn: fastest joint's angular speed outside strokes"
  std::string unit;     // "mm", "%"
  std::vector<double> samples;  // one per frame (and finger, hand, ...) it applied to
  double limit = -1.0;          // the most allowed for `worst` (p95 if by_p95), < 0: no limit
  bool by_p95 = false;
  bool two_sided = false;  // the limit bounds |sample| (a signed distance: above or into)
  // Where the worst sample (the largest, or the largest |x| when two-sided) was: its music time
  // and what it was of ("right index on key 64"), so a figure over its limit can be looked at.
  double worst_at_s = 0.0;
  std::string worst_of;

  // Adds a sample taken at music time `t_s`; `of` names what it measured (may be empty).
  void add(double value, double t_s, const std::string& of = {});

  double percentile(double p) const;  // of the samples; 0 when there are none
  double worst() const { return percentile(1.0); }
  bool within_limit() const;

  std::size_t worst_index_ = 0;  // of samples; kept by add()
};

struct PoseReport {
  std::vector<PoseMeasure> measures;  // in the order they were first taken
  std::size_t frames = 0;
  const PoseMeasure* find(const std::string& name) const;
};

// Geometry the measures share.
namespace pose {
// World matrices of a placed model's nodes as posed.
void world_of(const PlacedModel& placed, std::vector<glm::mat4>& out);
double distance_to_line(const glm::vec3& p, const glm::vec3& on_line, const glm::vec3& direction);
double distance_to_segment(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b);
inline constexpr const char* kFingerNames[5] = {"thumb", "index", "middle", "ring", "little"};
// The fingertip pad's radius (content/generator/hand_rig.json: finger radius × tip ratio).
inline constexpr double kPadRadiusMm[5] = {
    1000.0 * kFingertipPadRadiusM[0], 1000.0 * kFingertipPadRadiusM[1],
    1000.0 * kFingertipPadRadiusM[2], 1000.0 * kFingertipPadRadiusM[3],
    1000.0 * kFingertipPadRadiusM[4]};
}  // namespace pose

class PoseChecker {
 public:
  // A model's finger joints: [one hand, the other][thumb .. little][joint from the knuckle out],
  // -1 where it has none (BodyNodes::fingers).
  using FingerNodes = std::array<std::array<std::array<int, 3>, 5>, 2>;

  // Measures the frames posed in `world` (a sampling context's, StageContext::world()).
  PoseChecker(ecs::World& world, PoseReport& report, const FingerJointLimits& limits);

  // The frame just posed: its music time and the step since the last one.
  void at_time(double t_s, double dt_s);
  double t_s() const { return t_s_; }
  double dt_s() const { return dt_s_; }
  const ecs::World& world() const { return world_; }
  // A performer's name, as the measures are named ("?" when it has none).
  std::string performer_name(ecs::Entity performer) const;
  // Every note entity of the stage (read once).
  const std::vector<std::pair<ecs::Entity, const components::Note*>>& notes() const {
    return notes_;
  }

  // The measure of that name (made, with its unit and limit, the first time).
  PoseMeasure& measure(const std::string& name, const char* unit, double limit = -1.0,
                       bool by_p95 = false);

  // World matrices of the models a family measures in this frame (filled by pose::world_of):
  // the instrument, the body, the hands. The shared measures below read them.
  std::vector<glm::mat4>& instrument_world() { return instrument_world_; }
  std::vector<glm::mat4>& body_world() { return body_world_; }
  std::vector<glm::mat4>& hand_world() { return hand_world_; }

  // The fastest-turning joints of a posed model since the last frame (deg/s), by their local
  // rotations: a one-frame snap of an arm or a finger shows here as an angular speed no player
  // has. Strokes are measured apart, as they are quicker than any other motion: outside strokes
  // (limit 1000), the finger joints (`fingers`, -1 where a model has none; 2500), which strike
  // keys and press valves, and, when given, the arm making a stroke (`stroke_arm`, e.g. the
  // slide arm while the slide moves; 2000), named "<who>: <stroke_name>".
  void joint_speeds(const std::string& who, const PlacedModel& placed, const FingerNodes& fingers,
                    const TwoBoneChain* stroke_arm = nullptr, std::string_view stroke_name = {});
  // How deep the deepest of `points` is inside the head's capsule (body_world()).
  void head_clearance(const std::string& who, int head, const std::vector<glm::vec3>& points);
  // How deep the deepest of `points` is inside the torso's capsule (hips to neck).
  void torso_clearance(const std::string& who, int hips, int neck,
                       const std::vector<glm::vec3>& points);
  // How deep the instrument's surface (instrument_world()) reaches into either arm's sleeve.
  void arms_clear_of_instrument(const std::string& who, const PlacedModel& instrument,
                                const BodyNodes& nodes);
  // How far the instrument (instrument_world()) passes through its music stand's desk.
  void instrument_clear_of_desk(const std::string& who, const PlacedModel& instrument,
                                const PlacedModel& stand);
  // The worst finger joint (index .. little) of a posed hand past its limits.
  void finger_limits(const std::string& who, const model::ModelAsset& asset,
                     const model::ModelPose& pose, const BodyNodes& nodes);

  // A family's own state across frames, by a key of its own (made empty the first time).
  template <class T>
  T& family_state(const std::string& key) {
    auto [it, added] = family_state_.try_emplace(key);
    if (added) it->second = T{};
    return std::any_cast<T&>(it->second);
  }

 private:
  // A stand model's desk panel in the desk node's frame (node -1: none), read once per model.
  struct DeskPanel {
    int node = -1;
    glm::vec3 lo{0.0f}, hi{0.0f};
  };
  const DeskPanel& desk_panel(const model::ModelAsset& asset);

  const ecs::World& world_;
  PoseReport& report_;
  FingerJointLimits limits_;
  std::vector<glm::mat4> instrument_world_, body_world_, hand_world_, stand_world_;
  std::vector<glm::vec3> local_points_;
  std::vector<std::pair<ecs::Entity, const components::Note*>> notes_;
  double t_s_ = 0.0;
  double dt_s_ = 1.0 / 30.0;
  std::map<const PlacedModel*, std::vector<glm::quat>> last_rotations_;
  std::vector<std::uint8_t> joint_kind_;
  std::map<const model::ModelAsset*, DeskPanel> desk_panels_;
  std::map<std::string, std::any> family_state_;
};

}  // namespace tutti::stage
