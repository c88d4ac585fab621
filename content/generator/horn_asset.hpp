// SPDX-License-Identifier: MIT
#pragma once
// horn.glb: a double horn. The leadpipe runs from the mouthpiece forward and down to four rotary
// valves on the player's left (casings with rotor caps, rotor_1 .. rotor_4, that turn a quarter
// as their valve goes down); the left hand's levers (valve_1 .. valve_3, pads pressed along -Y)
// and the thumb's trigger (valve_4, pressed toward the instrument) beside them, the little
// finger's hook; the coils in front of the player's chest; the bell low on the player's right,
// pointing back, with the right palm's place inside it (grip_right). Frame as the other
// instruments: the mouthpiece rim at the origin, the player at +Z, their right +X, up +Y.

#include <tiny_gltf.h>

#include <tutti/generator/dimensions.hpp>

namespace tutti::content_generator {

tinygltf::Model build_horn(const HornDimensions& dims);

}  // namespace tutti::content_generator
