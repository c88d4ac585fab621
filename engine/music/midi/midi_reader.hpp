// SPDX-License-Identifier: MIT
#pragma once
// Standard MIDI File reader: formats 0, 1 and 2, PPQ and SMPTE divisions, running status
// (including across meta and sysex events, as real files do), sysex F0/F7, every meta event,
// note-on velocity 0 as note-off, overlapping notes of one pitch paired first-in-first-out, and
// the RIFF "RMID" wrapper.
//
// Format 2 tracks are independent patterns; they are laid end to end (track k starts where
// track k-1 ended) so the score is one timeline.
//
// Errors name the file, the track and the byte offset: "x.mid: track 2 at byte 812: ...".
// Memory is bounded by the input size: chunk lengths are checked against the bytes present.
//
// Valid or broken (checked against the jazz-soft edge-case files, see
// tests/music/midi/midi_testdata_test.cpp):
//  - accepted: unknown chunk types (skipped), bytes after the last announced track, running
//    status across meta and sysex events, bytes after end-of-track inside its chunk, a missing
//    end-of-track, format 0 files with several tracks (played together, as format 1);
//  - rejected: anything that is not an SMF (or RMID) header, a chunk or event running past the
//    end of its file or chunk (truncated files, wrong lengths), fewer tracks than the header
//    announces, status bytes 0xF1-0xF6 and 0xF8-0xFE (wire-protocol messages, not SMF events),
//    data bytes >= 0x80, variable-length quantities longer than 4 bytes, and malformed tempo,
//    time signature, key signature or SMPTE offset meta events.
// The details of how events become notes, parts and pedals are in midi_score_builder.hpp.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include <tutti/core/result.hpp>
#include <tutti/music/score.hpp>

namespace tutti::music {

Result<Score> read_midi(std::span<const std::uint8_t> bytes, const std::string& source_name);
Result<Score> read_midi_file(const std::filesystem::path& path);

}  // namespace tutti::music
