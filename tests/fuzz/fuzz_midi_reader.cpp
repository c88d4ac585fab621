// SPDX-License-Identifier: MIT
// Any bytes: the reader returns a score or an error, never crashes or hangs. A score it accepts
// must be sane and must survive a write/read round trip.
#include <cstdint>
#include <cstdlib>
#include <span>

#include <tutti/music/midi/midi_reader.hpp>
#include <tutti/music/midi/midi_writer.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tutti::music;
  auto score = read_midi(std::span(data, size), "fuzz.mid");
  if (!score) return 0;
  for (const Note& note : score->notes) {
    if (note.pitch < 0 || note.pitch > 127 || note.offset_ticks < note.onset_ticks) std::abort();
  }
  const auto bytes = write_midi(*score);
  auto again = read_midi(bytes, "fuzz-roundtrip.mid");
  if (!again || again->notes.size() != score->notes.size()) std::abort();
  return 0;
}
