// SPDX-License-Identifier: MIT
// Any text: the reader returns a score or an error; accepted scores round-trip through the writer.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include <tutti/music/pig/pig_format.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tutti::music;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  auto score = read_pig(text, "fuzz.txt");
  if (!score) return 0;
  auto again = read_pig(write_pig(*score), "fuzz-roundtrip.txt");
  if (!again || again->notes.size() != score->notes.size()) std::abort();
  for (std::size_t i = 0; i < score->notes.size(); ++i) {
    if (again->notes[i].pitch != score->notes[i].pitch) std::abort();
  }
  return 0;
}
