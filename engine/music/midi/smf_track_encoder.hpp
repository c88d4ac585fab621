// SPDX-License-Identifier: MIT
#pragma once
// Builds the bytes of Standard MIDI File chunks. The writer adds events in any order with a tick
// and a rank (which of several events at one tick comes first); encode() sorts them, writes delta
// times and running status and closes the track with end-of-track.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tutti::music::midi_detail {

void append_varlen(std::vector<std::uint8_t>& out, std::uint32_t value);
void append_be(std::vector<std::uint8_t>& out, std::uint32_t value, int byte_count);
void append_chunk(std::vector<std::uint8_t>& out, std::string_view tag,
                  const std::vector<std::uint8_t>& data);

class SmfTrackEncoder {
 public:
  // status 0x80..0xEF; program change and channel pressure take one data byte (data2 ignored).
  void add_channel(std::int64_t tick, int rank, std::uint8_t status, int data1, int data2 = 0);
  void add_meta(std::int64_t tick, int rank, std::uint8_t type, std::string data);

  // Events sorted by (tick, rank, order added), then end-of-track at the last event's tick or
  // `end_tick`, whichever is later.
  std::vector<std::uint8_t> encode(std::int64_t end_tick) const;

 private:
  struct Event {
    std::int64_t tick = 0;
    int rank = 0;
    std::size_t order = 0;
    std::uint8_t status = 0;  // 0xFF = meta
    std::uint8_t meta_type = 0;
    std::uint8_t data1 = 0;
    std::uint8_t data2 = 0;
    std::string payload;  // meta events
  };
  std::vector<Event> events_;
};

}  // namespace tutti::music::midi_detail
