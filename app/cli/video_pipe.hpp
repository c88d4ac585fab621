// SPDX-License-Identifier: MIT
#pragma once
// Encodes RGBA frames to H.264 (yuv420p, MP4), with an optional AAC track from a WAV file, by
// piping them into Debian's ffmpeg; no shell is
// involved (fork + exec with an argument vector), so any file name is safe. x264 is deterministic:
// the same frames give the same file.

#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>

#include <tutti/core/result.hpp>

namespace tutti::cli {

struct VideoEncoding {
  // x264 at -qp 0: every decoded frame is exactly the frame given (in yuv420p), so slices
  // rendered apart and joined equal a single render frame for frame. Files are several times
  // larger.
  bool lossless = false;
  std::string comment;  // written as the file's "comment" tag (tutti concat reads it)
};

class VideoPipe {
 public:
  // Starts `ffmpeg` (from PATH) writing `path`. With `audio_wav`, that file becomes the AAC
  // audio track (192 kb/s). An error when ffmpeg cannot be started.
  static Result<std::unique_ptr<VideoPipe>> open(const std::filesystem::path& path,
                                                 std::uint32_t width, std::uint32_t height, int fps,
                                                 const std::filesystem::path& audio_wav = {},
                                                 const VideoEncoding& encoding = {});
  ~VideoPipe();
  VideoPipe(const VideoPipe&) = delete;
  VideoPipe& operator=(const VideoPipe&) = delete;

  // width * height * 4 bytes, top row first.
  Status write(std::span<const std::uint8_t> rgba);
  // Closes the pipe and waits: an error when ffmpeg failed (its last message is included).
  Status finish();

 private:
  VideoPipe() = default;
  std::filesystem::path path_;
  int fd_ = -1;
  pid_t pid_ = -1;
  std::filesystem::path log_;
};

}  // namespace tutti::cli
