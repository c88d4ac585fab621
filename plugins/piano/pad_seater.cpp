// SPDX-License-Identifier: MIT
#include <tutti/piano/pad_seater.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include <tutti/stage/fingertip_reach.hpp>

namespace tutti::piano {

double key_surface_z_mm(const PianoRig& rig, int key, double angle, double y_mm) {
  const auto k = static_cast<std::size_t>(key);
  const double rail_y = rig.key_back_y_mm[k] + 1000.0 * static_cast<double>(rig.key_pivot_behind_m[k]);
  return rig.key_top_z_mm[k] - (rail_y - y_mm) * std::tan(angle);
}

PadSeater::PadSeater(PianoRig& rig, stage::PlacedModel& hand_model, const components::Finger& finger,
                     std::size_t side, std::size_t f, double key_angle)
    : rig_(rig), hand_model_(hand_model), finger_(finger), side_(side), f_(f), angle_(key_angle),
      mirror_(side == 0 ? 1.0f : -1.0f) {}

void PadSeater::pose(const PadSeat& seat) {
  const auto& bones = rig_.finger_bones[side_][f_];
  const double stroke = (f_ == 0 ? finger_.abduction_rad : finger_.mcp_flexion_rad) + seat.stroke;
  hand_model_.pose.local[static_cast<std::size_t>(bones[0])].rotation =
      glm::angleAxis(-mirror_ * static_cast<float>(finger_.spread_rad + seat.spread), glm::vec3(0, 1, 0)) *
      glm::angleAxis(static_cast<float>(stroke), glm::vec3(-1, 0, 0));
  if (bones[1] >= 0) {
    const double curl = (f_ == 0 ? finger_.mcp_flexion_rad : finger_.pip_flexion_rad) + seat.curl;
    hand_model_.pose.local[static_cast<std::size_t>(bones[1])].rotation =
        glm::angleAxis(static_cast<float>(curl), glm::vec3(-1, 0, 0));
  }
}

PadOnKey PadSeater::measure(const PadSeat& seat) {
  pose(seat);
  const model::ModelAsset& asset = *hand_model_.asset;
  std::vector<glm::mat4>& hand_world = rig_.scratch_world;
  hand_world.resize(asset.nodes.size());
  model::compute_world_matrices(asset, hand_model_.pose, hand_model_.root, hand_world);
  const auto in_keyboard = [&](int node) {
    return glm::vec3(rig_.world_to_keyboard * hand_world[static_cast<std::size_t>(node)][3]);
  };
  const auto& bones = rig_.finger_bones[side_][f_];
  // glTF keyboard frame (m): x, y up, -z into the keys.
  const glm::vec3 tip_at = in_keyboard(rig_.finger_tips[side_][f_]);
  const glm::vec3 last_joint = in_keyboard(bones[2]);
  const glm::vec3 root = in_keyboard(bones[0]);
  const glm::vec3 along = glm::normalize(tip_at - last_joint);
  const double radius = static_cast<double>(stage::kFingertipPadRadiusM[f_]) * 1000.0;
  const glm::vec3 centre = tip_at - static_cast<float>(radius / 1000.0) * along;
  const auto key = static_cast<std::size_t>(finger_.key);
  PadOnKey pad;
  pad.depth_mm = -1000.0 * static_cast<double>(centre.z);
  pad.height_mm = 1000.0 * static_cast<double>(centre.y) - radius -
                  key_surface_z_mm(rig_, finger_.key, angle_, pad.depth_mm);
  pad.side_mm = 1000.0 * static_cast<double>(centre.x) - rig_.key_centre_x_mm[key];
  pad.arm_mm = 1000.0 * static_cast<double>(glm::length(glm::vec2(centre.x - root.x, centre.z - root.z)));
  return pad;
}

glm::dvec2 PadSeater::off_key_mm(const PadOnKey& pad) const {
  const auto key = static_cast<std::size_t>(finger_.key);
  const double half_width = std::max(0.0, rig_.key_half_width_mm[key] - kPadInsideKeyMm);
  const double back = rig_.key_back_y_mm[key] - kPadInsideKeyMm;
  const double front = std::min(back, rig_.key_back_y_mm[key] - rig_.key_length_mm[key] + kPadInsideKeyMm);
  return {pad.side_mm - std::clamp(pad.side_mm, -half_width, half_width),
          pad.depth_mm - std::clamp(pad.depth_mm, front, back)};
}

PadSeat PadSeater::centre(PadSeat seat) {
  for (int round = 0; round < 4; ++round) {
    const PadOnKey pad = measure(seat);
    if (std::abs(pad.height_mm) < 0.05 && std::abs(pad.side_mm) < 0.2) break;
    if (pad.arm_mm < 10.0) break;
    seat.stroke += pad.height_mm / pad.arm_mm;
    // A larger spread carries the right hand's pads toward +x, the left's toward -x.
    seat.spread = std::clamp(seat.spread - static_cast<double>(mirror_) * pad.side_mm / pad.arm_mm,
                             -kMostSpreadCorrectionRad, kMostSpreadCorrectionRad);
  }
  pose(seat);
  return seat;
}

namespace {

PadSeat limited_onto_key(PadSeat s) {
  s.spread = std::clamp(s.spread, -kMostSpreadOntoKeyRad, kMostSpreadOntoKeyRad);
  s.curl = std::clamp(s.curl, -kMostCurlOntoKeyRad, kMostCurlOntoKeyRad);
  return s;
}

PadSeat turned(PadSeat s, int joint, double by) {
  (joint == 0 ? s.stroke : joint == 1 ? s.spread : s.curl) += by;
  return s;
}

constexpr double kStepRad = 0.01;
// Damped least squares: a small damping keeps a joint that barely moves the pad still.
constexpr double kDampingMm2 = 25.0;

}  // namespace

PadSeat PadSeater::onto_key(PadSeat seat) {
  const auto residual = [&](const PadSeat& s) {
    const PadOnKey pad = measure(s);
    const glm::dvec2 off = off_key_mm(pad);
    return glm::dvec3(pad.height_mm, off.x, off.y);
  };
  for (int round = 0; round < 6; ++round) {
    const glm::dvec3 r = residual(seat);
    if (std::abs(r.x) < 0.05 && std::abs(r.y) < 0.05 && std::abs(r.z) < 0.05) break;
    glm::dmat3 jacobian(0.0);  // columns: d residual / d (stroke, spread, curl), mm per rad
    for (int j = 0; j < 3; ++j) jacobian[j] = (residual(turned(seat, j, kStepRad)) - r) / kStepRad;
    const glm::dmat3 normal = glm::transpose(jacobian) * jacobian + glm::dmat3(kDampingMm2);
    const glm::dvec3 step = -(glm::inverse(normal) * (glm::transpose(jacobian) * r));
    seat = limited_onto_key({seat.stroke + step.x, seat.spread + step.y, seat.curl + step.z});
  }
  pose(seat);
  return seat;
}

PadSeat PadSeater::clear_of(PadSeat seat, std::span<const HandCapsule> other, double margin_mm) {
  // The pad's height, its centre off the outline across and along, then each of the finger's
  // (at most three) bones' overlap with each of the other hand's (at most sixteen) capsules.
  struct Residual {
    std::array<double, 3 + 3 * 16> mm{};
    std::size_t size = 0;
    bool clear() const {
      return std::all_of(mm.begin(), mm.begin() + static_cast<std::ptrdiff_t>(size),
                         [](double x) { return std::abs(x) < 0.05; });
    }
    bool apart() const {
      return std::all_of(mm.begin() + 3, mm.begin() + static_cast<std::ptrdiff_t>(size),
                         [](double x) { return x < 0.05; });
    }
  };
  // The pad stays on its key: its place on the key weighs far more than the other hand's room.
  constexpr double kOnKeyWeight = 30.0;
  const FingerChains chains = finger_chains(rig_, side_);
  std::vector<HandCapsule>& own = rig_.scratch_hand_capsules[side_];
  const auto residual = [&](const PadSeat& s, Residual& out) {
    const PadOnKey pad = measure(s);
    const glm::dvec2 off = off_key_mm(pad);
    out.mm[0] = kOnKeyWeight * pad.height_mm;
    out.mm[1] = kOnKeyWeight * off.x;
    out.mm[2] = kOnKeyWeight * off.y;
    out.size = 3;
    collect_hand_capsules(chains, rig_.scratch_world, own);
    for (const HandCapsule& bone : own) {
      if (bone.finger != static_cast<int>(f_)) continue;
      for (const HandCapsule& capsule : other) {
        if (out.size == out.mm.size()) return;
        out.mm[out.size++] = std::max(0.0, 1000.0 * overlap_m(bone, capsule) + margin_mm);
      }
    }
  };
  Residual r;
  residual(seat, r);
  if (r.apart()) return seat;
  // Each step is kept only while it lowers the sum of squares with the pad still on its key: the
  // overlaps are not smooth, and a step past their corner can undo the seating.
  const auto cost = [](const Residual& x) {
    double sum = 0.0;
    for (std::size_t i = 0; i < x.size; ++i) sum += x.mm[i] * x.mm[i];
    return sum;
  };
  const auto on_key = [&](const Residual& x) {
    return std::abs(x.mm[0]) <= kOnKeyWeight * 0.1 && std::abs(x.mm[1]) <= kOnKeyWeight * 0.05 &&
           std::abs(x.mm[2]) <= kOnKeyWeight * 0.05;
  };
  PadSeat best = seat;
  double best_cost = cost(r);
  std::array<Residual, 3> moved;
  Residual tried;
  double damping = kDampingMm2;
  for (int round = 0; round < 10; ++round) {
    for (int j = 0; j < 3; ++j) residual(turned(best, j, kStepRad), moved[static_cast<std::size_t>(j)]);
    glm::dmat3 normal(damping);
    glm::dvec3 gradient(0.0);
    for (std::size_t i = 0; i < r.size; ++i) {
      const glm::dvec3 row((moved[0].mm[i] - r.mm[i]) / kStepRad, (moved[1].mm[i] - r.mm[i]) / kStepRad,
                           (moved[2].mm[i] - r.mm[i]) / kStepRad);
      normal += glm::outerProduct(row, row);
      gradient += row * r.mm[i];
    }
    const glm::dvec3 step = -(glm::inverse(normal) * gradient);
    const PadSeat next = limited_onto_key({best.stroke + step.x, best.spread + step.y, best.curl + step.z});
    residual(next, tried);
    const double next_cost = cost(tried);
    if (next_cost < best_cost && on_key(tried)) {
      best = next;
      best_cost = next_cost;
      r = tried;
      damping = std::max(kDampingMm2, damping * 0.5);
      if (r.apart()) break;
    } else {
      damping *= 4.0;  // a shorter step next time, from the same seat
    }
  }
  pose(best);
  return best;
}

}  // namespace tutti::piano
