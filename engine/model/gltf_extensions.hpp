// SPDX-License-Identifier: MIT
#pragma once
// glTF as real pipelines write it, made plain glTF around tinygltf (which reads none of this):
//
//  - extensionsRequired: a file that needs an extension tutti does not read is refused, naming
//    it. Geometry extensions are decoded (below); appearance-only ones (texture transforms and
//    formats, KHR_materials_*, lights) are accepted: the geometry is whole, and tutti draws the
//    material's factors.
//  - EXT_meshopt_compression (gltfpack): before tinygltf, each compressed buffer view is pointed
//    at its compressed bytes and the "fallback" buffer (no data) gets a 3-byte stand-in; after,
//    the views are decoded with meshoptimizer's decoders and filters into new buffers.
//  - KHR_draco_mesh_compression: decoded with libdraco (gltf_draco.hpp).
//  - Sparse accessors: written out dense into new buffers.
//
// Every count, stride and range is checked before anything is decoded or allocated; the
// decoders only ever see input they accept. Internal to tutti_model.

#include <tiny_gltf.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <tutti/core/result.hpp>

namespace tutti::model::detail {

// One EXT_meshopt_compression buffer view, as the file declares it.
struct MeshoptView {
  std::size_t view = 0;
  std::size_t count = 0;
  std::size_t stride = 0;
  std::string mode;    // ATTRIBUTES, TRIANGLES, INDICES
  std::string filter;  // NONE, OCTAHEDRAL, QUATERNION, EXPONENTIAL
};

struct PreparedDocument {
  bool rewritten = false;          // `bytes` replaces the input
  std::vector<std::uint8_t> bytes;
  std::vector<MeshoptView> meshopt;
};

// `json` is the document's JSON (for a .glb its JSON chunk, already checked and scanned).
Result<PreparedDocument> prepare_extensions(std::span<const std::uint8_t> bytes, bool binary,
                                            std::span<const std::uint8_t> json);

// After tinygltf: meshopt views decoded, sparse accessors made dense.
Status resolve_extensions(tinygltf::Model& model, const PreparedDocument& prepared);

}  // namespace tutti::model::detail
