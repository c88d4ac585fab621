// SPDX-License-Identifier: MIT
#include <tutti/music/midi/smf_track_encoder.hpp>
#include <tutti/music/midi/smf_events.hpp>

#include <algorithm>
#include <tuple>

namespace tutti::music::midi_detail {
namespace {

constexpr std::uint32_t kMaxVarLen = 0x0FFFFFFF;  // 4 bytes of 7 bits
constexpr std::uint8_t kMetaSequencerSpecific = 0x7F;

std::uint8_t data_byte(int value) { return static_cast<std::uint8_t>(std::clamp(value, 0, 127)); }

}  // namespace

void append_varlen(std::vector<std::uint8_t>& out, std::uint32_t value) {
  value = std::min(value, kMaxVarLen);
  std::uint8_t groups[4];
  int count = 0;
  do {
    groups[count++] = static_cast<std::uint8_t>(value & 0x7F);
    value >>= 7;
  } while (value != 0);
  while (count > 1) out.push_back(static_cast<std::uint8_t>(groups[--count] | 0x80));
  out.push_back(groups[0]);
}

void append_be(std::vector<std::uint8_t>& out, std::uint32_t value, int byte_count) {
  for (int shift = 8 * (byte_count - 1); shift >= 0; shift -= 8) {
    out.push_back(static_cast<std::uint8_t>((value >> shift) & 0xFF));
  }
}

void append_chunk(std::vector<std::uint8_t>& out, std::string_view tag,
                  const std::vector<std::uint8_t>& data) {
  out.insert(out.end(), tag.begin(), tag.end());
  append_be(out, static_cast<std::uint32_t>(data.size()), 4);
  out.insert(out.end(), data.begin(), data.end());
}

void SmfTrackEncoder::add_channel(std::int64_t tick, int rank, std::uint8_t status, int data1,
                                  int data2) {
  Event event;
  event.tick = std::max<std::int64_t>(tick, 0);
  event.rank = rank;
  event.order = events_.size();
  event.status = status;
  event.data1 = data_byte(data1);
  event.data2 = data_byte(data2);
  events_.push_back(std::move(event));
}

void SmfTrackEncoder::add_meta(std::int64_t tick, int rank, std::uint8_t type, std::string data) {
  Event event;
  event.tick = std::max<std::int64_t>(tick, 0);
  event.rank = rank;
  event.order = events_.size();
  event.status = kMeta;
  event.meta_type = type;
  // A meta length is a 4-byte quantity; longer text cannot be stored and is cut.
  if (data.size() > kMaxVarLen) data.resize(kMaxVarLen);
  event.payload = std::move(data);
  events_.push_back(std::move(event));
}

std::vector<std::uint8_t> SmfTrackEncoder::encode(std::int64_t end_tick) const {
  std::vector<const Event*> sorted;
  sorted.reserve(events_.size());
  for (const Event& event : events_) sorted.push_back(&event);
  std::sort(sorted.begin(), sorted.end(), [](const Event* a, const Event* b) {
    return std::tie(a->tick, a->rank, a->order) < std::tie(b->tick, b->rank, b->order);
  });

  std::vector<std::uint8_t> out;
  std::int64_t now = 0;
  std::uint8_t running_status = 0;
  auto advance_to = [&](std::int64_t tick) {
    // A delta time holds at most 0x0FFFFFFF ticks; longer gaps are bridged with empty
    // sequencer-specific meta events, which every reader skips.
    while (tick - now > static_cast<std::int64_t>(kMaxVarLen)) {
      append_varlen(out, kMaxVarLen);
      out.insert(out.end(), {kMeta, kMetaSequencerSpecific, 0});
      now += kMaxVarLen;
      running_status = 0;
    }
    append_varlen(out, static_cast<std::uint32_t>(tick - now));
    now = tick;
  };

  for (const Event* event : sorted) {
    advance_to(event->tick);
    if (event->status == kMeta) {
      out.push_back(kMeta);
      out.push_back(event->meta_type);
      append_varlen(out, static_cast<std::uint32_t>(event->payload.size()));
      out.insert(out.end(), event->payload.begin(), event->payload.end());
      running_status = 0;  // the specification lets meta events cancel running status
      continue;
    }
    if (event->status != running_status) out.push_back(event->status);
    running_status = event->status;
    out.push_back(event->data1);
    const int message = event->status & 0xF0;
    if (message != 0xC0 && message != 0xD0) out.push_back(event->data2);
  }
  advance_to(std::max(now, end_tick));
  out.insert(out.end(), {kMeta, kMetaEndOfTrack, 0});
  return out;
}

}  // namespace tutti::music::midi_detail
