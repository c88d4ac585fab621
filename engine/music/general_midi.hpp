// SPDX-License-Identifier: MIT
#pragma once
// General MIDI level 1 program names, for reports and instrument auto-detection.

#include <string_view>

namespace tutti::music {

// General MIDI's percussion channel, channel 10 counted from 0.
inline constexpr int kPercussionChannel = 9;

// Program 0..127, named as General MIDI 1 names it. Out of range gives "Unknown".
std::string_view general_midi_program_name(int program);

}  // namespace tutti::music
