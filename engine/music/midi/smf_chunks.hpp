// SPDX-License-Identifier: MIT
#pragma once
// Step 1 of reading a Standard MIDI File: find the header and the track chunks. Nothing inside a
// track is looked at here; every chunk length is checked against the bytes actually present
// before anything is sliced, so a file that lies about its lengths fails fast and allocates
// nothing.
//
// Accepted layout: optional RIFF "RMID" wrapper, "MThd" chunk, then chunks until the header's
// track count of "MTrk" chunks has been seen. Chunks of other types (the SMF specification asks
// readers to skip them) and bytes after the last announced track are ignored.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <tutti/core/result.hpp>

namespace tutti::music::midi_detail {

struct SmfDivision {
  bool smpte = false;
  int ticks_per_quarter = 0;  // PPQ timing
  int frames_per_second = 0;  // SMPTE timing: 24, 25, 29 (= 29.97 drop frame) or 30
  int ticks_per_frame = 0;    // SMPTE timing
};

struct SmfHeader {
  int format = 1;  // 0, 1 or 2
  int announced_tracks = 0;
  SmfDivision division;
};

struct TrackChunk {
  int number = 0;               // 1-based ordinal among the MTrk chunks, as quoted in errors
  std::size_t data_offset = 0;  // absolute file offset of the chunk's first data byte
  std::span<const std::uint8_t> data;
};

struct SmfLayout {
  SmfHeader header;
  std::vector<TrackChunk> tracks;
};

Result<SmfLayout> locate_smf_chunks(std::span<const std::uint8_t> file, const std::string& source);

}  // namespace tutti::music::midi_detail
