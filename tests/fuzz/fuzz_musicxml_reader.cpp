// SPDX-License-Identifier: MIT
// Any bytes: the reader returns a score or an error, never crashes or hangs.
#include <cstdint>
#include <cstdlib>
#include <span>

#include <tutti/music/musicxml/musicxml_reader.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tutti::music;
  auto score = read_musicxml(std::span(data, size), "fuzz.musicxml");
  if (!score) return 0;
  for (const Note& note : score->notes) {
    if (note.pitch < 0 || note.pitch > 127 || note.offset_ticks < note.onset_ticks) std::abort();
  }
  return 0;
}
