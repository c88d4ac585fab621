// SPDX-License-Identifier: MIT
// The reader against third-party files (../shared/testdata/midi), checked against an independent
// reading by the python library mido, recorded in tests/data/midi/mido_expected.json by
// tests/data/midi/make_expected_mido.py (the test never runs python).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>

#include <tutti/music/midi/midi_reader.hpp>
#include <tutti/music/midi/midi_writer.hpp>
#include "score_compare.hpp"
#include "testdata.hpp"

namespace tutti::music {
namespace {

// The files our reader rejects, with the reasons, are listed in tests/data/broken_files.txt
// (shared with the CLI test, tests/app/tutti_cli_test.sh).
const std::set<std::string> kRejected = test::broken_testdata_files("midi/");

// Where mido (1.2.10) and we disagree on validity, and why we believe we are right.
const std::map<std::string, std::string> kMidoDisagrees = {
    // mido rejects, we accept:
    {"midi/jazz-soft/test-non-midi-track.mid",
     "mido reads the header's track count of chunks and requires each to be MTrk; the SMF "
     "specification tells readers to skip chunk types they do not know, and the file says "
     "\"Players should ignore it\""},
    {"midi/jazz-soft/test-running-status-sysex.mid",
     "mido lets the sysex event become the running status (0xF0), so the next data byte is read "
     "as a sysex length and the track runs off its end; the file expects the note-on running "
     "status to carry on after the sysex (\"You must hear a C-Major scale\"), as players do"},
    // mido accepts, we reject (see kRejected): it knows F1, F2, F3, F6, F8, FA, FB, FC and FE as
    // wire messages and reads them as if they could stand in a track.
    {"midi/jazz-soft/test-illegal-message-f1-xx.mid", "system common message in a track"},
    {"midi/jazz-soft/test-illegal-message-f2-xx-xx.mid", "system common message in a track"},
    {"midi/jazz-soft/test-illegal-message-f3-xx.mid", "system common message in a track"},
    {"midi/jazz-soft/test-illegal-message-f6.mid", "system common message in a track"},
    {"midi/jazz-soft/test-illegal-message-f8.mid", "system real-time message in a track"},
    {"midi/jazz-soft/test-illegal-message-fa.mid", "system real-time message in a track"},
    {"midi/jazz-soft/test-illegal-message-fb.mid", "system real-time message in a track"},
    {"midi/jazz-soft/test-illegal-message-fc.mid", "system real-time message in a track"},
    {"midi/jazz-soft/test-illegal-message-fe.mid", "system real-time message in a track"},
};

// Notes of files mido cannot read, counted by hand from the bytes: eight-note C major scales.
const std::map<std::string, std::size_t> kNotesWithoutMido = {
    {"midi/jazz-soft/test-non-midi-track.mid", 8},
    {"midi/jazz-soft/test-running-status-sysex.mid", 8},
};

struct MidoView {
  bool ok = false;
  std::size_t notes = 0;
  std::optional<double> length;
};

std::map<std::string, MidoView> load_mido_expectations() {
  std::ifstream in(test::source_dir() / "tests/data/midi/mido_expected.json");
  std::map<std::string, MidoView> views;
  if (!in) return views;
  const auto json = nlohmann::json::parse(in);
  for (const auto& [file, entry] : json.at("files").items()) {
    MidoView view;
    view.ok = entry.at("ok").get<bool>();
    if (view.ok) view.notes = entry.at("notes").get<std::size_t>();
    if (!entry.at("length").is_null()) view.length = entry.at("length").get<double>();
    views[file] = view;
  }
  return views;
}

std::set<std::string> midi_files_on_disk() {
  std::set<std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(test::testdata("midi"))) {
    const auto extension = entry.path().extension();
    if (entry.is_regular_file() && (extension == ".mid" || extension == ".midi")) {
      files.insert(entry.path().lexically_relative(test::testdata_dir()).generic_string());
    }
  }
  return files;
}

// The structural promises of the score model, for any file the reader accepts.
void expect_consistent(const std::string& file, const Score& score) {
  SCOPED_TRACE(file);
  std::set<std::string> ids;
  for (const Part& part : score.parts) {
    EXPECT_TRUE(ids.insert(part.id).second) << "duplicate part id " << part.id;
    EXPECT_EQ(part.id, "track" + std::to_string(part.track) + "-ch" + std::to_string(part.channel));
    EXPECT_GE(part.channel, 0);
    EXPECT_LE(part.channel, 15);
    EXPECT_EQ(part.percussion, part.channel == 9);
    EXPECT_GE(part.program, 0);
    EXPECT_LE(part.program, 127);
  }
  std::vector<int> notes_per_part(score.parts.size(), 0);
  std::vector<bool> seen_source(score.notes.size(), false);
  for (const Note& note : score.notes) {
    EXPECT_GE(note.pitch, 0);
    EXPECT_LE(note.pitch, 127);
    EXPECT_GE(note.velocity, 1);
    EXPECT_LE(note.velocity, 127);
    EXPECT_LE(note.onset_ticks, note.offset_ticks);
    EXPECT_LE(note.onset_s, note.offset_s);
    EXPECT_LE(note.offset_ticks, score.end_ticks);
    ASSERT_GE(note.part, 0);
    ASSERT_LT(static_cast<std::size_t>(note.part), score.parts.size());
    ++notes_per_part[static_cast<std::size_t>(note.part)];
    EXPECT_EQ(score.parts[static_cast<std::size_t>(note.part)].channel, note.channel);
    ASSERT_GE(note.source_index, 0);
    ASSERT_LT(static_cast<std::size_t>(note.source_index), score.notes.size());
    EXPECT_FALSE(seen_source[static_cast<std::size_t>(note.source_index)]);
    seen_source[static_cast<std::size_t>(note.source_index)] = true;
  }
  for (int count : notes_per_part) EXPECT_GT(count, 0) << "a part without notes";
  EXPECT_TRUE(
      std::is_sorted(score.notes.begin(), score.notes.end(),
                     [](const Note& a, const Note& b) { return a.onset_ticks < b.onset_ticks; }));
  for (const PedalSpan& pedal : score.pedal_spans) {
    EXPECT_GE(pedal.part, 0);
    EXPECT_LT(static_cast<std::size_t>(pedal.part), score.parts.size());
    EXPECT_LT(pedal.onset_ticks, pedal.offset_ticks);
  }
  EXPECT_GE(score.duration_s(), 0.0);
}

TEST(MidiTestdata, EveryFileMatchesMidoOrIsAKnownDisagreement) {
  TUTTI_REQUIRE_TESTDATA();
  const auto mido = load_mido_expectations();
  ASSERT_FALSE(mido.empty()) << "tests/data/midi/mido_expected.json is missing or empty";
  const auto on_disk = midi_files_on_disk();
  for (const auto& file : on_disk) {
    EXPECT_TRUE(mido.count(file)) << file << " is not in mido_expected.json: regenerate it";
  }

  std::set<std::string> rejected;
  for (const auto& [file, view] : mido) {
    SCOPED_TRACE(file);
    ASSERT_TRUE(on_disk.count(file)) << "listed in mido_expected.json but not on disk";
    const auto path = test::testdata(file);
    auto score = read_midi_file(path);

    const bool mido_agrees = view.ok == score.ok();
    EXPECT_EQ(mido_agrees, !kMidoDisagrees.count(file))
        << "mido " << (view.ok ? "accepts" : "rejects") << " it, we "
        << (score.ok() ? "accept" : "reject") << " it";

    if (!score.ok()) {
      rejected.insert(file);
      const std::string& message = score.error().message;
      EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      continue;
    }
    expect_consistent(file, *score);
    if (!view.ok) {
      EXPECT_EQ(score->notes.size(), kNotesWithoutMido.at(file));
      continue;
    }
    // mido counts note_on messages with velocity > 0; each of them is exactly one Note.
    EXPECT_EQ(score->notes.size(), view.notes);
    if (view.length) {
      const double tolerance = std::max(1e-6 * *view.length, 1e-9);
      EXPECT_NEAR(score->duration_s(), *view.length, tolerance);
    }
  }
  EXPECT_EQ(rejected, kRejected);
}

TEST(MidiTestdata, RejectionsNameFileTrackAndByte) {
  TUTTI_REQUIRE_TESTDATA();
  const auto check = [](const std::string& file, const std::string& expected_tail) {
    const auto path = test::testdata("midi/jazz-soft/" + file);
    auto score = read_midi_file(path);
    ASSERT_FALSE(score.ok()) << file;
    EXPECT_EQ(score.error().message, path.string() + ": " + expected_tail);
  };
  check("test-corrupt-file-missing-byte.mid",
        "track 1 at byte 14: chunk length 246 runs past the end of the file (245 bytes left)");
  check("test-illegal-message-f1-xx.mid",
        "track 1 at byte 216: illegal status byte 0xF1 (MIDI time code quarter frame): system "
        "common messages are not allowed in a MIDI file");
  check("test-empty-file.mid", "empty file (0 bytes), not a MIDI file");
  check("test-not-a-midi-file.mid", "at byte 0: not a MIDI file (it does not start with \"MThd\")");
}

TEST(MidiTestdata, AcceptedEdgeCasesReadAsTheirAuthorsIntend) {
  TUTTI_REQUIRE_TESTDATA();
  // Both spell out "You must hear a C-Major scale".
  for (const char* file : {"test-running-status-sysex.mid", "test-running-status-metaevent.mid",
                           "test-non-midi-track.mid", "test-corrupt-file-extra-byte.mid"}) {
    SCOPED_TRACE(file);
    auto score = read_midi_file(test::testdata(std::string{"midi/jazz-soft/"} + file));
    ASSERT_TRUE(score.ok()) << score.error().message;
    std::vector<int> pitches;
    for (const Note& note : score->notes) pitches.push_back(note.pitch);
    EXPECT_EQ(pitches, (std::vector<int>{60, 62, 64, 65, 67, 69, 71, 72}));
  }
  auto format2 = read_midi_file(test::testdata("midi/jazz-soft/test-2-tracks-type-2.mid"));
  ASSERT_TRUE(format2.ok());
  ASSERT_EQ(format2->notes.size(), 16u);
  // "Two scales in two tracks must play sequentially."
  EXPECT_GE(format2->notes[8].onset_ticks, format2->notes[7].offset_ticks);
  EXPECT_NE(format2->notes[8].part, format2->notes[7].part);
}

TEST(MidiTestdata, EveryValidFileSurvivesAWriterRoundTrip) {
  TUTTI_REQUIRE_TESTDATA();
  for (const auto& file : midi_files_on_disk()) {
    auto score = read_midi_file(test::testdata(file));
    if (!score.ok()) continue;
    SCOPED_TRACE(file);
    auto back = read_midi(write_midi(*score), file + " (written)");
    ASSERT_TRUE(back.ok()) << back.error().message;
    test::expect_same_music(*score, *back);
  }
}

}  // namespace
}  // namespace tutti::music
