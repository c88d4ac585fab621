// The only translation unit with stb_image_write's implementation (compiled with warnings off:
// it is third-party code). PNG output is deterministic: fixed compression level, no timestamps.
#include <cstdint>
#include <vector>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#include <stb/stb_image_write.h>

#include "app/piano_roll_plot.hpp"
#include "core/file_io.hpp"

namespace tutti::app {
namespace {

void append(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(context);
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

std::vector<std::uint8_t> encode_png(const PlotImage& image) {
  std::vector<std::uint8_t> out;
  if (image.width <= 0 || image.height <= 0) return out;
  stbi_write_png_compression_level = 8;
  stbi_write_png_to_func(append, &out, image.width, image.height, 3, image.rgb.data(),
                         image.width * 3);
  return out;
}

Status write_png(const std::filesystem::path& path, const PlotImage& image) {
  const std::vector<std::uint8_t> bytes = encode_png(image);
  if (bytes.empty()) return Error{path.string() + ": nothing to plot"};
  return write_file_atomically(path, std::string(bytes.begin(), bytes.end()));
}

}  // namespace tutti::app
