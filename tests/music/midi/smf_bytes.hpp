// SPDX-License-Identifier: MIT
#pragma once
// Hand-made Standard MIDI Files for tests: every byte is spelled out in the test, these helpers
// only add the chunk headers and lengths so a test reads like the file it builds.

#include <cstdint>
#include <initializer_list>
#include <string_view>
#include <vector>

namespace tutti::test {

using Bytes = std::vector<std::uint8_t>;

inline Bytes bytes(std::initializer_list<int> values) {
  Bytes out;
  for (int v : values) out.push_back(static_cast<std::uint8_t>(v));
  return out;
}

inline void append(Bytes& out, const Bytes& more) {
  out.insert(out.end(), more.begin(), more.end());
}

inline Bytes tag(std::string_view name) { return Bytes(name.begin(), name.end()); }

inline Bytes be32(std::uint32_t value) {
  return bytes({static_cast<int>(value >> 24), static_cast<int>((value >> 16) & 0xFF),
                static_cast<int>((value >> 8) & 0xFF), static_cast<int>(value & 0xFF)});
}

inline Bytes le32(std::uint32_t value) {
  return bytes({static_cast<int>(value & 0xFF), static_cast<int>((value >> 8) & 0xFF),
                static_cast<int>((value >> 16) & 0xFF), static_cast<int>(value >> 24)});
}

inline Bytes chunk(std::string_view name, const Bytes& data) {
  Bytes out = tag(name);
  append(out, be32(static_cast<std::uint32_t>(data.size())));
  append(out, data);
  return out;
}

// "MThd" chunk. `division` is the raw 16-bit field: PPQ, or 0x8000 | SMPTE bits.
inline Bytes header(int format, int tracks, int division) {
  return chunk("MThd",
               bytes({0, format, tracks >> 8, tracks & 0xFF, division >> 8, division & 0xFF}));
}

inline Bytes track(std::initializer_list<int> events) { return chunk("MTrk", bytes(events)); }

// A whole file: header then the given track chunks.
inline Bytes smf(int format, int division, std::initializer_list<Bytes> tracks) {
  Bytes out = header(format, static_cast<int>(tracks.size()), division);
  for (const Bytes& t : tracks) append(out, t);
  return out;
}

}  // namespace tutti::test
