// SPDX-License-Identifier: MIT
#include <tutti/music/midi/smf_events.hpp>

#include <tutti/music/midi/byte_cursor.hpp>
#include <tutti/music/midi/smf_error.hpp>

namespace tutti::music::midi_detail {
namespace {

constexpr std::uint8_t kSysex = 0xF0;
constexpr std::uint8_t kSysexEscape = 0xF7;

// Data bytes after the status byte, by the high nibble of a channel status 0x80..0xE0.
int channel_data_bytes(std::uint8_t status) {
  const int message = status & 0xF0;
  return (message == 0xC0 || message == 0xD0) ? 1 : 2;
}

const char* channel_message_name(std::uint8_t status) {
  switch (status & 0xF0) {
    case 0x80:
      return "note-off";
    case 0x90:
      return "note-on";
    case 0xA0:
      return "key pressure";
    case 0xB0:
      return "control change";
    case 0xC0:
      return "program change";
    case 0xD0:
      return "channel pressure";
    default:
      return "pitch bend";
  }
}

// Why a status byte in 0xF1..0xFE cannot start an SMF event: these are wire-protocol messages
// (MIDI time code, song position, timing clock, ...) that the SMF specification does not allow
// inside a track; 0xF4, 0xF5, 0xF9 and 0xFD are not even defined on the wire.
std::string illegal_status_reason(std::uint8_t status) {
  const char* name = "undefined";
  switch (status) {
    case 0xF1:
      name = "MIDI time code quarter frame";
      break;
    case 0xF2:
      name = "song position pointer";
      break;
    case 0xF3:
      name = "song select";
      break;
    case 0xF6:
      name = "tune request";
      break;
    case 0xF8:
      name = "timing clock";
      break;
    case 0xFA:
      name = "start";
      break;
    case 0xFB:
      name = "continue";
      break;
    case 0xFC:
      name = "stop";
      break;
    case 0xFE:
      name = "active sensing";
      break;
    default:
      break;
  }
  const bool realtime = status >= 0xF8;
  return "illegal status byte " + hex_byte(status) + " (" + name + "): system " +
         (realtime ? "real-time" : "common") + " messages are not allowed in a MIDI file";
}

std::string varlen_problem(const VarLen& varlen, const std::string& what) {
  return varlen.status == VarLen::Status::too_long ? what + " longer than 4 bytes"
                                                   : what + " runs past the end of the track chunk";
}

class TrackDecoder {
 public:
  TrackDecoder(const TrackChunk& chunk, const std::string& source, SmfEventHandler& handler)
      : chunk_(chunk), source_(source), handler_(handler), cursor_(chunk.data, chunk.data_offset) {}

  Result<std::int64_t> run() {
    std::int64_t tick = 0;
    std::int64_t end_tick = 0;
    while (!cursor_.at_end()) {
      const std::size_t delta_offset = cursor_.offset();
      const VarLen delta = cursor_.read_varlen();
      if (delta.status != VarLen::Status::ok) {
        return fail(delta_offset, varlen_problem(delta, "delta time"));
      }
      tick += delta.value;
      if (cursor_.at_end()) {
        return fail(cursor_.offset(), "track chunk ends after a delta time, before its event");
      }
      SmfEvent event;
      event.tick = tick;
      event.offset = cursor_.offset();
      if (auto problem = read_event(event); !problem.empty()) return fail(event.offset, problem);
      if (auto problem = handler_.on_event(event); !problem.empty()) {
        return fail(event.offset, problem);
      }
      end_tick = tick;
      if (event.kind == SmfEventKind::meta && event.meta_type == kMetaEndOfTrack) {
        break;  // anything after it in the chunk is padding, by the specification
      }
    }
    return end_tick;
  }

 private:
  Error fail(std::size_t offset, const std::string& reason) const {
    return track_error(source_, chunk_.number, offset, reason);
  }

  // Fills `event` from the cursor; returns an empty string or the reason it failed.
  std::string read_event(SmfEvent& event) {
    const std::uint8_t first = *cursor_.peek();
    if (first < 0x80) {
      // Running status: the data byte belongs to a message with the previous channel status.
      if (running_status_ == 0) {
        return "data byte " + hex_byte(first) + " without a preceding status byte";
      }
      event.status = running_status_;
      return read_channel_data(event);
    }
    (void)cursor_.read_u8();
    event.status = first;
    if (first < 0xF0) {
      running_status_ = first;
      return read_channel_data(event);
    }
    if (first == kMeta) return read_meta(event);
    if (first == kSysex || first == kSysexEscape) return read_sysex(event);
    return illegal_status_reason(first);
  }

  std::string read_channel_data(SmfEvent& event) {
    event.kind = SmfEventKind::channel;
    const int count = channel_data_bytes(event.status);
    std::uint8_t data[2] = {0, 0};
    for (int i = 0; i < count; ++i) {
      const auto byte = cursor_.read_u8();
      if (!byte) {
        return std::string{channel_message_name(event.status)} +
               " event runs past the end of the track chunk";
      }
      if (*byte >= 0x80) {
        return std::string{channel_message_name(event.status)} + " event has " + hex_byte(*byte) +
               " where a data byte (0x00-0x7F) belongs";
      }
      data[i] = *byte;
    }
    event.data1 = data[0];
    event.data2 = data[1];
    return {};
  }

  std::string read_meta(SmfEvent& event) {
    event.kind = SmfEventKind::meta;
    const auto type = cursor_.read_u8();
    if (!type) return "meta event runs past the end of the track chunk";
    event.meta_type = *type;
    return read_payload(event, "meta event " + hex_byte(*type));
  }

  std::string read_sysex(SmfEvent& event) {
    event.kind = SmfEventKind::sysex;
    return read_payload(event, event.status == kSysex ? "sysex event" : "sysex escape event");
  }

  // Length-prefixed data of meta and sysex events, checked against the chunk before slicing.
  std::string read_payload(SmfEvent& event, const std::string& what) {
    const VarLen length = cursor_.read_varlen();
    if (length.status != VarLen::Status::ok) return varlen_problem(length, what + " length");
    const auto payload = cursor_.read_bytes(length.value);
    if (!payload) {
      return what + " of " + std::to_string(length.value) + " bytes runs past the end of the " +
             "track chunk (" + std::to_string(cursor_.remaining()) + " bytes left)";
    }
    event.payload = *payload;
    return {};
  }

  const TrackChunk& chunk_;
  const std::string& source_;
  SmfEventHandler& handler_;
  ByteCursor cursor_;
  std::uint8_t running_status_ = 0;  // 0 = none yet
};

}  // namespace

Result<std::int64_t> decode_track(const TrackChunk& chunk, const std::string& source,
                                  SmfEventHandler& handler) {
  return TrackDecoder(chunk, source, handler).run();
}

}  // namespace tutti::music::midi_detail
