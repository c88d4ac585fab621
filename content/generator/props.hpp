// SPDX-License-Identifier: MIT
#pragma once
// The stage props: music_stand.glb and chair.glb. Simple shapes with real dimensions; every
// part is a named node (README.md lists them). Origins on the floor, +Y up, metres; the player
// sits or stands at +Z, facing -Z (the same convention as piano.glb).

#include <tiny_gltf.h>

#include <tutti/generator/dimensions.hpp>

namespace tutti::content_generator {

// Nodes: `music_stand` > `base`, `shaft`, `desk` (the desk's origin is its hinge at the top of
// the shaft; it leans back desk_lean_deg (20) degrees about its local X axis).
tinygltf::Model build_music_stand(const MusicStandDimensions& dims = {});

// Nodes: `chair` > `seat`, `leg_front_left`, `leg_front_right`, `leg_back_left`,
// `leg_back_right`, `backrest`. Seat top seat_top_mm (460) above the floor.
tinygltf::Model build_chair(const ChairDimensions& dims = {});

}  // namespace tutti::content_generator
