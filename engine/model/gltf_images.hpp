// SPDX-License-Identifier: MIT
#pragma once
// Decoding a glTF image's bytes (PNG and JPEG with stb_image, WebP with libwebp — Debian's
// libstb-dev and libwebp-dev) to 8-bit RGBA, refusing what a hostile file could use to exhaust
// memory: at most 8192 × 8192 pixels per image, 1 GiB of pixels per model. The format is read
// from the bytes' signature, not the file's claim.
//
// Internal to tutti_model. Errors are reasons without the file name.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include <tutti/core/result.hpp>
#include <tutti/model/model_asset.hpp>

namespace tutti::model::detail {

inline constexpr std::uint32_t kMaxImageSide = 8192;
inline constexpr std::size_t kMaxPixelBytesPerModel = std::size_t{1} << 30;

// "image/png", "image/jpeg", "image/webp" by signature; "" when none of them.
std::string sniff_image_type(std::span<const std::uint8_t> bytes);

// Fills image.width, height and rgba from image.encoded; `budget` is what is left of the
// model's pixel bytes and shrinks by this image's.
Status decode_image(Image& image, std::size_t& budget);

}  // namespace tutti::model::detail
