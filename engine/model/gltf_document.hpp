// SPDX-License-Identifier: MIT
#pragma once
// Parsing a glTF file's container and JSON with tinygltf, hardened against hostile input before
// tinygltf sees it: the .glb chunk layout is checked here (tinygltf 2.7 trusts the BIN chunk's
// length by 8 bytes too many), the JSON is pre-scanned by a SAX pass (nesting depth, value
// count: tinygltf converts `extras` recursively and allocates far more per value than the
// text), images are kept as their encoded bytes (tinygltf::Image::image, width -1), and external
// buffers and images are read only from the folder given, through the project's capped file reads.
//
// Internal to tutti_model: the loader turns the tinygltf::Model into a ModelAsset.

#include <tiny_gltf.h>

#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <string>

#include <tutti/core/result.hpp>

namespace tutti::model::detail {

inline constexpr std::size_t kMaxJsonDepth = 64;
inline constexpr std::size_t kMaxJsonValues = 2'000'000;
// A model file (and each external buffer) is read up to this size.
inline constexpr std::size_t kMaxModelFileBytes = std::size_t{256} << 20;
// The most elements a decoded (compressed) view or primitive may hold.
inline constexpr std::size_t kMaxDecodedCount = std::size_t{1} << 24;

// The little-endian 32-bit word at `offset` (the caller checks the bounds): the host is
// little-endian (x86-64, arm64).
inline std::uint32_t read_u32(std::span<const std::uint8_t> bytes, std::size_t offset) {
  std::uint32_t value = 0;
  std::memcpy(&value, bytes.data() + offset, 4);
  return value;
}

// `base_dir`: where external buffers of a .gltf are looked for; nullopt = external files are
// refused (bytes from memory, the fuzzer). The error is a reason without the file name.
Result<tinygltf::Model> parse_gltf(std::span<const std::uint8_t> bytes,
                                   const std::optional<std::string>& base_dir);

// tinygltf's multi-line error and warning text as one short printable line.
std::string fold_message(const std::string& text);

}  // namespace tutti::model::detail
