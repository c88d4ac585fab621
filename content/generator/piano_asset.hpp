// SPDX-License-Identifier: MIT
#pragma once
// piano.glb: an upright piano whose 88 keys are separate nodes, built from the keyboard geometry
// in content/piano/keyboard.json (tutti::piano_model::Keyboard). See README.md for the node names
// and axes.
//
// Frames. The keyboard frame (tutti's piano code) has x along the keys (mm, 0 at the left edge
// of the lowest key), y into the keys (away from the player), z up. glTF has +Y up and metres,
// so a keyboard point (x, y, z) mm is the glTF point (x, z, -y) / 1000 in the `keyboard` node.
// The player sits at +Z looking toward -Z.

#include <array>
#include <string>

#include <tiny_gltf.h>

#include <tutti/generator/dimensions.hpp>
#include <tutti/piano_model/keyboard.hpp>
#include <tutti/piano_model/keyboard_instruments.hpp>

namespace tutti::content_generator {

// The model (nodes `piano` > `keyboard` > `key_21`..`key_108`, `piano` > `case`).
tinygltf::Model build_piano(const piano_model::Keyboard& keyboard, const PianoDimensions& dims = {},
                            const std::array<double, 3>& case_color = {0.01, 0.01, 0.012},
                            const std::string& root_name = "piano",
                            const piano_model::Pedalboard* pedalboard = nullptr);
// Key and case sizes come from `dims` (content/generator/dimensions.json); the key x positions
// and the white-key pitch from `keyboard`; the case's colour (linear RGB) from `case_color`; the
// root node is `root_name` (the instrument's id); an organ's `pedalboard` adds its pedals
// (`pedalboard` > `pedal_36`.., piano_model/pedal_geometry.hpp).
// The keyboard family's other instruments (content/piano/instruments.json) are the same build
// with their compass and case: keyboard_<id>.glb.

}  // namespace tutti::content_generator
