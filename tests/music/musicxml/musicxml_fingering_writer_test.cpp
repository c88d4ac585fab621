// SPDX-License-Identifier: MIT
#include <tutti/music/musicxml/musicxml_fingering_writer.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <tutti/core/file_io.hpp>
#include <tutti/music/musicxml/musicxml_reader.hpp>
#include "musicxml_test_support.hpp"
#include "testdata.hpp"

namespace tutti::music {
namespace {

namespace fs = std::filesystem;
using test::bytes_of;
using test::divisions;
using test::measure;
using test::one_part_score;
using test::pitched;
using test::read_xml;

std::string file_text(const fs::path& path) {
  auto bytes = read_file_bytes(path);
  EXPECT_TRUE(bytes.ok()) << bytes.error().message;
  if (!bytes) return {};
  return std::string(bytes->begin(), bytes->end());
}

// A score whose notes with these source indices carry these fingers.
Score fingers_on(const Score& read, const std::map<int, std::pair<int, int>>& fingers) {
  Score fingered = read;
  for (Note& note : fingered.notes) {
    note.finger = 0;
    note.finger_substitute = 0;
    if (auto it = fingers.find(note.source_index); it != fingers.end()) {
      note.finger = it->second.first;
      note.finger_substitute = it->second.second;
    }
  }
  return fingered;
}

Result<std::string> annotate(const std::string& xml, const Score& fingered,
                             const std::string& name = "t.musicxml") {
  return add_fingering_marks(bytes_of(xml), name, fingered);
}

void expect_same_music(const Score& a, const Score& b) {
  ASSERT_EQ(a.notes.size(), b.notes.size());
  for (std::size_t i = 0; i < a.notes.size(); ++i) {
    EXPECT_EQ(a.notes[i].pitch, b.notes[i].pitch) << i;
    EXPECT_EQ(a.notes[i].onset_ticks, b.notes[i].onset_ticks) << i;
    EXPECT_EQ(a.notes[i].offset_ticks, b.notes[i].offset_ticks) << i;
    EXPECT_EQ(a.notes[i].source_index, b.notes[i].source_index) << i;
  }
  EXPECT_EQ(a.end_ticks, b.end_ticks);
}

TEST(MusicXmlFingeringWriterTest, NoFingersGivesTheInputBackByteForByte) {
  TUTTI_REQUIRE_TESTDATA();
  for (const char* name :
       {"lilypond-test-suite/01a-Pitches-Pitches.xml", "lilypond-test-suite/32a-Notations.xml",
        "lilypond-test-suite/51b-Header-Quotes.xml",
        "lilypond-test-suite/99a-Sibelius5-IgnoreBeaming.xml", "music21/bwv69.6.xml",
        "pianoplayer/pachelbel_canon.xml"}) {
    const std::string original = file_text(test::testdata(std::string("musicxml/") + name));
    const auto read = read_xml(original, name);
    ASSERT_TRUE(read.ok()) << read.error().message;
    const auto written = annotate(original, fingers_on(*read, {}), name);
    ASSERT_TRUE(written.ok()) << written.error().message;
    EXPECT_TRUE(*written == original) << name;
  }
}

TEST(MusicXmlFingeringWriterTest, AddedFingersReadBackAndEverythingElseIsUntouched) {
  TUTTI_REQUIRE_TESTDATA();
  const std::string original =
      file_text(test::testdata("musicxml/lilypond-test-suite/01a-Pitches-Pitches.xml"));
  const auto read = read_xml(original);
  ASSERT_TRUE(read.ok()) << read.error().message;
  const std::map<int, std::pair<int, int>> fingers = {
      {0, {1, 0}}, {7, {3, 0}}, {64, {5, 2}}, {109, {4, 0}}};
  const auto written = annotate(original, fingers_on(*read, fingers));
  ASSERT_TRUE(written.ok()) << written.error().message;

  const auto reread = read_xml(*written);
  ASSERT_TRUE(reread.ok()) << reread.error().message;
  expect_same_music(*read, *reread);
  for (const Note& note : reread->notes) {
    const auto it = fingers.find(note.source_index);
    EXPECT_EQ(note.finger, it == fingers.end() ? 0 : it->second.first) << note.source_index;
    EXPECT_EQ(note.finger_substitute, it == fingers.end() ? 0 : it->second.second);
  }

  // Outside the edited notes the bytes are the original's: the text before the first <note>
  // and after the last edited one, and the growth is exactly the new marks.
  const std::size_t first_note = original.find("<note>");
  EXPECT_EQ(written->compare(0, first_note, original, 0, first_note), 0);
  const std::size_t tail = original.size() - original.rfind("</note>");
  EXPECT_EQ(written->compare(written->size() - tail, tail, original, original.size() - tail, tail),
            0);
  const std::string mark = "<notations><technical><fingering>1</fingering></technical></notations>";
  EXPECT_NE(written->find("<type>quarter</type>\n        " + mark + "\n      </note>"),
            std::string::npos)
      << "the new notations should sit on their own line after <type>";
  EXPECT_NE(written->find("<fingering>5</fingering><fingering substitution=\"yes\">2</fingering>"),
            std::string::npos);
}

TEST(MusicXmlFingeringWriterTest, RewrittenNotesDifferOnlyByTheNewMarks) {
  TUTTI_REQUIRE_TESTDATA();
  // Every note of 01a gets a finger, so every <note> goes through the serializer; taking the
  // new marks out again must give the original bytes.
  const std::string original =
      file_text(test::testdata("musicxml/lilypond-test-suite/01a-Pitches-Pitches.xml"));
  const auto read = read_xml(original);
  ASSERT_TRUE(read.ok()) << read.error().message;
  std::map<int, std::pair<int, int>> all;
  for (const Note& note : read->notes) all[note.source_index] = {1 + note.source_index % 5, 0};
  const auto written = annotate(original, fingers_on(*read, all));
  ASSERT_TRUE(written.ok()) << written.error().message;
  std::string stripped = *written;
  int removed = 0;
  for (int finger = 1; finger <= 5; ++finger) {
    const std::string mark = "\n        <notations><technical><fingering>" +
                             std::to_string(finger) + "</fingering></technical></notations>";
    for (std::size_t at = stripped.find(mark); at != std::string::npos; at = stripped.find(mark)) {
      stripped.erase(at, mark.size());
      ++removed;
    }
  }
  EXPECT_EQ(removed, 110);
  EXPECT_TRUE(stripped == original);
}

TEST(MusicXmlFingeringWriterTest, NotationsGoWhereTheSchemaPutsThem) {
  const std::string xml = one_part_score(
      measure(divisions(1) +
              pitched("C", 4, 1,
                      "<voice>1</voice><type>quarter</type><stem>up</stem><beam number=\"1\">"
                      "begin</beam><lyric><text>la</text></lyric><play/>") +
              pitched("D", 4, 1,
                      "<notations><slur type=\"start\"/></notations><lyric><text>la</text>"
                      "</lyric>") +
              pitched("E", 4, 1, "<notations><technical><up-bow/></technical></notations>")));
  const auto read = read_xml(xml);
  ASSERT_TRUE(read.ok()) << read.error().message;
  const auto written = annotate(xml, fingers_on(*read, {{0, {2, 0}}, {1, {3, 0}}, {2, {4, 0}}}));
  ASSERT_TRUE(written.ok()) << written.error().message;
  EXPECT_NE(written->find("<beam number=\"1\">begin</beam><notations><technical><fingering>2"
                          "</fingering></technical></notations><lyric>"),
            std::string::npos)
      << *written;
  EXPECT_NE(written->find("<notations><slur type=\"start\"/><technical><fingering>3</fingering>"
                          "</technical></notations><lyric>"),
            std::string::npos)
      << *written;
  EXPECT_NE(written->find("<technical><up-bow/><fingering>4</fingering></technical>"),
            std::string::npos)
      << *written;
}

TEST(MusicXmlFingeringWriterTest, ExistingFingeringIsReplacedInPlace) {
  const std::string xml = one_part_score(
      measure(divisions(1) +
              pitched("C", 4, 1,
                      "<notations><technical><fingering placement='above'>2</fingering>"
                      "<fingering substitution=\"yes\">1</fingering></technical>"
                      "</notations>") +
              pitched("D", 4, 1,
                      "<notations><technical><fingering>3</fingering></technical></notations>")));
  const auto read = read_xml(xml);
  ASSERT_TRUE(read.ok()) << read.error().message;
  ASSERT_EQ(read->notes[0].finger, 2);
  ASSERT_EQ(read->notes[0].finger_substitute, 1);

  Score fingered = fingers_on(*read, {{0, {4, 0}}, {1, {5, 3}}});
  const auto written = annotate(xml, fingered);
  ASSERT_TRUE(written.ok()) << written.error().message;
  EXPECT_NE(written->find("<fingering placement='above'>4</fingering></technical>"),
            std::string::npos)
      << *written;
  EXPECT_NE(written->find("<fingering>5</fingering><fingering substitution=\"yes\">3</fingering>"),
            std::string::npos)
      << *written;
  const auto reread = read_xml(*written);
  ASSERT_TRUE(reread.ok()) << reread.error().message;
  EXPECT_EQ(reread->notes[0].finger, 4);
  EXPECT_EQ(reread->notes[0].finger_substitute, 0);
  EXPECT_EQ(reread->notes[1].finger, 5);
  EXPECT_EQ(reread->notes[1].finger_substitute, 3);
}

TEST(MusicXmlFingeringWriterTest, EditedNotesKeepTheirOriginalSpelling) {
  // Start tags are copied as written (single quotes, "<x />"); entities stay entities.
  const std::string xml =
      one_part_score(measure(
          divisions(1) + "<note id='say \"hi\" &amp; go'><pitch><step>C</step><octave>4</octave>"
                         "</pitch><duration>1</duration><stem  >up</stem><beam number = '1'></beam>"
                         "<lyric><text>Fish &amp; chips</text><extend /></lyric></note>"));
  const auto read = read_xml(xml);
  ASSERT_TRUE(read.ok()) << read.error().message;
  const auto written = annotate(xml, fingers_on(*read, {{0, {1, 0}}}));
  ASSERT_TRUE(written.ok()) << written.error().message;
  EXPECT_NE(written->find("<note id='say \"hi\" &amp; go'><pitch>"), std::string::npos) << *written;
  EXPECT_NE(written->find("<stem  >up</stem><beam number = '1'></beam><notations><technical>"
                          "<fingering>1</fingering></technical></notations><lyric><text>Fish "
                          "&amp; chips</text><extend /></lyric></note>"),
            std::string::npos)
      << *written;
  EXPECT_TRUE(read_xml(*written).ok());
}

TEST(MusicXmlFingeringWriterTest, ClassicMacLineEndingsSurvive) {
  TUTTI_REQUIRE_TESTDATA();
  // bwv69.6.xml ends its lines with a lone CR.
  const std::string original = file_text(test::testdata("musicxml/music21/bwv69.6.xml"));
  const auto read = read_xml(original);
  ASSERT_TRUE(read.ok()) << read.error().message;
  int pitched_index = -1;
  for (const Note& note : read->notes) {
    if (note.part == 0) {
      pitched_index = note.source_index;
      break;
    }
  }
  ASSERT_GE(pitched_index, 0);
  const auto written = annotate(original, fingers_on(*read, {{pitched_index, {3, 0}}}));
  ASSERT_TRUE(written.ok()) << written.error().message;
  // The file's only LF is inside a credit text; the rewritten note must not add any.
  EXPECT_EQ(std::count(written->begin(), written->end(), '\n'), 1);
  EXPECT_GT(std::count(written->begin(), written->end(), '\r'),
            std::count(original.begin(), original.end(), '\r'));
  const auto reread = read_xml(*written);
  ASSERT_TRUE(reread.ok()) << reread.error().message;
  expect_same_music(*read, *reread);
}

TEST(MusicXmlFingeringWriterTest, CompressedInputGivesUncompressedOutput) {
  TUTTI_REQUIRE_TESTDATA();
  const fs::path path = test::testdata("musicxml/music21/polonaise_op1n2.mxl");
  const auto read = read_musicxml_file(path);
  ASSERT_TRUE(read.ok()) << read.error().message;
  std::map<int, std::pair<int, int>> fingers;
  for (const Note& note : read->notes) {
    if (note.staff == 2 && fingers.size() < 5) fingers[note.source_index] = {5, 0};
  }
  const auto bytes = read_file_bytes(path);
  ASSERT_TRUE(bytes.ok());
  const auto written = add_fingering_marks(*bytes, path.string(), fingers_on(*read, fingers));
  ASSERT_TRUE(written.ok()) << written.error().message;
  EXPECT_EQ(written->rfind("<?xml", 0), 0u);
  const auto reread = read_xml(*written);
  ASSERT_TRUE(reread.ok()) << reread.error().message;
  expect_same_music(*read, *reread);
  int fives = 0;
  for (const Note& note : reread->notes) {
    if (fingers.count(note.source_index) != 0) {
      EXPECT_EQ(note.finger, 5);
      ++fives;
    }
  }
  EXPECT_EQ(fives, 5);
}

TEST(MusicXmlFingeringWriterTest, TimewiseDocumentsNumberNotesInDocumentOrder) {
  const std::string xml =
      "<score-timewise><part-list><score-part id=\"R\"/><score-part id=\"L\"/></part-list>\n"
      "<measure number=\"1\"><part id=\"R\">" +
      divisions(1) + pitched("E", 5, 4) + "</part><part id=\"L\">" + divisions(1) +
      pitched("C", 3, 4) +
      "</part></measure>\n"
      "<measure number=\"2\"><part id=\"R\">" +
      pitched("D", 5, 4) + "</part><part id=\"L\">" + pitched("G", 2, 4) +
      "</part></measure>\n</score-timewise>\n";
  const auto read = read_xml(xml);
  ASSERT_TRUE(read.ok()) << read.error().message;
  // Document order: E5 (#0), C3 (#1), D5 (#2), G2 (#3).
  const auto written = annotate(xml, fingers_on(*read, {{1, {5, 0}}, {2, {3, 0}}}));
  ASSERT_TRUE(written.ok()) << written.error().message;
  const auto reread = read_xml(*written);
  ASSERT_TRUE(reread.ok()) << reread.error().message;
  for (const Note& note : reread->notes) {
    const int expected = note.pitch == 48 ? 5 : note.pitch == 74 ? 3 : 0;
    EXPECT_EQ(note.finger, expected) << note.pitch;
  }
}

TEST(MusicXmlFingeringWriterTest, Utf16DocumentsAreRewrittenInUtf16) {
  const std::string utf8 = one_part_score(measure(divisions(1) + pitched("A", 4, 1)));
  std::string utf16 = "\xFF\xFE";
  for (const char c : utf8) {
    utf16 += c;
    utf16 += '\0';
  }
  const auto read = read_xml(utf16);
  ASSERT_TRUE(read.ok()) << read.error().message;
  const auto written = annotate(utf16, fingers_on(*read, {{0, {2, 0}}}));
  ASSERT_TRUE(written.ok()) << written.error().message;
  EXPECT_EQ(written->substr(0, 4), std::string("\xFF\xFE<\0", 4));
  const auto reread = read_xml(*written);
  ASSERT_TRUE(reread.ok()) << reread.error().message;
  ASSERT_EQ(reread->notes.size(), 1u);
  EXPECT_EQ(reread->notes[0].finger, 2);
}

TEST(MusicXmlFingeringWriterTest, ScoresThatDoNotMatchTheFileAreRefused) {
  const std::string xml = one_part_score(measure(divisions(1) + pitched("A", 4, 1)));
  const auto read = read_xml(xml);
  ASSERT_TRUE(read.ok());
  Score wrong = *read;
  wrong.notes[0].source_index = 5;
  wrong.notes[0].finger = 1;
  const auto beyond = annotate(xml, wrong);
  ASSERT_FALSE(beyond.ok());
  EXPECT_EQ(beyond.error().message.rfind("t.musicxml: ", 0), 0u);
  EXPECT_NE(beyond.error().message.find("<note> #5"), std::string::npos);

  Score six = fingers_on(*read, {{0, {6, 0}}});
  const auto bad_finger = annotate(xml, six);
  ASSERT_FALSE(bad_finger.ok());
  EXPECT_NE(bad_finger.error().message.find("fingers are 1-5"), std::string::npos);

  const auto not_xml = annotate("not xml at all", six);
  ASSERT_FALSE(not_xml.ok());
}

TEST(MusicXmlFingeringWriterTest, WritesTheFileAtomically) {
  TUTTI_REQUIRE_TESTDATA();
  const fs::path original = test::testdata("musicxml/lilypond-test-suite/43a-PianoStaff.xml");
  const fs::path output = test::unique_temp_path("43a.musicxml");
  const auto read = read_musicxml_file(original);
  ASSERT_TRUE(read.ok()) << read.error().message;
  const Status status = write_musicxml_with_fingering(
      original, output, fingers_on(*read, {{0, {3, 0}}, {1, {5, 0}}}));
  ASSERT_TRUE(status.ok()) << status.error().message;
  const auto reread = read_musicxml_file(output);
  ASSERT_TRUE(reread.ok()) << reread.error().message;
  for (const Note& note : reread->notes) EXPECT_EQ(note.finger, note.source_index == 0 ? 3 : 5);
  fs::remove(output);

  const Status missing = write_musicxml_with_fingering("/nonexistent/x.musicxml", output, *read);
  ASSERT_FALSE(missing.ok());
  EXPECT_FALSE(fs::exists(output));
}

}  // namespace
}  // namespace tutti::music
