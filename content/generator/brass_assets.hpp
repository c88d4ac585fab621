// SPDX-License-Identifier: MIT
#pragma once
// trumpet.glb and trombone.glb: a B-flat trumpet with three piston nodes and a tenor trombone
// with a slide node, real dimensions (README.md). Held instruments: the root's origin is the
// mouthpiece rim (where the lips meet it), the player at +Z looking toward -Z, +Y up.

#include <tiny_gltf.h>

#include <tutti/generator/dimensions.hpp>

namespace tutti::content_generator {

tinygltf::Model build_trumpet(const TrumpetDimensions& dims = {});

// `max_extension_mm`: the slide's 7th position (brass_model::Instrument::slide_length_mm of
// content/instruments/trombone_tenor.json); must be below inner_slide_length_mm - 30.
tinygltf::Model build_trombone(double max_extension_mm, const TromboneDimensions& dims = {});

}  // namespace tutti::content_generator
