// SPDX-License-Identifier: MIT
#include <tutti/piano/hands_apart.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <utility>

#include <glm/gtc/quaternion.hpp>

#include <tutti/components/finger.hpp>

namespace tutti::piano {
namespace {

using stage::PlacedModel;

void pose_world(const PlacedModel& model, std::vector<glm::mat4>& world) {
  world.resize(model.asset->nodes.size());
  model::compute_world_matrices(*model.asset, model.pose, model.root, world);
}

// A finger's turn away from its planned pose at its first joint: aside (about the vertical,
// > 0 toward the little finger's side) and its stroke (about -X, < 0 lifts the tip).
struct Yield {
  double spread = 0.0;
  double stroke = 0.0;
};

class FingerYielder {
 public:
  FingerYielder(PianoRig& rig, PlacedModel& model, const components::Finger& finger, std::size_t side,
                std::size_t f, std::span<const HandCapsule> other)
      : rig_(rig), model_(model), finger_(finger), side_(side), f_(f), other_(other),
        mirror_(side == 0 ? 1.0f : -1.0f) {}

  void pose(const Yield& y) {
    const double stroke = (f_ == 0 ? finger_.abduction_rad : finger_.mcp_flexion_rad) + y.stroke;
    model_.pose.local[static_cast<std::size_t>(rig_.finger_bones[side_][f_][0])].rotation =
        glm::angleAxis(-mirror_ * static_cast<float>(finger_.spread_rad + y.spread), glm::vec3(0, 1, 0)) *
        glm::angleAxis(static_cast<float>(stroke), glm::vec3(-1, 0, 0));
  }

  // At most three bones against a hand's sixteen capsules: fixed, so posing allocates nothing.
  struct Overlaps {
    std::array<double, 3 * 16> mm{};
    std::size_t size = 0;
  };

  // Each of the finger's bones' overlap with each of the other hand's capsules, plus the margin
  // (mm; 0 where clear), posed with `y`.
  void overlaps(const Yield& y, Overlaps& out) {
    pose(y);
    std::vector<glm::mat4>& world = rig_.scratch_hand_world[side_];
    pose_world(model_, world);
    std::vector<HandCapsule>& own = rig_.scratch_hand_capsules[side_];
    collect_hand_capsules(finger_chains(rig_, side_), world, own);
    out.size = 0;
    for (const HandCapsule& bone : own) {
      if (bone.finger != static_cast<int>(f_)) continue;
      for (const HandCapsule& capsule : other_) {
        if (out.size == out.mm.size()) return;
        out.mm[out.size++] = std::max(0.0, 1000.0 * overlap_m(bone, capsule) + kApartMarginMm);
      }
    }
  }

  static bool clear(const Overlaps& r) {
    return std::all_of(r.mm.begin(), r.mm.begin() + static_cast<std::ptrdiff_t>(r.size),
                       [](double x) { return x < 0.05; });
  }

  // Turns the finger clear of the other hand if it is in it; leaves it posed either way.
  void yield() {
    Yield y;
    overlaps(y, r_);
    if (clear(r_)) return;
    const auto limited = [](Yield v) {
      v.spread = std::clamp(v.spread, -kMostYieldSpreadRad, kMostYieldSpreadRad);
      v.stroke = std::clamp(v.stroke, -kMostYieldLiftRad, 0.0);
      return v;
    };
    constexpr double kStepRad = 0.01;
    for (int round = 0; round < 8; ++round) {
      // Columns: d overlap / d (spread, stroke), mm per rad. The stroke's is taken upward.
      Yield aside = y;
      aside.spread += kStepRad;
      overlaps(aside, column_[0]);
      Yield up = y;
      up.stroke -= kStepRad;
      overlaps(up, column_[1]);
      glm::dmat2 normal(0.0);
      glm::dvec2 gradient(0.0);
      for (std::size_t i = 0; i < r_.size; ++i) {
        const glm::dvec2 j((column_[0].mm[i] - r_.mm[i]) / kStepRad,
                           (r_.mm[i] - column_[1].mm[i]) / kStepRad);
        normal += glm::outerProduct(j, j);
        gradient += j * r_.mm[i];
      }
      // Damped least squares: a small damping keeps a joint that barely moves the bones still.
      normal += glm::dmat2(25.0);
      const glm::dvec2 step = -(glm::inverse(normal) * gradient);
      y = limited({y.spread + step.x, y.stroke + step.y});
      overlaps(y, r_);
      if (clear(r_)) break;
    }
    pose(y);
  }

 private:
  PianoRig& rig_;
  PlacedModel& model_;
  const components::Finger& finger_;
  std::size_t side_;
  std::size_t f_;
  std::span<const HandCapsule> other_;
  float mirror_;
  Overlaps r_;
  std::array<Overlaps, 2> column_;
};

// Whether finger f's bones in `own` are clear of every capsule in `other` by the margin, as
// FingerYielder counts clear: the test that spares a finger in no one's way its searches.
bool finger_clear(std::span<const HandCapsule> own, std::size_t f,
                  std::span<const HandCapsule> other) {
  for (const HandCapsule& bone : own) {
    if (bone.finger != static_cast<int>(f)) continue;
    for (const HandCapsule& capsule : other) {
      if (1000.0 * overlap_m(bone, capsule) + kApartMarginMm >= 0.05) return false;
    }
  }
  return true;
}

// Whether two hands' capsules lie further apart than the margin along some axis: then no
// finger of one can reach the other.
bool hands_far_apart(std::span<const HandCapsule> one, std::span<const HandCapsule> other) {
  if (one.empty() || other.empty()) return true;
  const auto bounds = [](std::span<const HandCapsule> capsules) {
    glm::vec3 lo(std::numeric_limits<float>::max());
    glm::vec3 hi(std::numeric_limits<float>::lowest());
    for (const HandCapsule& c : capsules) {
      lo = glm::min(lo, glm::min(c.a, c.b) - glm::vec3(c.radius));
      hi = glm::max(hi, glm::max(c.a, c.b) + glm::vec3(c.radius));
    }
    return std::pair{lo, hi};
  };
  const auto [lo1, hi1] = bounds(one);
  const auto [lo2, hi2] = bounds(other);
  const auto margin = static_cast<float>(kApartMarginMm / 1000.0);
  for (int axis = 0; axis < 3; ++axis) {
    if (lo1[axis] > hi2[axis] + margin || lo2[axis] > hi1[axis] + margin) return true;
  }
  return false;
}

void collect_posed_capsules(PianoRig& rig, const PlacedModel& model, std::size_t side) {
  pose_world(model, rig.scratch_hand_world[side]);
  collect_hand_capsules(finger_chains(rig, side), rig.scratch_hand_world[side],
                        rig.scratch_hand_capsules[side]);
}

}  // namespace

void keep_hands_apart(const ecs::World& world, PianoRig& rig,
                      const std::array<PlacedModel*, 2>& hand_models, const SeatedFingers& seated) {
  if (hand_models[0] == nullptr || hand_models[1] == nullptr || hand_models[0]->asset == nullptr ||
      hand_models[1]->asset == nullptr) {
    return;
  }
  // Most frames the hands are apart: two forward passes tell, and nothing else is done.
  for (std::size_t side = 0; side < 2; ++side) collect_posed_capsules(rig, *hand_models[side], side);
  if (hands_far_apart(rig.scratch_hand_capsules[0], rig.scratch_hand_capsules[1])) return;
  // Free fingers first, then pressing ones where that was not enough.
  for (const bool pressing : {false, true}) {
    for (std::size_t side = 0; side < 2; ++side) {
      const std::size_t other = 1 - side;
      // Both hands as they are now. A finger's search below poses only that finger, so the
      // other fingers' capsules in scratch_hand_capsules[side] stay true for them.
      collect_posed_capsules(rig, *hand_models[other], other);
      collect_posed_capsules(rig, *hand_models[side], side);
      for (std::size_t f = 0; f < 5; ++f) {
        const auto* finger = world.try_get<components::Finger>(rig.fingers[side][f]);
        if (finger == nullptr || rig.finger_bones[side][f][0] < 0) continue;
        if (finger_clear(rig.scratch_hand_capsules[side], f, rig.scratch_hand_capsules[other])) {
          continue;
        }
        if (!pressing && finger->key < 0) {
          FingerYielder(rig, *hand_models[side], *finger, side, f, rig.scratch_hand_capsules[other])
              .yield();
        } else if (pressing && finger->key >= 0 && seated.on_key[side][f]) {
          PadSeater(rig, *hand_models[side], *finger, side, f, seated.key_angle[side][f])
              .clear_of(seated.seat[side][f], rig.scratch_hand_capsules[other], kApartMarginMm);
        }
      }
    }
  }
}

}  // namespace tutti::piano
