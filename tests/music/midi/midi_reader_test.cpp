// SPDX-License-Identifier: MIT
// Byte-level tests of the MIDI reader: every file is built here, byte by byte, so each test
// shows exactly the input it is about.

#include <tutti/music/midi/midi_reader.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <random>
#include <string>

#include "smf_bytes.hpp"

// The bytes of each file are laid out by hand, one MIDI event per line.
// clang-format off
namespace tutti::music {
namespace {

using test::append;
using test::Bytes;
using test::bytes;
using test::chunk;
using test::header;
using test::smf;
using test::track;

constexpr int kPpq = 96;
// Offset of the first event in a plain file: MThd chunk (14 bytes), then MTrk header (8 bytes).
constexpr std::size_t kFirstEvent = 22;

Score read_ok(const Bytes& file) {
  auto score = read_midi(file, "t.mid");
  EXPECT_TRUE(score.ok()) << score.error().message;
  return score.ok() ? std::move(score).value() : Score{};
}

std::string read_error(const Bytes& file) {
  auto score = read_midi(file, "t.mid");
  EXPECT_FALSE(score.ok()) << "the file was accepted";
  return score.ok() ? std::string{} : score.error().message;
}

TEST(MidiReader, RunningStatusRepeatsTheLastChannelStatus) {
  const Score score = read_ok(smf(0, kPpq, {track({0x00, 0x90, 60, 100,  // C4 on
                                                   0x00, 64, 100,         // E4 on, running status
                                                   0x60, 60, 0,           // C4 off (velocity 0)
                                                   0x00, 64, 0,           // E4 off
                                                   0x00, 0xFF, 0x2F, 0x00})}));
  ASSERT_EQ(score.notes.size(), 2u);
  EXPECT_EQ(score.notes[0].pitch, 60);
  EXPECT_EQ(score.notes[1].pitch, 64);
  for (const Note& note : score.notes) {
    EXPECT_EQ(note.onset_ticks, 0);
    EXPECT_EQ(note.offset_ticks, 96);
    EXPECT_EQ(note.velocity, 100);
  }
}

TEST(MidiReader, RunningStatusSurvivesMetaAndSysexEvents) {
  // As in jazz-soft test-running-status-{metaevent,sysex}.mid: real files keep using the running
  // status after a meta or sysex event, although the specification says they cancel it.
  const Score score = read_ok(smf(0, kPpq, {track({0x00, 0x90, 60, 100,
                                                   0x30, 0xFF, 0x01, 3, 'a', 'b', 'c',
                                                   0x00, 0xF0, 0x03, 0x7E, 0x7F, 0xF7,
                                                   0x30, 60, 0,     // C4 off
                                                   0x00, 62, 80,    // D4 on
                                                   0x60, 62, 0,     // D4 off
                                                   0x00, 0xFF, 0x2F, 0x00})}));
  ASSERT_EQ(score.notes.size(), 2u);
  EXPECT_EQ(score.notes[0].pitch, 60);
  EXPECT_EQ(score.notes[0].offset_ticks, 96);
  EXPECT_EQ(score.notes[1].pitch, 62);
  EXPECT_EQ(score.notes[1].onset_ticks, 96);
  EXPECT_EQ(score.notes[1].offset_ticks, 192);
  EXPECT_EQ(score.notes[1].velocity, 80);
}

TEST(MidiReader, NoteOnWithVelocityZeroIsANoteOff) {
  const Score score = read_ok(smf(0, kPpq, {track({0x00, 0x90, 60, 100,
                                                   0x60, 0x80, 60, 30,   // note-off, velocity 30
                                                   0x00, 0x90, 62, 100,
                                                   0x60, 0x90, 62, 0,    // note-on velocity 0
                                                   0x00, 0xFF, 0x2F, 0x00})}));
  ASSERT_EQ(score.notes.size(), 2u);
  EXPECT_EQ(score.notes[0].offset_ticks, 96);
  EXPECT_EQ(score.notes[0].release_velocity, 30);
  EXPECT_EQ(score.notes[1].offset_ticks, 192);
  EXPECT_EQ(score.notes[1].release_velocity, 64);  // the velocity a note-on/0 stands for
}

TEST(MidiReader, OverlappingNotesOfOneKeyArePairedFirstInFirstOut) {
  const Score score = read_ok(smf(0, kPpq, {track({0x00, 0x90, 60, 80,
                                                   0x0A, 0x90, 60, 96,
                                                   0x0A, 0x80, 60, 0,
                                                   0x0A, 0x80, 60, 0,
                                                   0x00, 0xFF, 0x2F, 0x00})}));
  ASSERT_EQ(score.notes.size(), 2u);
  EXPECT_EQ(score.notes[0].velocity, 80);
  EXPECT_EQ(score.notes[0].onset_ticks, 0);
  EXPECT_EQ(score.notes[0].offset_ticks, 20);
  EXPECT_EQ(score.notes[1].velocity, 96);
  EXPECT_EQ(score.notes[1].onset_ticks, 10);
  EXPECT_EQ(score.notes[1].offset_ticks, 30);
}

TEST(MidiReader, NotesNeverSwitchedOffEndWithTheirTrack) {
  const Score score = read_ok(smf(1, kPpq, {track({0x00, 0x90, 60, 100,
                                                   0x60, 0x90, 62, 100,
                                                   0x83, 0x00, 0xFF, 0x2F, 0x00}),  // +384
                                            track({0x00, 0x90, 70, 100,
                                                   0x10, 0xFF, 0x2F, 0x00})}));
  ASSERT_EQ(score.notes.size(), 3u);
  EXPECT_EQ(score.notes[0].pitch, 60);
  EXPECT_EQ(score.notes[0].offset_ticks, 480);
  EXPECT_EQ(score.notes[1].pitch, 70);
  EXPECT_EQ(score.notes[1].offset_ticks, 16);  // its own track ended there
  EXPECT_EQ(score.notes[2].pitch, 62);
  EXPECT_EQ(score.notes[2].offset_ticks, 480);
  EXPECT_EQ(score.end_ticks, 480);
}

TEST(MidiReader, StrayNoteOffsAreIgnored) {
  const Score score = read_ok(smf(0, kPpq, {track({0x00, 0x80, 60, 0,
                                                   0x00, 0x90, 60, 100,
                                                   0x60, 0x80, 60, 0,
                                                   0x00, 0x80, 60, 0,
                                                   0x00, 0xFF, 0x2F, 0x00})}));
  ASSERT_EQ(score.notes.size(), 1u);
  EXPECT_EQ(score.notes[0].offset_ticks, 96);
}

TEST(MidiReader, TempoChangeMidPieceChangesSeconds) {
  const Score score = read_ok(smf(0, kPpq, {track({0x00, 0xFF, 0x51, 3, 0x07, 0xA1, 0x20,  // 0.5 s
                                                   0x00, 0x90, 60, 100,
                                                   0x60, 0x80, 60, 0,
                                                   0x00, 0xFF, 0x51, 3, 0x0F, 0x42, 0x40,  // 1 s
                                                   0x60, 0x90, 62, 100,
                                                   0x60, 0x80, 62, 0,
                                                   0x00, 0xFF, 0x2F, 0x00})}));
  ASSERT_EQ(score.notes.size(), 2u);
  EXPECT_DOUBLE_EQ(score.notes[0].offset_s, 0.5);
  EXPECT_EQ(score.notes[1].onset_ticks, 192);
  EXPECT_DOUBLE_EQ(score.notes[1].onset_s, 1.5);
  EXPECT_DOUBLE_EQ(score.notes[1].offset_s, 2.5);
  EXPECT_DOUBLE_EQ(score.notes[1].onset_beats, 2.0);
  EXPECT_DOUBLE_EQ(score.duration_s(), 2.5);
  ASSERT_EQ(score.tempo_map.changes().size(), 2u);
  EXPECT_DOUBLE_EQ(score.tempo_map.bpm_at(200), 60.0);
}

TEST(MidiReader, TempoInAnyTrackOfAFormat1FileCounts) {
  const Score score = read_ok(smf(1, kPpq, {track({0x00, 0xFF, 0x2F, 0x00}),
                                            track({0x00, 0xFF, 0x51, 3, 0x0F, 0x42, 0x40,
                                                   0x00, 0x90, 60, 100,
                                                   0x60, 0x80, 60, 0,
                                                   0x00, 0xFF, 0x2F, 0x00})}));
  ASSERT_EQ(score.notes.size(), 1u);
  EXPECT_DOUBLE_EQ(score.notes[0].offset_s, 1.0);
}

TEST(MidiReader, SmpteDivisionCountsTicksInRealTime) {
  // 0xE7 = -25 frames per second, 40 ticks per frame: 1000 ticks per second. Tempo 0.25 s.
  const Score score = read_ok(smf(0, 0xE728, {track({0x00, 0xFF, 0x51, 3, 0x03, 0xD0, 0x90,
                                                     0x00, 0x90, 60, 100,
                                                     0x8B, 0x5C, 0x80, 60, 0,  // +1500
                                                     0x00, 0x90, 62, 100,
                                                     0x83, 0x74, 0x80, 62, 0,  // +500
                                                     0x00, 0xFF, 0x2F, 0x00})}));
  EXPECT_TRUE(score.tempo_map.is_smpte());
  EXPECT_EQ(score.tempo_map.smpte_frames_per_second(), 25);
  EXPECT_EQ(score.tempo_map.smpte_ticks_per_frame(), 40);
  ASSERT_EQ(score.notes.size(), 2u);
  EXPECT_DOUBLE_EQ(score.notes[0].offset_s, 1.5);
  EXPECT_DOUBLE_EQ(score.notes[1].onset_s, 1.5);
  EXPECT_DOUBLE_EQ(score.notes[1].offset_s, 2.0);
  EXPECT_DOUBLE_EQ(score.notes[1].offset_beats, 8.0);  // the tempo still counts quarters
  EXPECT_DOUBLE_EQ(score.duration_s(), 2.0);
}

TEST(MidiReader, SmpteDivisionWithAnImpossibleFrameRateIsAnError) {
  const std::string message = read_error(smf(0, 0xE928, {track({0x00, 0xFF, 0x2F, 0x00})}));
  EXPECT_EQ(message,
            "t.mid: at byte 12: SMPTE division with 23 frames per second (only 24, 25, 29 and 30 "
            "exist)");
}

Bytes simple_song() {
  return smf(0, kPpq, {track({0x00, 0xFF, 0x03, 4, 'S', 'o', 'n', 'g',
                              0x00, 0x90, 60, 100,
                              0x60, 0x80, 60, 0,
                              0x00, 0xFF, 0x2F, 0x00})});
}

TEST(MidiReader, RmidWrapperIsUnwrapped) {
  const Bytes inner = simple_song();
  Bytes riff_body = test::tag("RMID");
  append(riff_body, chunk("LIST", bytes({'a', 'b', 'c'})));  // odd size: one pad byte follows
  riff_body.push_back(0);
  append(riff_body, test::tag("data"));
  append(riff_body, test::le32(static_cast<std::uint32_t>(inner.size())));
  append(riff_body, inner);
  Bytes file = test::tag("RIFF");
  append(file, test::le32(static_cast<std::uint32_t>(riff_body.size())));
  append(file, riff_body);
  // The LIST chunk's size is big-endian in chunk(); RIFF wants little-endian, so patch it.
  file[16] = 3, file[17] = 0, file[18] = 0, file[19] = 0;

  const Score score = read_ok(file);
  ASSERT_EQ(score.notes.size(), 1u);
  ASSERT_EQ(score.parts.size(), 1u);
  EXPECT_EQ(score.parts[0].name, "Song");
}

TEST(MidiReader, RmidErrorsQuoteOffsetsInTheWholeFile) {
  Bytes inner = smf(0, kPpq, {track({0x81, 0x81, 0x81, 0x81, 0x00})});
  Bytes file = test::tag("RIFF");
  append(file, test::le32(static_cast<std::uint32_t>(inner.size() + 12)));
  append(file, test::tag("RMID"));
  append(file, test::tag("data"));
  append(file, test::le32(static_cast<std::uint32_t>(inner.size())));
  append(file, inner);
  EXPECT_EQ(read_error(file), "t.mid: track 1 at byte " + std::to_string(20 + kFirstEvent) +
                                  ": delta time longer than 4 bytes");
}

TEST(MidiReader, RiffThatIsNotRmidIsRejected) {
  Bytes file = test::tag("RIFF");
  append(file, test::le32(4));
  append(file, test::tag("WAVE"));
  EXPECT_EQ(read_error(file),
            "t.mid: at byte 8: RIFF file that is not of type \"RMID\", so not a MIDI file");
}

TEST(MidiReader, Format2TracksAreLaidEndToEnd) {
  const Score score = read_ok(smf(2, kPpq, {track({0x00, 0x90, 60, 100,
                                                   0x60, 0x80, 60, 0,
                                                   0x60, 0xFF, 0x2F, 0x00}),  // ends at 192
                                            track({0x00, 0xFF, 0x03, 1, 'B',
                                                   0x00, 0x90, 62, 100,
                                                   0x60, 0x80, 62, 0,
                                                   0x00, 0xFF, 0x2F, 0x00})}));
  ASSERT_EQ(score.notes.size(), 2u);
  EXPECT_EQ(score.notes[1].pitch, 62);
  EXPECT_EQ(score.notes[1].onset_ticks, 192);
  EXPECT_EQ(score.notes[1].offset_ticks, 288);
  EXPECT_EQ(score.end_ticks, 288);
  ASSERT_EQ(score.parts.size(), 2u);
  EXPECT_EQ(score.parts[1].id, "track1-ch0");
  EXPECT_EQ(score.parts[1].name, "B");
  EXPECT_EQ(score.notes[1].part, 1);
}

TEST(MidiReader, Format0WithSeveralTracksPlaysThemTogether) {
  // The specification allows one track in format 0; players (and mido) play more in parallel.
  const Score score = read_ok(smf(0, kPpq, {track({0x00, 0x90, 60, 100, 0x60, 0x80, 60, 0}),
                                            track({0x00, 0x90, 62, 100, 0x60, 0x80, 62, 0})}));
  ASSERT_EQ(score.notes.size(), 2u);
  EXPECT_EQ(score.notes[0].onset_ticks, 0);
  EXPECT_EQ(score.notes[1].onset_ticks, 0);
  EXPECT_EQ(score.end_ticks, 96);
}

TEST(MidiReader, SysexAndEscapeEventsAreSkipped) {
  const Score score = read_ok(smf(0, kPpq, {track({0x00, 0xF0, 0x05, 0x7E, 0x7F, 0x09, 0x01, 0xF7,
                                                   0x00, 0xF0, 0x03, 0x43, 0x12, 0x00,  // packet 1
                                                   0x10, 0xF7, 0x02, 0x34, 0xF7,        // packet 2
                                                   0x00, 0xF7, 0x02, 0xF3, 0x01,  // escape: F3
                                                   0x00, 0x90, 60, 100,
                                                   0x60, 0x80, 60, 0,
                                                   0x00, 0xFF, 0x2F, 0x00})}));
  ASSERT_EQ(score.notes.size(), 1u);
  EXPECT_EQ(score.notes[0].onset_ticks, 16);
}

TEST(MidiReader, EveryTruncationOfAFileIsAnErrorWithAByteOffset) {
  const Bytes full = simple_song();
  for (std::size_t size = 0; size < full.size(); ++size) {
    const Bytes cut(full.begin(), full.begin() + static_cast<std::ptrdiff_t>(size));
    const std::string message = read_error(cut);
    EXPECT_EQ(message.rfind("t.mid: ", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    if (size > 0) {
      EXPECT_NE(message.find(" at byte "), std::string::npos) << message;
    }
  }
  const Bytes cut(full.begin(), full.end() - 1);
  EXPECT_EQ(read_error(cut), "t.mid: track 1 at byte 14: chunk length " +
                                 std::to_string(full.size() - kFirstEvent) +
                                 " runs past the end of the file (" +
                                 std::to_string(full.size() - kFirstEvent - 1) + " bytes left)");
  EXPECT_EQ(read_error({}), "t.mid: empty file (0 bytes), not a MIDI file");
}

TEST(MidiReader, EventCutByTheEndOfItsChunkIsAnError) {
  EXPECT_EQ(read_error(smf(0, kPpq, {track({0x00, 0x90, 60})})),
            "t.mid: track 1 at byte 23: note-on event runs past the end of the track chunk");
  EXPECT_EQ(read_error(smf(0, kPpq, {track({0x00, 0xFF, 0x01, 0x10, 'a'})})),
            "t.mid: track 1 at byte 23: meta event 0x01 of 16 bytes runs past the end of the "
            "track chunk (1 bytes left)");
  EXPECT_EQ(read_error(smf(0, kPpq, {track({0x00, 0x90, 60, 100, 0x81})})),
            "t.mid: track 1 at byte 26: delta time runs past the end of the track chunk");
  EXPECT_EQ(read_error(smf(0, kPpq, {track({0x00, 0x90, 60, 100, 0x60, 0x80, 60, 0, 0x00})})),
            "t.mid: track 1 at byte 31: track chunk ends after a delta time, before its event");
}

TEST(MidiReader, LyingLengthsFailFastWithoutAllocating) {
  const auto started = std::chrono::steady_clock::now();
  Bytes file = header(1, 1, kPpq);
  append(file, test::tag("MTrk"));
  append(file, test::be32(0xFFFFFFF0));
  append(file, bytes({0x00, 0x90, 60, 100}));
  EXPECT_EQ(read_error(file),
            "t.mid: track 1 at byte 14: chunk length 4294967280 runs past the end of the file "
            "(4 bytes left)");

  Bytes many_tracks = header(1, 0xFFFF, kPpq);
  append(many_tracks, track({0x00, 0xFF, 0x2F, 0x00}));
  EXPECT_EQ(read_error(many_tracks),
            "t.mid: at byte 26: file ends after 1 of the 65535 tracks announced in the header");

  // The largest 4-byte length, on a meta and on a sysex event.
  EXPECT_EQ(read_error(smf(0, kPpq, {track({0x00, 0xFF, 0x01, 0xFF, 0xFF, 0xFF, 0x7F, 'a'})})),
            "t.mid: track 1 at byte 23: meta event 0x01 of 268435455 bytes runs past the end of "
            "the track chunk (1 bytes left)");
  EXPECT_NE(read_error(smf(0, kPpq, {track({0x00, 0xF0, 0xFF, 0xFF, 0xFF, 0x7F, 0x01})}))
                .find("sysex event of 268435455 bytes runs past the end"),
            std::string::npos);

  Bytes header_lies = test::tag("MThd");
  append(header_lies, test::be32(0xFFFFFFFF));
  append(header_lies, bytes({0, 1, 0, 1, 0, 96}));
  EXPECT_EQ(read_error(header_lies),
            "t.mid: at byte 4: MThd chunk length 4294967295 runs past the end of the file (6 "
            "bytes left)");
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(1));
}

TEST(MidiReader, VariableLengthQuantityLongerThanFourBytesIsAnError) {
  EXPECT_EQ(read_error(smf(0, kPpq, {track({0x81, 0x81, 0x81, 0x81, 0x00,
                                            0x90, 60, 100})})),
            "t.mid: track 1 at byte 22: delta time longer than 4 bytes");
  EXPECT_EQ(read_error(smf(0, kPpq, {track({0x00, 0xFF, 0x01, 0x80, 0x80, 0x80, 0x80, 0x01})})),
            "t.mid: track 1 at byte 23: meta event 0x01 length longer than 4 bytes");
  // Four bytes is the maximum and fine: 0x0FFFFFFF ticks.
  const Score score = read_ok(smf(0, kPpq, {track({0xFF, 0xFF, 0xFF, 0x7F, 0xFF, 0x2F, 0x00})}));
  EXPECT_EQ(score.end_ticks, 0x0FFFFFFF);
}

TEST(MidiReader, SystemCommonAndRealTimeStatusBytesAreErrors) {
  for (int status = 0xF1; status <= 0xFE; ++status) {
    if (status == 0xF7) continue;  // sysex escape: legal
    const std::string message = read_error(smf(0, kPpq, {track({0x00, status, 0x00, 0x00,
                                                                0x00, 0xFF, 0x2F, 0x00})}));
    EXPECT_EQ(message.rfind("t.mid: track 1 at byte 23: illegal status byte 0x", 0), 0u)
        << message;
    EXPECT_NE(message.find("not allowed in a MIDI file"), std::string::npos) << message;
  }
  EXPECT_EQ(read_error(smf(0, kPpq, {track({0x00, 0xF8, 0x00, 0x90, 60, 100})})),
            "t.mid: track 1 at byte 23: illegal status byte 0xF8 (timing clock): system "
            "real-time messages are not allowed in a MIDI file");
}

TEST(MidiReader, DataBytesOutOfPlaceAreErrors) {
  EXPECT_EQ(read_error(smf(0, kPpq, {track({0x00, 60, 100})})),
            "t.mid: track 1 at byte 23: data byte 0x3C without a preceding status byte");
  EXPECT_EQ(read_error(smf(0, kPpq, {track({0x00, 0x90, 60, 0x90, 0x00})})),
            "t.mid: track 1 at byte 23: note-on event has 0x90 where a data byte (0x00-0x7F) "
            "belongs");
}

TEST(MidiReader, HeaderProblemsAreErrors) {
  EXPECT_EQ(read_error(bytes({'n', 'o', 't', ' ', 'a', ' ', 'm', 'i', 'd', 'i'})),
            "t.mid: at byte 0: not a MIDI file (it does not start with \"MThd\")");
  EXPECT_EQ(read_error(smf(3, kPpq, {})),
            "t.mid: at byte 8: unknown MIDI file format 3 (only 0, 1 and 2 exist)");
  EXPECT_EQ(read_error(smf(1, 0, {})), "t.mid: at byte 12: division of 0 ticks per quarter note");
  Bytes short_header = test::chunk("MThd", bytes({0, 1, 0, 0, 0}));
  append(short_header, bytes({0, 0, 0}));
  EXPECT_EQ(read_error(short_header), "t.mid: at byte 4: MThd chunk length 5 is less than 6");
}

TEST(MidiReader, UnknownChunksAndTrailingBytesAreSkipped) {
  Bytes file = header(1, 1, kPpq);
  append(file, chunk("Junk", bytes({'x', 'y', 'z'})));
  append(file, track({0x00, 0x90, 60, 100, 0x60, 0x80, 60, 0, 0x00, 0xFF, 0x2F, 0x00}));
  file.push_back(0x2A);  // as jazz-soft test-corrupt-file-extra-byte.mid
  const Score score = read_ok(file);
  EXPECT_EQ(score.notes.size(), 1u);
}

TEST(MidiReader, BytesAfterEndOfTrackInsideTheChunkAreIgnored) {
  const Score score = read_ok(smf(0, kPpq, {track({0x00, 0xFF, 0x2F, 0x00,
                                                   0x00, 0x90, 60, 100, 0xF8, 0xF8})}));
  EXPECT_TRUE(score.notes.empty());
}

TEST(MidiReader, PartsArePerTrackAndChannel) {
  const Score score = read_ok(smf(1, kPpq, {
      // Conductor: a program for channel 3 (index 2) that track 2 never sets itself.
      track({0x00, 0xFF, 0x03, 4, 'S', 'o', 'n', 'g',
             0x00, 0xC2, 40,
             0x00, 0xFF, 0x2F, 0x00}),
      track({0x00, 0xFF, 0x03, 5, 'P', 'i', 'a', 'n', 'o',
             0x00, 0xC0, 5,
             0x00, 0xC1, 11,
             0x0A, 0x90, 60, 100,     // ch 0 first note at 10: program 5
             0x00, 0x91, 48, 100,
             0x0A, 0xC0, 7,           // too late for the first note
             0x0A, 0x80, 60, 0,
             0x00, 0x81, 48, 0,
             0x00, 0xFF, 0x2F, 0x00}),
      track({0x00, 0x99, 36, 100,     // percussion, channel 10 to humans
             0x00, 0x92, 67, 100,
             0x60, 0x89, 36, 0,
             0x00, 0x82, 67, 0,
             0x00, 0xFF, 0x2F, 0x00})}));
  ASSERT_EQ(score.parts.size(), 4u);
  const Part& piano_right = score.parts[0];
  EXPECT_EQ(piano_right.id, "track1-ch0");
  EXPECT_EQ(piano_right.name, "Piano (ch 1)");
  EXPECT_EQ(piano_right.program, 5);
  EXPECT_EQ(piano_right.track, 1);
  EXPECT_EQ(piano_right.channel, 0);
  EXPECT_EQ(score.parts[1].id, "track1-ch1");
  EXPECT_EQ(score.parts[1].name, "Piano (ch 2)");
  EXPECT_EQ(score.parts[1].program, 11);
  EXPECT_EQ(score.parts[2].id, "track2-ch2");
  EXPECT_EQ(score.parts[2].name, "ch 3");
  EXPECT_EQ(score.parts[2].program, 40);
  EXPECT_FALSE(score.parts[2].percussion);
  EXPECT_EQ(score.parts[3].id, "track2-ch9");
  EXPECT_TRUE(score.parts[3].percussion);
  for (const Note& note : score.notes) {
    const Part& part = score.parts[static_cast<std::size_t>(note.part)];
    EXPECT_EQ(part.channel, note.channel);
  }
}

TEST(MidiReader, ProgramAtTheSameTickPrefersThePartsOwnTrack) {
  const Score score = read_ok(smf(1, kPpq, {
      track({0x00, 0xC0, 10, 0x00, 0x90, 60, 100, 0x60, 0x80, 60, 0}),
      track({0x00, 0xC0, 20, 0x00, 0x90, 62, 100, 0x60, 0x80, 62, 0}),
      track({0x00, 0x90, 64, 100, 0x60, 0x80, 64, 0})}));
  ASSERT_EQ(score.parts.size(), 3u);
  EXPECT_EQ(score.parts[0].program, 10);
  EXPECT_EQ(score.parts[1].program, 20);
  EXPECT_EQ(score.parts[2].program, 20);  // no change of its own: the later one in the file
}

TEST(MidiReader, SustainPedalBecomesSpans) {
  const Score score = read_ok(smf(1, kPpq, {
      track({0x00, 0xB0, 64, 127,
             0x00, 0x90, 60, 100,
             0x60, 0x80, 60, 0,
             0x00, 0xB0, 64, 0,       // lift at 96 ...
             0x00, 0xB0, 64, 127,     // ... and press again at once: a pedal change
             0x04, 0xB0, 64, 64,      // already down: nothing
             0x81, 0x00, 0xB0, 64, 10,  // lift at 228 (100 + 128)
             0x00, 0xB0, 64, 100,     // never lifted: ends with the track
             0x0C, 0xFF, 0x2F, 0x00}),
      // A pedal in a track without notes on its channel belongs to that channel's part.
      track({0x83, 0x00, 0xB0, 64, 127, 0x10, 0xB0, 64, 0})}));
  ASSERT_EQ(score.parts.size(), 1u);
  ASSERT_EQ(score.pedal_spans.size(), 4u);
  EXPECT_EQ(score.pedal_spans[0].onset_ticks, 0);
  EXPECT_EQ(score.pedal_spans[0].offset_ticks, 96);
  EXPECT_EQ(score.pedal_spans[1].onset_ticks, 96);
  EXPECT_EQ(score.pedal_spans[1].offset_ticks, 228);
  EXPECT_EQ(score.pedal_spans[2].onset_ticks, 228);
  EXPECT_EQ(score.pedal_spans[2].offset_ticks, 240);
  EXPECT_EQ(score.pedal_spans[3].onset_ticks, 384);
  EXPECT_EQ(score.pedal_spans[3].offset_ticks, 400);
  EXPECT_DOUBLE_EQ(score.pedal_spans[0].offset_s, 0.5);
}

TEST(MidiReader, SignaturesAndTexts) {
  const Score score = read_ok(smf(0, kPpq, {track({
      0x00, 0xFF, 0x58, 4, 6, 3, 24, 8,            // 6/8
      0x00, 0xFF, 0x59, 2, 0xFD, 1,                // 3 flats, minor
      0x00, 0xFF, 0x06, 5, 'V', 'e', 'r', 's', 'e',
      0x00, 0xFF, 0x05, 2, 'f', 0xE9,              // Latin-1 e acute
      0x00, 0xFF, 0x01, 3, 0xC3, 0xBC, 0x00,       // UTF-8 u umlaut, C string terminator
      0x00, 0xFF, 0x7F, 3, 0x00, 0x00, 0x41,       // sequencer-specific: ignored
      0x00, 0xFF, 0x54, 5, 0x60, 0, 0, 0, 0,       // SMPTE offset: parsed, ignored
      0x60, 0xFF, 0x58, 4, 2, 1, 24, 8,            // 2/2 at 96
      0x00, 0xFF, 0x2F, 0x00})}));
  ASSERT_EQ(score.time_signatures.size(), 2u);
  EXPECT_EQ(score.time_signatures[0].numerator, 6);
  EXPECT_EQ(score.time_signatures[0].denominator, 8);
  EXPECT_EQ(score.time_signatures[1].tick, 96);
  EXPECT_EQ(score.time_signatures[1].denominator, 2);
  ASSERT_EQ(score.key_signatures.size(), 1u);
  EXPECT_EQ(score.key_signatures[0].fifths, -3);
  EXPECT_TRUE(score.key_signatures[0].minor);
  ASSERT_EQ(score.texts.size(), 3u);
  EXPECT_EQ(score.texts[0].kind, TextKind::marker);
  EXPECT_EQ(score.texts[0].text, "Verse");
  EXPECT_EQ(score.texts[0].track, 0);
  EXPECT_EQ(score.texts[1].kind, TextKind::lyric);
  EXPECT_EQ(score.texts[1].text, "f\xC3\xA9");
  EXPECT_EQ(score.texts[2].text, "\xC3\xBC");
  EXPECT_EQ(score.end_ticks, 96);
}

TEST(MidiReader, MalformedMetaEventsAreErrors) {
  EXPECT_EQ(read_error(smf(0, kPpq, {track({0x00, 0xFF, 0x51, 2, 0x07, 0xA1})})),
            "t.mid: track 1 at byte 23: tempo meta event needs 3 data bytes, has 2");
  EXPECT_EQ(read_error(smf(0, kPpq, {track({0x00, 0xFF, 0x51, 3, 0, 0, 0})})),
            "t.mid: track 1 at byte 23: tempo meta event of 0 microseconds per quarter note");
  EXPECT_EQ(read_error(smf(0, kPpq, {track({0x00, 0xFF, 0x59, 2, 8, 0})})),
            "t.mid: track 1 at byte 23: key signature meta event with 8 fifths (-7..7 exist)");
  EXPECT_EQ(read_error(smf(0, kPpq, {track({0x00, 0xFF, 0x58, 4, 0, 2, 24, 8})})),
            "t.mid: track 1 at byte 23: time signature meta event with numerator 0");
}

TEST(MidiReader, SourceIndexCountsSoundingNoteOnsInFileOrder) {
  const Score score = read_ok(smf(1, kPpq, {
      track({0x60, 0x90, 70, 100, 0x60, 0x90, 70, 0}),
      track({0x00, 0x90, 60, 0,        // velocity 0: a note-off, not counted
             0x00, 0x90, 60, 100, 0x60, 0x80, 60, 0})}));
  ASSERT_EQ(score.notes.size(), 2u);
  EXPECT_EQ(score.notes[0].pitch, 60);
  EXPECT_EQ(score.notes[0].source_index, 1);
  EXPECT_EQ(score.notes[1].pitch, 70);
  EXPECT_EQ(score.notes[1].source_index, 0);
}

TEST(MidiReader, EndTicksIsTheLastEventOfAnyKind) {
  const Score score = read_ok(smf(1, kPpq, {
      track({0x00, 0x90, 60, 100, 0x60, 0x80, 60, 0, 0x83, 0x00, 0xFF, 0x2F, 0x00}),
      track({0x00, 0xFF, 0x2F, 0x00})}));
  EXPECT_EQ(score.end_ticks, 96 + 384);
  EXPECT_DOUBLE_EQ(score.duration_s(), 2.5);
}

TEST(MidiReader, RandomlyCorruptedFilesGiveAScoreOrAOneLineError) {
  // A cheap, deterministic cousin of tests/fuzz/fuzz_midi_reader.cpp that runs with every build
  // (under the sanitizers in the asan preset): flip, insert and drop bytes of a valid file.
  const Bytes original = smf(1, kPpq, {
      track({0x00, 0xFF, 0x51, 3, 0x07, 0xA1, 0x20, 0x00, 0xFF, 0x58, 4, 3, 2, 24, 8,
             0x00, 0xFF, 0x2F, 0x00}),
      track({0x00, 0xFF, 0x03, 2, 'R', 'H', 0x00, 0xC0, 5, 0x00, 0xB0, 64, 127,
             0x00, 0x90, 60, 100, 0x00, 64, 90, 0x60, 60, 0, 0x00, 0xF0, 2, 0x01, 0xF7,
             0x10, 64, 0, 0x81, 0x00, 0xB0, 64, 0, 0x00, 0xFF, 0x2F, 0x00})});
  std::mt19937 random(20240601);
  for (int round = 0; round < 3000; ++round) {
    Bytes file = original;
    const int edits = 1 + static_cast<int>(random() % 4);
    for (int e = 0; e < edits && !file.empty(); ++e) {
      const std::size_t at = random() % file.size();
      switch (random() % 3) {
        case 0: file[at] = static_cast<std::uint8_t>(random()); break;
        case 1: file.insert(file.begin() + static_cast<std::ptrdiff_t>(at),
                            static_cast<std::uint8_t>(random())); break;
        default: file.erase(file.begin() + static_cast<std::ptrdiff_t>(at)); break;
      }
    }
    auto score = read_midi(file, "t.mid");
    if (score.ok()) {
      for (const Note& note : score->notes) {
        ASSERT_LE(note.onset_ticks, note.offset_ticks);
        ASSERT_LT(static_cast<std::size_t>(note.part), score->parts.size());
      }
    } else {
      ASSERT_EQ(score.error().message.rfind("t.mid: ", 0), 0u);
      ASSERT_EQ(score.error().message.find('\n'), std::string::npos);
    }
  }
}

TEST(MidiReader, SourceNameIsKept) {
  auto score = read_midi(simple_song(), "songs/a.mid");
  ASSERT_TRUE(score.ok());
  EXPECT_EQ(score->source, "songs/a.mid");
}

TEST(MidiReader, MissingFileIsAnError) {
  auto score = read_midi_file("/nonexistent/dir/x.mid");
  ASSERT_FALSE(score.ok());
  EXPECT_EQ(score.error().message.rfind("/nonexistent/dir/x.mid", 0), 0u);
}

}  // namespace
}  // namespace tutti::music
// clang-format on
