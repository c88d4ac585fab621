// SPDX-License-Identifier: MIT
#pragma once
// Which frames of a render to produce: parsing "A:B" (frames or seconds) against the output's
// frame count, and the time of each frame (t = start + k / fps: exact, never accumulated).

#include <cstdint>
#include <string>

#include <tutti/audio_sync/audio_clock.hpp>
#include <tutti/core/result.hpp>

namespace tutti::cli {

struct FrameRange {
  std::int64_t first = 0;  // inclusive
  std::int64_t end = 0;    // exclusive
};

// Frames in [start_s, end_s) at fps: ceil((end_s - start_s) * fps - 1e-9).
std::int64_t frame_count(double start_s, double end_s, int fps);

// "A:B" (either side may be empty: from the first / to the last frame) in frame numbers.
Result<FrameRange> parse_frame_range(const std::string& text, std::int64_t total);
// "A:B" in seconds of the music: the frames whose times lie in [A, B) (at a practice tempo,
// frame k shows start_s + k / fps x tempo_factor).
Result<FrameRange> parse_seconds_range(const std::string& text, double start_s, int fps,
                                       std::int64_t total, double tempo_factor = 1.0);

// The score time frame k shows: audio_sync's offline clock.
inline double frame_time(double start_s, int fps, std::int64_t frame, double tempo_factor = 1.0) {
  return audio_sync::offline_frame_time(start_s, fps, frame, tempo_factor);
}

}  // namespace tutti::cli
