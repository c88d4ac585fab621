// SPDX-License-Identifier: MIT
#pragma once
// Writing the default assets: the models from piano_asset.hpp and props.hpp serialised as glTF
// binary (.glb). Errors are one line naming the file and the reason.

#include <tiny_gltf.h>

#include <filesystem>
#include <string>
#include <vector>

#include <tutti/core/result.hpp>

namespace tutti::content_generator {

// The .glb bytes of `model` (one binary chunk; deterministic).
Result<std::string> to_glb(const tinygltf::Model& model);

// Writes `model` to `path` atomically.
Status write_glb(const tinygltf::Model& model, const std::filesystem::path& path);

// The file names generate_assets writes, in order.
std::vector<std::string> asset_file_names();

// Builds every asset and writes it into `out_dir` (created if missing). Reads
// `content_dir`/piano/keyboard.json and `content_dir`/generator/dimensions.json; a missing or
// invalid file is an Error naming it (and the JSON path), and nothing is written.
Status generate_assets(const std::filesystem::path& content_dir,
                       const std::filesystem::path& out_dir);

}  // namespace tutti::content_generator
