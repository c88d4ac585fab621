// SPDX-License-Identifier: MIT
#include <tutti/music/midi/smf_chunks.hpp>

#include <algorithm>
#include <string_view>

#include <tutti/music/midi/byte_cursor.hpp>
#include <tutti/music/midi/smf_error.hpp>

namespace tutti::music::midi_detail {
namespace {

constexpr std::size_t kChunkHeaderBytes = 8;
constexpr std::size_t kMinHeaderDataBytes = 6;

bool has_tag(std::span<const std::uint8_t> bytes, std::string_view tag) {
  return bytes.size() >= tag.size() &&
         std::equal(tag.begin(), tag.end(), bytes.begin(),
                    [](char c, std::uint8_t b) { return static_cast<std::uint8_t>(c) == b; });
}

// A chunk id for messages: printable ids verbatim ("Junk"), anything else as hex bytes.
std::string describe_tag(std::span<const std::uint8_t> tag) {
  const bool printable =
      std::all_of(tag.begin(), tag.end(), [](std::uint8_t b) { return b >= 0x20 && b < 0x7F; });
  if (printable) return '"' + std::string(tag.begin(), tag.end()) + '"';
  std::string text;
  for (std::uint8_t b : tag) text += (text.empty() ? "" : " ") + hex_byte(b);
  return text;
}

// The SMF inside a RIFF "RMID" file is the payload of its "data" sub-chunk. RIFF sizes are
// little-endian and sub-chunks are padded to an even length.
struct Unwrapped {
  std::span<const std::uint8_t> smf;
  std::size_t offset = 0;
};

Result<Unwrapped> unwrap_rmid(std::span<const std::uint8_t> file, const std::string& source) {
  if (file.size() < 12 || !has_tag(file.subspan(8), "RMID")) {
    return smf_error(source, 8, "RIFF file that is not of type \"RMID\", so not a MIDI file");
  }
  ByteCursor cursor(file.subspan(12), 12);
  while (cursor.remaining() >= kChunkHeaderBytes) {
    const std::size_t chunk_offset = cursor.offset();
    const auto tag = *cursor.read_bytes(4);
    const std::uint32_t size = *cursor.read_le32();
    if (size > cursor.remaining()) {
      return smf_error(source, chunk_offset,
                       "RIFF chunk " + describe_tag(tag) + " claims " + std::to_string(size) +
                           " bytes but only " + std::to_string(cursor.remaining()) + " remain");
    }
    const std::size_t data_offset = cursor.offset();
    const auto data = *cursor.read_bytes(size);
    if (has_tag(tag, "data")) return Unwrapped{data, data_offset};
    if (size % 2 == 1) (void)cursor.read_u8();  // pad byte; may be missing at the very end
  }
  return smf_error(source, 12, "RIFF RMID file without a \"data\" chunk");
}

Result<SmfDivision> parse_division(std::uint32_t raw, std::size_t offset,
                                   const std::string& source) {
  SmfDivision division;
  if ((raw & 0x8000u) != 0) {
    // SMPTE: the high byte is the negative frame rate (two's complement), the low byte the ticks
    // per frame.
    division.smpte = true;
    division.frames_per_second = 256 - static_cast<int>(raw >> 8);
    division.ticks_per_frame = static_cast<int>(raw & 0xFFu);
    const int fps = division.frames_per_second;
    if (fps != 24 && fps != 25 && fps != 29 && fps != 30) {
      return smf_error(source, offset,
                       "SMPTE division with " + std::to_string(fps) +
                           " frames per second (only 24, 25, 29 and 30 exist)");
    }
    if (division.ticks_per_frame == 0) {
      return smf_error(source, offset, "SMPTE division with 0 ticks per frame");
    }
  } else {
    division.ticks_per_quarter = static_cast<int>(raw);
    if (division.ticks_per_quarter == 0) {
      return smf_error(source, offset, "division of 0 ticks per quarter note");
    }
  }
  return division;
}

}  // namespace

Result<SmfLayout> locate_smf_chunks(std::span<const std::uint8_t> file, const std::string& source) {
  if (file.empty()) return Error{source + ": empty file (0 bytes), not a MIDI file"};

  std::span<const std::uint8_t> smf = file;
  std::size_t base = 0;
  if (has_tag(file, "RIFF")) {
    auto unwrapped = unwrap_rmid(file, source);
    if (!unwrapped) return unwrapped.error();
    smf = unwrapped->smf;
    base = unwrapped->offset;
  }

  ByteCursor cursor(smf, base);
  if (!has_tag(smf, "MThd")) {
    return smf_error(source, base, "not a MIDI file (it does not start with \"MThd\")");
  }
  if (cursor.remaining() < kChunkHeaderBytes + kMinHeaderDataBytes) {
    return smf_error(
        source, base,
        "MThd header chunk is cut short (" + std::to_string(cursor.remaining()) + " of 14 bytes)");
  }
  (void)cursor.read_bytes(4);
  const std::uint32_t header_size = *cursor.read_be32();
  if (header_size < kMinHeaderDataBytes) {
    return smf_error(source, base + 4,
                     "MThd chunk length " + std::to_string(header_size) + " is less than 6");
  }
  if (header_size > cursor.remaining()) {
    return smf_error(source, base + 4,
                     "MThd chunk length " + std::to_string(header_size) +
                         " runs past the end of the file (" + std::to_string(cursor.remaining()) +
                         " bytes left)");
  }
  auto header_bytes = *cursor.read_bytes(header_size);  // longer headers: extra bytes skipped
  ByteCursor header(header_bytes, base + kChunkHeaderBytes);

  SmfLayout layout;
  layout.header.format = static_cast<int>(*header.read_be16());
  if (layout.header.format > 2) {
    return smf_error(source, header.offset() - 2,
                     "unknown MIDI file format " + std::to_string(layout.header.format) +
                         " (only 0, 1 and 2 exist)");
  }
  layout.header.announced_tracks = static_cast<int>(*header.read_be16());
  const std::size_t division_offset = header.offset();
  auto division = parse_division(*header.read_be16(), division_offset, source);
  if (!division) return division.error();
  layout.header.division = *division;

  // The header's count is trusted only as far as the bytes go: each chunk below must be present
  // in full before it is added, so the vector grows with the input, never with a length field.
  while (static_cast<int>(layout.tracks.size()) < layout.header.announced_tracks) {
    const int number = static_cast<int>(layout.tracks.size()) + 1;
    const std::size_t chunk_offset = cursor.offset();
    if (cursor.remaining() < kChunkHeaderBytes) {
      return smf_error(source, chunk_offset,
                       "file ends after " + std::to_string(number - 1) + " of the " +
                           std::to_string(layout.header.announced_tracks) +
                           " tracks announced in the header");
    }
    const auto tag = *cursor.read_bytes(4);
    const std::uint32_t size = *cursor.read_be32();
    const bool is_track = has_tag(tag, "MTrk");
    if (size > cursor.remaining()) {
      const std::string what =
          is_track ? "chunk length " : "length of chunk " + describe_tag(tag) + " ";
      const std::string reason = what + std::to_string(size) + " runs past the end of the file (" +
                                 std::to_string(cursor.remaining()) + " bytes left)";
      return is_track ? track_error(source, number, chunk_offset, reason)
                      : smf_error(source, chunk_offset, reason);
    }
    const std::size_t data_offset = cursor.offset();
    const auto data = *cursor.read_bytes(size);
    if (is_track) layout.tracks.push_back(TrackChunk{number, data_offset, data});
  }
  return layout;
}

}  // namespace tutti::music::midi_detail
