// stb_image_write's implementation, static to this translation unit (STB_IMAGE_WRITE_STATIC) so
// it can be linked beside engine/app's copy; compiled with warnings off (third-party code).
#include "render/png_writer.hpp"

#include <string>

#include "core/file_io.hpp"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#define STBI_WRITE_NO_STDIO
#include <stb/stb_image_write.h>

namespace tutti::render {
namespace {

void append(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(context);
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

std::vector<std::uint8_t> encode_png(std::span<const std::uint8_t> rgba, std::uint32_t width,
                                     std::uint32_t height) {
  std::vector<std::uint8_t> out;
  if (width == 0 || height == 0 || rgba.size() != std::size_t{width} * height * 4) return out;
  stbi_write_png_compression_level = 8;
  stbi_write_png_to_func(append, &out, static_cast<int>(width), static_cast<int>(height), 4,
                         rgba.data(), static_cast<int>(width * 4));
  return out;
}

Status write_png(const std::filesystem::path& path, std::span<const std::uint8_t> rgba,
                 std::uint32_t width, std::uint32_t height) {
  const std::vector<std::uint8_t> bytes = encode_png(rgba, width, height);
  if (bytes.empty()) {
    return Error{path.string() + ": cannot encode a " + std::to_string(width) + "x" +
                 std::to_string(height) + " image from " + std::to_string(rgba.size()) + " bytes"};
  }
  return write_file_atomically(path, std::string(bytes.begin(), bytes.end()));
}

}  // namespace tutti::render
