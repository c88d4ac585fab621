// SPDX-License-Identifier: MIT
#pragma once
// KHR_draco_mesh_compression: each compressed primitive decoded with Debian's libdraco into new
// buffers, and its accessors (which the file declares without data) pointed at them. Counts are
// checked against the accessors and the caps before anything is copied. Internal to tutti_model.

#include <tiny_gltf.h>

#include <tutti/core/result.hpp>

namespace tutti::model::detail {

Status decode_draco_primitives(tinygltf::Model& model);

}  // namespace tutti::model::detail
