// SPDX-License-Identifier: MIT
#pragma once
// A pressing finger's pad seated on its key. The planned chain is a planar model of the finger;
// the hand model's joints are not quite it (the thumb turns about a tilted axis). Where a finger
// touches its key, its joints are corrected on the posed model until the pad's lowest point lies
// on the key's top, inside the key's outline, and (hands_apart.hpp) clear of the other hand.

#include <array>
#include <cstddef>
#include <span>

#include <glm/glm.hpp>

#include <tutti/components/finger.hpp>
#include <tutti/piano/hand_capsules.hpp>
#include <tutti/piano/piano_components.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::piano {

// How far the seating may turn a finger's joints past the plan. Centring a pad on its key's
// centre line takes at most kMostSpreadCorrectionRad: a key further away is the plan's to reach
// (the hand's place, the finger's range), not a finger's to twist toward. Only a pad that would
// press beside or in front of its key's top (the thumb's tilted joint carries it there on a black
// key), or one in the other hand's way, turns further, and only as far as the key's outline less
// kPadInsideKeyMm.
inline constexpr double kMostSpreadCorrectionRad = 0.1;
inline constexpr double kMostSpreadOntoKeyRad = 0.35;
inline constexpr double kMostCurlOntoKeyRad = 0.35;
inline constexpr double kPadInsideKeyMm = 1.0;

// A seated finger's turn past its planned pose: its first joint's stroke (about -X) and spread
// (about the vertical) and its next joint's flexion (curl).
struct PadSeat {
  double stroke = 0.0;
  double spread = 0.0;
  double curl = 0.0;
};

// The pad of a pressing finger against its key (keyboard frame, mm): its lowest point's height
// over the key's top there, its centre's distance across from the key's centre line, and its
// centre's depth into the keys.
struct PadOnKey {
  double height_mm = 0.0;
  double side_mm = 0.0;
  double depth_mm = 0.0;
  double arm_mm = 0.0;  // the pad's horizontal distance from the finger's first joint
};

// The pressing fingers of both hands as seated: [side][finger] whether the finger was seated on
// its key, its turn past the plan, and its key's angle.
struct SeatedFingers {
  std::array<std::array<bool, 5>, 2> on_key{};
  std::array<std::array<PadSeat, 5>, 2> seat{};
  std::array<std::array<double, 5>, 2> key_angle{};
};

// The key's top surface height (keyboard frame, mm) at depth y_mm, the key turned `angle` about
// its rail.
double key_surface_z_mm(const PianoRig& rig, int key, double angle, double y_mm);

// Finger `f` of hand `side` (0 right, 1 left) of `hand_model`, pressing `finger.key` turned down
// by `key_angle` (rad). Posing writes the finger's first two bones' rotations; measuring poses
// and runs forward kinematics into rig.scratch_world.
class PadSeater {
 public:
  PadSeater(PianoRig& rig, stage::PlacedModel& hand_model, const components::Finger& finger,
            std::size_t side, std::size_t f, double key_angle);

  void pose(const PadSeat& seat);
  PadOnKey measure(const PadSeat& seat);

  // How far the pad's centre lies outside its key's top less kPadInsideKeyMm: across, and in
  // front of (negative) or behind (positive) it. 0, 0 on it.
  glm::dvec2 off_key_mm(const PadOnKey& pad) const;

  // The pad's lowest point onto the key's top, its centre as near the key's centre line as
  // kMostSpreadCorrectionRad allows: the stroke corrects the height on an arm as long as the
  // pad's horizontal distance from the joint, the spread sideways on the same arm.
  PadSeat centre(PadSeat seat);

  // A pad centred as far as allowed but still off its key's top: the stroke, spread and curl
  // together (Gauss-Newton on measured differences) put it on the top's edge less the margin,
  // its lowest point on the surface.
  PadSeat onto_key(PadSeat seat);

  // A seated finger (turned `seat`) whose bones reach into `other` (the other hand's capsules)
  // less `margin_mm`: the stroke, spread and curl together move the pad along its key's top, away
  // from the other hand, its lowest point kept on the surface and its centre inside the outline.
  PadSeat clear_of(PadSeat seat, std::span<const HandCapsule> other, double margin_mm);

 private:
  PianoRig& rig_;
  stage::PlacedModel& hand_model_;
  const components::Finger& finger_;
  std::size_t side_;
  std::size_t f_;
  double angle_;
  float mirror_;
};

}  // namespace tutti::piano
