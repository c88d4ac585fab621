// SPDX-License-Identifier: MIT
#pragma once
// performer.glb: the skinned performer rig (README.md, "Performer"). An adult of about 1.75 m in
// a dark suit, standing in the A-pose, facing +Z (the audience), `_l` bones at -X; the root
// `performer` on the floor between the feet. Every bone's rest rotation is the identity (bones
// differ by translation only), so a turn about a bone's local X axis is a turn about the body's
// left-right axis. Attach points: `mouth` (on the lips, child of `head`), `grip_l` / `grip_r`
// (palm centres, children of `hand_l` / `hand_r`, whose origins are the wrists). The face mesh
// carries the morph targets `tension` (brass embouchure) and `open` (breath), deltas only within
// 50 mm of `mouth`.

#include <tiny_gltf.h>

#include <tutti/generator/dimensions.hpp>
#include <tutti/generator/hand_rig.hpp>

namespace tutti::content_generator {

// `right_hand` / `left_hand`: the finger layout (roots, phalanx lengths) and flesh sizes of
// load_hand_rig; the performer's fingers hang straight down the arm with a relaxed curl.
tinygltf::Model build_performer(const PerformerDimensions& dims, const HandRig& right_hand,
                                const HandRig& left_hand);

}  // namespace tutti::content_generator
