#pragma once
// Which frames of a render to produce: parsing "A:B" (frames or seconds) against the output's
// frame count, and the time of each frame (t = start + k / fps: exact, never accumulated).

#include <cstdint>
#include <string>

#include "core/result.hpp"

namespace tutti::app {

struct FrameRange {
  std::int64_t first = 0;  // inclusive
  std::int64_t end = 0;    // exclusive
};

// Frames in [start_s, end_s) at fps: ceil((end_s - start_s) * fps - 1e-9).
std::int64_t frame_count(double start_s, double end_s, int fps);

// "A:B" (either side may be empty: from the first / to the last frame) in frame numbers.
Result<FrameRange> parse_frame_range(const std::string& text, std::int64_t total);
// "A:B" in seconds of the music: the frames whose times lie in [A, B).
Result<FrameRange> parse_seconds_range(const std::string& text, double start_s, int fps,
                                       std::int64_t total);

inline double frame_time(double start_s, int fps, std::int64_t frame) {
  return start_s + static_cast<double>(frame) / fps;
}

}  // namespace tutti::app
