// SPDX-License-Identifier: MIT
#pragma once
// Step 2 of reading a Standard MIDI File: decode one MTrk chunk into timed events. Only syntax is
// handled here (delta times, running status, event lengths); what the events mean is up to
// midi_score_builder.
//
// Leniency, chosen to match what real files do and what players accept:
//  - running status survives meta and sysex events (the specification says they cancel it, but
//    files in the wild rely on it continuing, see jazz-soft test-running-status-*.mid);
//  - bytes after the end-of-track event inside the chunk are ignored;
//  - a chunk without an end-of-track event simply ends with its last event.
// Rejected: system common and real-time status bytes (0xF1-0xF6, 0xF8-0xFE), which are not SMF
// events, data bytes >= 0x80, variable-length quantities longer than 4 bytes, and any event that
// runs past the end of its chunk.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include <tutti/core/result.hpp>
#include <tutti/music/midi/smf_chunks.hpp>

namespace tutti::music::midi_detail {

enum class SmfEventKind : std::uint8_t { channel, sysex, meta };

inline constexpr std::uint8_t kMeta = 0xFF;  // the status byte of a meta event
inline constexpr std::uint8_t kMetaEndOfTrack = 0x2F;

struct SmfEvent {
  std::int64_t tick = 0;   // absolute, from the start of the track
  std::size_t offset = 0;  // absolute file offset of the event's status (or first data) byte
  SmfEventKind kind = SmfEventKind::channel;
  std::uint8_t status = 0;     // channel: 0x80..0xEF; sysex: 0xF0 or 0xF7; meta: 0xFF
  std::uint8_t meta_type = 0;  // meta events only
  std::uint8_t data1 = 0;      // channel events: first data byte
  std::uint8_t data2 = 0;      // channel events: second data byte (0 for program/pressure)
  std::span<const std::uint8_t> payload;  // meta and sysex data, a view into the file bytes

  int channel() const { return status & 0x0F; }
  int message() const { return status & 0xF0; }  // 0x80 note-off, 0x90 note-on, ...
};

// Receives the events of a track as they are decoded, so no per-event list is ever built.
class SmfEventHandler {
 public:
  virtual ~SmfEventHandler() = default;
  // Returns an empty string to go on, or why the event is unacceptable (the decoder then fails
  // with that reason at the event's offset).
  virtual std::string on_event(const SmfEvent& event) = 0;
};

// Decodes the chunk and hands every event to `handler` in file order. Returns the tick of the
// track's last event (normally end-of-track), i.e. the track's length.
Result<std::int64_t> decode_track(const TrackChunk& chunk, const std::string& source,
                                  SmfEventHandler& handler);

}  // namespace tutti::music::midi_detail
