// SPDX-License-Identifier: MIT
#pragma once
// MusicXML reader: partwise and timewise scores, uncompressed .xml/.musicxml and compressed
// .mxl (a zip with META-INF/container.xml naming the root file; told apart by the zip
// signature, not the file name). Handles divisions (and their changes), chords, voices,
// backup/forward, ties, grace notes, cue notes, rests, percussion, tempo from <sound tempo>
// (and <metronome>), dynamics, sustain pedal, transposing instruments (<transpose>: Note::pitch
// is the sounding pitch), multiple staves, time/key signatures and <technical><fingering>
// marks (Note::finger, Note::finger_substitute). Policies are spelled out in
// measure_walker.hpp, grace_placement.hpp, tie_merge.hpp and tick_resolution.hpp.
//
// Ticks: every divisions value in the file is brought to one resolution, lcm(480, all
// divisions) capped at 10^6 (beyond: 665280 with rounding), stored as the tempo map's
// ticks_per_quarter. Measures are aligned across parts (measure k starts where the longest
// measure k-1 ended) and Score::end_ticks is the end of the last measure.
// Note::source_index is the ordinal of the <note> element in document order (0-based, counting
// every <note>: rests, grace, cue and chord notes included) so writers can find the element
// again; a tie chain keeps its first element's index.
//
// Errors are one line naming the file and, where it applies, the line or the part and measure:
// "x.musicxml: line 12: XML error: ...", "x.musicxml: part P1 measure 3: <duration> is not a
// number". Hostile inputs (absurd durations, deep nesting, zip bombs) fail the same way;
// nothing loops over durations and positions are capped at 2^50 ticks.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include <tutti/core/result.hpp>
#include <tutti/music/score.hpp>

namespace tutti::music {

Result<Score> read_musicxml(std::span<const std::uint8_t> bytes, const std::string& source_name);
Result<Score> read_musicxml_file(const std::filesystem::path& path);

}  // namespace tutti::music
