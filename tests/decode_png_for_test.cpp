// SPDX-License-Identifier: MIT
// stb_image's implementation for the PNG round-trip tests (third-party code, warnings off; link
// this file into a test program that needs decode_png_for_test).
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

#include <cstdint>
#include <vector>

// Decodes a PNG to RGBA8; empty on failure.
std::vector<std::uint8_t> decode_png_for_test(const std::vector<std::uint8_t>& png, int& width,
                                              int& height) {
  int channels = 0;
  stbi_uc* pixels = stbi_load_from_memory(png.data(), static_cast<int>(png.size()), &width, &height,
                                          &channels, 4);
  if (pixels == nullptr) return {};
  std::vector<std::uint8_t> out(pixels, pixels + std::size_t(width) * height * 4);
  stbi_image_free(pixels);
  return out;
}
