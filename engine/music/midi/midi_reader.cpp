// SPDX-License-Identifier: MIT
#include <tutti/music/midi/midi_reader.hpp>

#include <algorithm>
#include <utility>

#include <tutti/core/file_io.hpp>
#include <tutti/music/midi/midi_score_builder.hpp>
#include <tutti/music/midi/smf_chunks.hpp>
#include <tutti/music/midi/smf_events.hpp>

namespace tutti::music {

// Three steps, each in its own file: find the chunks (smf_chunks), decode each track's events
// (smf_events), give them meaning (midi_score_builder). Events stream from the decoder into the
// builder, so memory grows with the notes in the file, never with a length field.
Result<Score> read_midi(std::span<const std::uint8_t> bytes, const std::string& source_name) {
  using namespace midi_detail;
  auto layout = locate_smf_chunks(bytes, source_name);
  if (!layout) return layout.error();

  const bool tracks_play_in_turn = layout->header.format == 2;
  MidiScoreBuilder builder(layout->header, source_name);
  std::int64_t track_start = 0;
  std::int64_t end_ticks = 0;
  for (std::size_t i = 0; i < layout->tracks.size(); ++i) {
    builder.begin_track(static_cast<int>(i), track_start);
    auto length = decode_track(layout->tracks[i], source_name, builder);
    if (!length) return length.error();
    const std::int64_t track_end = track_start + *length;
    builder.end_track(track_end);
    end_ticks = std::max(end_ticks, track_end);
    if (tracks_play_in_turn) track_start = track_end;
  }
  return std::move(builder).finish(end_ticks);
}

Result<Score> read_midi_file(const std::filesystem::path& path) {
  auto bytes = read_file_bytes(path);
  if (!bytes) return bytes.error();
  return read_midi(*bytes, path.string());
}

}  // namespace tutti::music
