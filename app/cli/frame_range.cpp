// SPDX-License-Identifier: MIT
#include <tutti/cli/frame_range.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace tutti::cli {
namespace {

Result<double> parse_number(const std::string& text, const std::string& what) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value)) {
    return Error{what + " \"" + text + "\" is not a number"};
  }
  return value;
}

struct Sides {
  std::string a, b;
};

Result<Sides> split(const std::string& text, const std::string& option) {
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos || text.find(':', colon + 1) != std::string::npos) {
    return Error{option + " \"" + text + "\": expected A:B"};
  }
  return Sides{text.substr(0, colon), text.substr(colon + 1)};
}

}  // namespace

std::int64_t frame_count(double start_s, double end_s, int fps) {
  if (!(end_s > start_s) || fps <= 0) return 0;
  return static_cast<std::int64_t>(std::ceil((end_s - start_s) * fps - 1e-9));
}

Result<FrameRange> parse_frame_range(const std::string& text, std::int64_t total) {
  auto sides = split(text, "--frames");
  if (!sides) return sides.error();
  FrameRange range{0, total};
  for (int side = 0; side < 2; ++side) {
    const std::string& s = side == 0 ? sides->a : sides->b;
    if (s.empty()) continue;
    auto value = parse_number(s, "--frames");
    if (!value) return value.error();
    if (*value != std::floor(*value) || *value < 0) {
      return Error{"--frames \"" + text + "\": frame numbers are whole numbers >= 0"};
    }
    (side == 0 ? range.first : range.end) = static_cast<std::int64_t>(*value);
  }
  if (range.end > total || range.first >= range.end) {
    return Error{"--frames \"" + text + "\": the render has frames 0:" + std::to_string(total) +
                 "; the range must be inside it and not empty"};
  }
  return range;
}

Result<FrameRange> parse_seconds_range(const std::string& text, double start_s, int fps,
                                       std::int64_t total, double tempo_factor) {
  auto sides = split(text, "--seconds");
  if (!sides) return sides.error();
  FrameRange range{0, total};
  for (int side = 0; side < 2; ++side) {
    const std::string& s = side == 0 ? sides->a : sides->b;
    if (s.empty()) continue;
    auto value = parse_number(s, "--seconds");
    if (!value) return value.error();
    const std::int64_t frame = frame_count(0.0, (*value - start_s) / tempo_factor, fps);
    (side == 0 ? range.first : range.end) = std::clamp<std::int64_t>(frame, 0, total);
  }
  if (range.first >= range.end) {
    return Error{"--seconds \"" + text + "\": no frame of the render lies in it"};
  }
  return range;
}

}  // namespace tutti::cli
