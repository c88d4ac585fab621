// SPDX-License-Identifier: MIT
#pragma once
// stage.glb: a wooden stage platform for the performers to stand on and cast shadows onto
// (README.md). Origin at the centre of the floor's top surface (y = 0), front edge toward +Z.

#include <tiny_gltf.h>

#include <tutti/generator/dimensions.hpp>

namespace tutti::content_generator {

tinygltf::Model build_stage(const StageDimensions& dims = {});

}  // namespace tutti::content_generator
