// SPDX-License-Identifier: MIT
// The only translation unit with stb_image's implementation, compiled with warnings off
// (third-party code; engine/model/CMakeLists.txt).
#include <tutti/model/gltf_images.hpp>

#include <cstring>
#include <memory>

#include <webp/decode.h>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO
#include <stb/stb_image.h>

namespace tutti::model::detail {

std::string sniff_image_type(std::span<const std::uint8_t> bytes) {
  static constexpr std::uint8_t kPng[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
  if (bytes.size() >= 8 && std::memcmp(bytes.data(), kPng, 8) == 0) return "image/png";
  if (bytes.size() >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF) {
    return "image/jpeg";
  }
  if (bytes.size() >= 12 && std::memcmp(bytes.data(), "RIFF", 4) == 0 &&
      std::memcmp(bytes.data() + 8, "WEBP", 4) == 0) {
    return "image/webp";
  }
  return "";
}

Status decode_image(Image& image, std::size_t& budget) {
  const std::span<const std::uint8_t> bytes(image.encoded);
  const std::string type = sniff_image_type(bytes);
  if (type.empty()) return Error{"not a PNG, JPEG or WebP image"};
  if (bytes.size() > static_cast<std::size_t>(INT32_MAX)) return Error{"image larger than 2 GiB"};
  const int size = static_cast<int>(bytes.size());
  int width = 0, height = 0;
  if (type == "image/webp") {
    if (!WebPGetInfo(bytes.data(), bytes.size(), &width, &height)) return Error{"broken WebP image"};
  } else {
    int channels = 0;
    if (!stbi_info_from_memory(bytes.data(), size, &width, &height, &channels)) {
      return Error{std::string("broken ") + (type == "image/png" ? "PNG" : "JPEG") + " image (" +
                   stbi_failure_reason() + ")"};
    }
  }
  if (width <= 0 || height <= 0 || static_cast<std::uint32_t>(width) > kMaxImageSide ||
      static_cast<std::uint32_t>(height) > kMaxImageSide) {
    return Error{"image of " + std::to_string(width) + " x " + std::to_string(height) +
                 " pixels (at most " + std::to_string(kMaxImageSide) + " per side)"};
  }
  const std::size_t pixel_bytes = std::size_t{4} * static_cast<std::size_t>(width) *
                                  static_cast<std::size_t>(height);
  if (pixel_bytes > budget) return Error{"images larger than 1 GiB of pixels in all, refused"};
  image.rgba.resize(pixel_bytes);
  if (type == "image/webp") {
    if (WebPDecodeRGBAInto(bytes.data(), bytes.size(), image.rgba.data(), image.rgba.size(),
                           width * 4) == nullptr) {
      image.rgba.clear();
      return Error{"broken WebP image"};
    }
  } else {
    int w = 0, h = 0, channels = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(bytes.data(), size, &w, &h, &channels, 4), stbi_image_free);
    if (!pixels || w != width || h != height) {
      image.rgba.clear();
      return Error{std::string("broken ") + (type == "image/png" ? "PNG" : "JPEG") + " image"};
    }
    std::memcpy(image.rgba.data(), pixels.get(), pixel_bytes);
  }
  image.width = static_cast<std::uint32_t>(width);
  image.height = static_cast<std::uint32_t>(height);
  if (image.mime_type.empty()) image.mime_type = type;
  budget -= pixel_bytes;
  return Status::success();
}

}  // namespace tutti::model::detail
