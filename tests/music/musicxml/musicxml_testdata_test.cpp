// SPDX-License-Identifier: MIT
// The reader against third-party files: the Unofficial MusicXML Test Suite (one feature per
// file), music21's Bach chorales and Clara Schumann polonaises, and pianoplayer's piano scores.
// Expected values were worked out from the XML by hand (and a separate xml.etree script).

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <tutti/music/musicxml/musicxml_reader.hpp>
#include "musicxml_test_support.hpp"
#include "testdata.hpp"

namespace tutti::music {
namespace {

namespace fs = std::filesystem;
using test::notes_of_part;

Score read_suite_file(const std::string& relative) {
  const auto score = read_musicxml_file(test::testdata("musicxml/" + relative));
  EXPECT_TRUE(score.ok()) << score.error().message;
  return score.ok() ? *score : Score{};
}

Score lilypond(const std::string& name) { return read_suite_file("lilypond-test-suite/" + name); }

std::vector<int> pitches(const std::vector<Note>& notes) {
  std::vector<int> out;
  for (const Note& note : notes) out.push_back(note.pitch);
  return out;
}

std::vector<std::int64_t> onsets(const std::vector<Note>& notes) {
  std::vector<std::int64_t> out;
  for (const Note& note : notes) out.push_back(note.onset_ticks);
  return out;
}

// Notes in document order (finalize_score sorts by onset, then pitch).
std::vector<Note> in_document_order(const Score& score) {
  std::vector<Note> notes = score.notes;
  std::sort(notes.begin(), notes.end(),
            [](const Note& a, const Note& b) { return a.source_index < b.source_index; });
  return notes;
}

void expect_every_file_reads(const std::string& folder) {
  int files = 0;
  for (const auto& entry : fs::directory_iterator(test::testdata("musicxml/" + folder))) {
    const std::string extension = entry.path().extension().string();
    if (extension != ".xml" && extension != ".mxl" && extension != ".musicxml") continue;
    ++files;
    const auto score = read_musicxml_file(entry.path());
    ASSERT_TRUE(score.ok()) << score.error().message;
    EXPECT_FALSE(score->parts.empty()) << entry.path();
    for (const Note& note : score->notes) {
      EXPECT_GE(note.offset_ticks, note.onset_ticks) << entry.path();
      EXPECT_GE(note.onset_ticks, 0) << entry.path();
      EXPECT_LE(note.offset_ticks, score->end_ticks) << entry.path();
      EXPECT_GE(note.source_index, 0) << entry.path();
    }
  }
  EXPECT_GT(files, 0) << folder;
}

TEST(MusicXmlTestdataTest, EveryTestSuiteFileReads) {
  TUTTI_REQUIRE_TESTDATA();
  expect_every_file_reads("lilypond-test-suite");
}

TEST(MusicXmlTestdataTest, EveryMusic21AndPianoplayerFileReads) {
  TUTTI_REQUIRE_TESTDATA();
  expect_every_file_reads("music21");
  expect_every_file_reads("pianoplayer");
}

TEST(MusicXmlTestdataTest, PitchesComeOutExactly) {
  TUTTI_REQUIRE_TESTDATA();
  const Score score = lilypond("01a-Pitches-Pitches.xml");
  // G2..C7 plain, sharpened, flattened, then naturals, double alterations and cautionaries.
  const std::vector<int> expected = {
      43, 45, 47, 48, 50, 52, 53, 55, 57, 59, 60, 62, 64, 65, 67, 69, 71, 72, 74, 76, 77, 79,
      81, 83, 84, 86, 88, 89, 91, 93, 95, 96, 44, 46, 48, 49, 51, 53, 54, 56, 58, 60, 61, 63,
      65, 66, 68, 70, 72, 73, 75, 77, 78, 80, 82, 84, 85, 87, 89, 90, 92, 94, 96, 97, 42, 44,
      46, 47, 49, 51, 52, 54, 56, 58, 59, 61, 63, 64, 66, 68, 70, 71, 73, 75, 76, 78, 80, 82,
      83, 85, 87, 88, 90, 92, 94, 95, 64, 65, 67, 69, 71, 72, 74, 76, 74, 70, 73, 73, 73, 73};
  EXPECT_EQ(pitches(score.notes), expected);
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    EXPECT_EQ(score.notes[i].onset_ticks, static_cast<std::int64_t>(i) * 480);
    EXPECT_EQ(score.notes[i].source_index, static_cast<int>(i));
  }
  EXPECT_EQ(score.end_ticks, 110 * 480);
  EXPECT_DOUBLE_EQ(score.end_s, 55.0);
}

TEST(MusicXmlTestdataTest, MicrotonesRound) {
  TUTTI_REQUIRE_TESTDATA();
  // 01d: C4 -1.5, D4 -0.5, E4 +0.5, F4 +1.5 (then an octave up), rounded half away from 0.
  const Score score = lilypond("01d-Pitches-Microtones.xml");
  EXPECT_EQ(pitches(in_document_order(score)), (std::vector<int>{58, 61, 65, 67, 70, 73, 77, 79}));
}

TEST(MusicXmlTestdataTest, Chords) {
  TUTTI_REQUIRE_TESTDATA();
  const Score score = lilypond("21b-Chords-TwoNotes.xml");
  ASSERT_EQ(score.notes.size(), 16u);
  ASSERT_EQ(score.tempo_map.ticks_per_quarter(), 960);
  for (std::size_t i = 0; i < 16; ++i) {
    EXPECT_EQ(score.notes[i].pitch, i % 2 == 0 ? 65 : 69);  // F4 + A4 quarters
    EXPECT_EQ(score.notes[i].onset_ticks, static_cast<std::int64_t>(i / 2) * 960);
    EXPECT_EQ(score.notes[i].offset_ticks, static_cast<std::int64_t>(i / 2 + 1) * 960);
  }
  // 21c: chord notes of different durations start together.
  const Score mixed = lilypond("21c-Chords-ThreeNotesDuration.xml");
  ASSERT_GE(mixed.notes.size(), 3u);
  EXPECT_EQ(pitches({mixed.notes.begin(), mixed.notes.begin() + 3}),
            (std::vector<int>{65, 69, 72}));
  for (int i = 0; i < 3; ++i) EXPECT_EQ(mixed.notes[i].offset_ticks, 1440);
}

TEST(MusicXmlTestdataTest, BackupStartsTheSecondVoiceMidMeasure) {
  TUTTI_REQUIRE_TESTDATA();
  const Score score = lilypond("03b-Rhythm-Backup.xml");
  const auto notes = in_document_order(score);
  ASSERT_EQ(notes.size(), 4u);
  EXPECT_EQ(pitches(notes), (std::vector<int>{60, 60, 57, 57}));
  EXPECT_EQ(onsets(notes), (std::vector<std::int64_t>{0, 480, 480, 960}));
  EXPECT_EQ(notes[2].voice, 2);
}

TEST(MusicXmlTestdataTest, DivisionChangesMidPart) {
  TUTTI_REQUIRE_TESTDATA();
  // divisions 1, then 8, then 38: ppq = lcm(480, 8, 38) = 9120.
  const Score score = lilypond("03c-Rhythm-DivisionChange.xml");
  ASSERT_EQ(score.tempo_map.ticks_per_quarter(), 9120);
  EXPECT_EQ(onsets(score.notes), (std::vector<std::int64_t>{0, 9120, 18240, 27360, 36480, 54720}));
  EXPECT_EQ(score.notes.back().offset_ticks, 72960);
  EXPECT_EQ(score.end_ticks, 72960);
}

TEST(MusicXmlTestdataTest, Ties) {
  TUTTI_REQUIRE_TESTDATA();
  const Score tie = lilypond("33b-Spanners-Tie.xml");
  ASSERT_EQ(tie.notes.size(), 1u);
  EXPECT_EQ(tie.notes[0].pitch, 65);
  EXPECT_EQ(tie.notes[0].offset_ticks, 2 * 1920);

  // 33i: a tie never stopped, a stop never started, then a proper one.
  const Score unended = lilypond("33i-Ties-NotEnded.xml");
  ASSERT_EQ(unended.notes.size(), 4u);
  EXPECT_EQ(onsets(unended.notes), (std::vector<std::int64_t>{0, 1920, 3840, 5760}));
  EXPECT_EQ(unended.notes[3].offset_ticks, 9600);
}

TEST(MusicXmlTestdataTest, GraceNotes) {
  TUTTI_REQUIRE_TESTDATA();
  const Score score = lilypond("24a-GraceNotes.xml");
  ASSERT_EQ(score.notes.size(), 28u);
  const auto notes = in_document_order(score);
  // An acciaccatura D5 takes a 32nd from the first C5.
  EXPECT_EQ(notes[0].pitch, 74);
  EXPECT_TRUE(notes[0].grace);
  EXPECT_EQ(notes[0].onset_ticks, 0);
  EXPECT_EQ(notes[0].offset_ticks, 60);
  EXPECT_EQ(notes[1].pitch, 72);
  EXPECT_FALSE(notes[1].grace);
  EXPECT_EQ(notes[1].onset_ticks, 60);
  EXPECT_EQ(notes[1].offset_ticks, 480);
  const auto graces =
      std::count_if(score.notes.begin(), score.notes.end(), [](const Note& n) { return n.grace; });
  EXPECT_EQ(graces, 15);
  // No note of a pitch starts before the previous note of that pitch in the voice ended.
  std::map<std::pair<int, int>, std::int64_t> sounding_until;
  for (const Note& note : score.notes) {
    auto& until = sounding_until[{note.voice, note.pitch}];
    EXPECT_GE(note.onset_ticks, until) << note.source_index;
    until = note.offset_ticks;
  }
}

TEST(MusicXmlTestdataTest, TempoFromSoundAndMetronome) {
  TUTTI_REQUIRE_TESTDATA();
  // Every voice of the chorale states <sound tempo="96"/> (only the trumpet here) at the start.
  const Score chorale = read_suite_file("music21/bwv69.6.xml");
  ASSERT_EQ(chorale.tempo_map.changes().size(), 1u);
  EXPECT_DOUBLE_EQ(chorale.tempo_map.changes()[0].bpm(), 96.0);

  const Score prelude = read_suite_file("pianoplayer/bach_prelude.xml");
  std::vector<double> bpms;
  for (const auto& change : prelude.tempo_map.changes()) bpms.push_back(change.bpm());
  EXPECT_EQ(bpms, (std::vector<double>{72, 66, 48, 30}));

  // 31c has metronome marks only: dotted quarter = 100 is 150 quarters a minute.
  const Score marks = lilypond("31c-MetronomeMarks.xml");
  ASSERT_GE(marks.tempo_map.changes().size(), 2u);
  EXPECT_DOUBLE_EQ(marks.tempo_map.changes()[0].bpm(), 150.0);
  EXPECT_DOUBLE_EQ(marks.tempo_map.changes().back().bpm(), 115.5);  // (dotted quarter = 77)
}

TEST(MusicXmlTestdataTest, TransposingInstrumentsSoundAtConcertPitch) {
  TUTTI_REQUIRE_TESTDATA();
  // Trumpet in Bb and horn in Eb written in D and A major; all three parts sound C major.
  const Score score = lilypond("72a-TransposingInstruments.xml");
  ASSERT_EQ(score.parts.size(), 3u);
  EXPECT_EQ(score.parts[0].name, "Trumpet in Bb");
  EXPECT_EQ(score.parts[0].transpose_semitones, -2);
  EXPECT_EQ(score.parts[1].name, "Horn in Eb");
  EXPECT_EQ(score.parts[1].transpose_semitones, -9);
  EXPECT_EQ(score.parts[2].transpose_semitones, 0);
  const std::vector<int> c_major = {60, 62, 64, 65, 67, 69, 71, 72};
  for (int part = 0; part < 3; ++part) EXPECT_EQ(pitches(notes_of_part(score, part)), c_major);
  ASSERT_EQ(score.key_signatures.size(), 1u);
  EXPECT_EQ(score.key_signatures[0].fifths, 0);

  // 72c: Eb clarinet (+3), then Bb clarinet (-2) from measure 2, both written C4.
  const Score change = lilypond("72c-TransposingInstruments-Change.xml");
  EXPECT_EQ(pitches(change.notes), (std::vector<int>{63, 58, 58}));
  EXPECT_EQ(change.parts[0].transpose_semitones, 3);
}

TEST(MusicXmlTestdataTest, MultipleStaves) {
  TUTTI_REQUIRE_TESTDATA();
  const Score piano = lilypond("43a-PianoStaff.xml");
  ASSERT_EQ(piano.parts.size(), 1u);
  EXPECT_EQ(piano.parts[0].staves, 2);
  const auto notes = in_document_order(piano);
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_EQ(notes[0].pitch, 65);
  EXPECT_EQ(notes[0].staff, 1);
  EXPECT_EQ(notes[1].pitch, 47);
  EXPECT_EQ(notes[1].staff, 2);
  EXPECT_EQ(notes[1].onset_ticks, 0);

  // 43d: one voice moving between the staves.
  const Score change = lilypond("43d-MultiStaff-StaffChange.xml");
  const auto moving = in_document_order(change);
  ASSERT_GE(moving.size(), 2u);
  EXPECT_EQ(moving[0].staff, 2);
  EXPECT_EQ(moving[1].staff, 1);
}

TEST(MusicXmlTestdataTest, VoicesAndParts) {
  TUTTI_REQUIRE_TESTDATA();
  const Score two_voices = lilypond("42a-MultiVoice-TwoVoicesOnStaff-Lyrics.xml");
  std::vector<int> upper;
  std::vector<int> lower;
  for (const Note& note : two_voices.notes) (note.voice == 1 ? upper : lower).push_back(note.pitch);
  EXPECT_EQ(upper, (std::vector<int>{76, 74, 71, 74, 59, 72}));
  EXPECT_EQ(lower, (std::vector<int>{72, 71, 67, 71, 55, 69}));

  const Score four_parts = lilypond("41a-MultiParts-Partorder.xml");
  ASSERT_EQ(four_parts.parts.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(four_parts.parts[i].id, "P" + std::to_string(i));
    EXPECT_EQ(four_parts.parts[i].name, "Part " + std::to_string(i + 1));
    ASSERT_EQ(notes_of_part(four_parts, i).size(), 1u);
  }
  EXPECT_EQ(notes_of_part(four_parts, 3)[0].pitch, 71);

  // 41g: a <part> without id still finds its <score-part>.
  const Score no_id = lilypond("41g-PartNoId.xml");
  ASSERT_EQ(no_id.parts.size(), 1u);
  EXPECT_EQ(no_id.parts[0].id, "P1");
}

TEST(MusicXmlTestdataTest, PickupAndImplicitMeasuresAreNotPadded) {
  TUTTI_REQUIRE_TESTDATA();
  // A 3/8 pickup, a 2/4 measure split by an implicit measure, an incomplete 3/4 measure.
  const Score score = lilypond("46d-PickupMeasure-ImplicitMeasures.xml");
  EXPECT_EQ(onsets(score.notes),
            (std::vector<std::int64_t>{0, 480, 720, 1200, 1680, 2160, 2640, 3120}));
  EXPECT_EQ(score.end_ticks, 4080);
}

TEST(MusicXmlTestdataTest, FingeringMarks) {
  TUTTI_REQUIRE_TESTDATA();
  const Score scales = read_suite_file("pianoplayer/test_scales_all_keys.xml");
  std::map<int, std::pair<int, int>> fingered;  // source_index -> (pitch, finger)
  for (const Note& note : scales.notes) {
    if (note.finger > 0) fingered[note.source_index] = {note.pitch, note.finger};
  }
  EXPECT_EQ(fingered.size(), 24u);
  EXPECT_EQ(fingered[0], std::make_pair(60, 1));
  EXPECT_EQ(fingered[15], std::make_pair(67, 1));
  EXPECT_EQ(fingered[90], std::make_pair(66, 2));
  EXPECT_EQ(fingered[135], std::make_pair(70, 4));
  EXPECT_EQ(fingered[345], std::make_pair(65, 4));

  const Score polonaise = read_suite_file("music21/polonaise_op1n1.mxl");
  std::map<int, std::pair<int, int>> marks;
  for (const Note& note : polonaise.notes) {
    if (note.finger > 0) marks[note.source_index] = {note.pitch, note.finger};
  }
  EXPECT_EQ(marks.size(), 14u);
  EXPECT_EQ(marks[567], std::make_pair(70, 2));
  EXPECT_EQ(marks[582], std::make_pair(73, 5));
  EXPECT_EQ(marks[863], std::make_pair(69, 1));
}

TEST(MusicXmlTestdataTest, BachChoralesWithTrumpets) {
  TUTTI_REQUIRE_TESTDATA();
  const Score bwv69 = read_suite_file("music21/bwv69.6.xml");
  std::vector<std::string> names;
  for (const Part& part : bwv69.parts) names.push_back(part.name);
  EXPECT_EQ(names, (std::vector<std::string>{"Trumpet 1", "Trumpet 2", "Trumpet 3", "Timpani",
                                             "Soprano", "Alto", "Tenor", "Bass"}));
  for (const Part& part : bwv69.parts) {
    EXPECT_EQ(part.transpose_semitones, 0) << part.name;  // the trumpets are written in C
    EXPECT_EQ(part.program, 0);                           // midi-program 1
  }
  EXPECT_EQ(bwv69.parts[0].channel, 5);  // midi-channel 6
  EXPECT_EQ(bwv69.parts[4].channel, 0);
  ASSERT_EQ(bwv69.key_signatures.size(), 1u);
  EXPECT_EQ(bwv69.key_signatures[0].fifths, 2);
  // The first trumpet enters in measure 2 (after a quarter pickup and a full bar) on A5.
  const auto trumpet = notes_of_part(bwv69, 0);
  ASSERT_FALSE(trumpet.empty());
  EXPECT_EQ(trumpet[0].pitch, 81);
  EXPECT_EQ(trumpet[0].onset_ticks, 480 + 1920 + 480);

  const Score bwv29 = read_suite_file("music21/bwv29.8.mxl");
  ASSERT_EQ(bwv29.parts.size(), 8u);
  EXPECT_EQ(bwv29.parts[0].name, "Trumpet 1");
  EXPECT_EQ(bwv29.parts[2].name, "Trumpet 3");
  EXPECT_EQ(bwv29.parts[7].name, "Timpani");
  for (const Part& part : bwv29.parts) EXPECT_EQ(part.transpose_semitones, 0);
  ASSERT_EQ(bwv29.time_signatures.size(), 1u);
  EXPECT_EQ(bwv29.time_signatures[0].numerator, 3);
}

TEST(MusicXmlTestdataTest, CompressedTestSuiteFile) {
  TUTTI_REQUIRE_TESTDATA();
  const Score score = lilypond("90a-Compressed-MusicXML.mxl");
  EXPECT_EQ(score.notes.size(), 4u);
}

}  // namespace
}  // namespace tutti::music
