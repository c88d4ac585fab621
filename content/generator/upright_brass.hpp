// SPDX-License-Identifier: MIT
#pragma once
// euphonium.glb and tuba.glb: upright valved instruments, four top-action piston nodes
// (valve_1 .. valve_4, button tops at their origins, pressed along -Y) in a row on the player's
// right, the bell branch on their left with the bell up. Like the held instruments
// (brass_assets.hpp) the root's origin is the mouthpiece rim, the player at +Z, +Y up; grip_left
// on the bell branch, thumb_rest on the casings for the right thumb.

#include <string>

#include <tiny_gltf.h>

#include <tutti/generator/dimensions.hpp>

namespace tutti::content_generator {

tinygltf::Model build_upright(const std::string& name, const UprightDimensions& dims);

}  // namespace tutti::content_generator
