// SPDX-License-Identifier: MIT
#pragma once
// Text carried by MIDI meta events (track names, lyrics, markers, ...). The SMF specification
// leaves the encoding open: modern files use UTF-8, older ones Latin-1 (or a local code page).
// The score model stores UTF-8, so valid UTF-8 is kept and anything else is read as Latin-1,
// which maps every byte to some character and therefore never fails.

#include <cstdint>
#include <span>
#include <string>

namespace tutti::music::midi_detail {

// Also drops trailing NUL bytes, which some writers add as C-string terminators.
std::string text_from_midi_bytes(std::span<const std::uint8_t> bytes);

}  // namespace tutti::music::midi_detail
