// SPDX-License-Identifier: MIT
#pragma once
// One spelling for every MIDI reader error, so users (and tests) can rely on the shape:
//   "<file>: at byte <offset>: <reason>"                 (file structure)
//   "<file>: track <n> at byte <offset>: <reason>"       (inside the n-th MTrk chunk, 1-based)
// Offsets are absolute positions in the file, counted from 0, so `xxd -s <offset>` shows the spot.

#include <cstddef>
#include <cstdint>
#include <string>

#include <tutti/core/result.hpp>

namespace tutti::music::midi_detail {

inline Error smf_error(const std::string& source, std::size_t offset, const std::string& reason) {
  return Error{source + ": at byte " + std::to_string(offset) + ": " + reason};
}

inline Error track_error(const std::string& source, int track_number, std::size_t offset,
                         const std::string& reason) {
  return Error{source + ": track " + std::to_string(track_number) + " at byte " +
               std::to_string(offset) + ": " + reason};
}

inline std::string hex_byte(std::uint8_t byte) {
  static constexpr char kDigits[] = "0123456789ABCDEF";
  return std::string{"0x"} + kDigits[byte >> 4] + kDigits[byte & 0x0F];
}

}  // namespace tutti::music::midi_detail
