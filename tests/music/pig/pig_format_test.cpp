// SPDX-License-Identifier: MIT
#include <tutti/music/pig/pig_format.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace tutti::music {
namespace {

// Written by hand in the published layout; not taken from any dataset.
constexpr const char* kTwoHands =
    "//Version: PigletFormat 1.0\n"
    "0\t0.000000\t0.500000\tC4\t64\t80\t0\t1\n"
    "1\t0.000000\t1.000000\tC3\t70\t80\t1\t-5\n"
    "2\t0.500000\t1.000000\tEb4\t60\t80\t0\t3_1\n"
    "3\t1.000000\t1.250000\tF#2\t50\t0\t1\t-2\n";

TEST(PigFormatTest, ReadsNotesHandsAndFingers) {
  auto score = read_pig(kTwoHands, "hand.txt");
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->parts.size(), 2u);
  ASSERT_EQ(score->notes.size(), 4u);
  const Note& c3 = score->notes[0];  // sorted by onset then pitch
  EXPECT_EQ(c3.pitch, 48);
  EXPECT_EQ(c3.hand, Hand::left);
  EXPECT_EQ(c3.finger, 5);
  EXPECT_EQ(c3.part, 1);
  EXPECT_DOUBLE_EQ(c3.offset_s, 1.0);
  const Note& c4 = score->notes[1];
  EXPECT_EQ(c4.pitch, 60);
  EXPECT_EQ(c4.hand, Hand::right);
  EXPECT_EQ(c4.finger, 1);
  const Note& eb4 = score->notes[2];
  EXPECT_EQ(eb4.pitch, 63);
  EXPECT_EQ(eb4.finger, 3);
  EXPECT_EQ(eb4.finger_substitute, 1);
  EXPECT_DOUBLE_EQ(eb4.onset_s, 0.5);
  EXPECT_DOUBLE_EQ(eb4.onset_beats, 1.0);
  EXPECT_EQ(score->notes[3].pitch, 42);
  EXPECT_EQ(score->notes[3].release_velocity, 0);
  EXPECT_DOUBLE_EQ(score->duration_s(), 1.25);
}

// The PIG dataset's own format details (this file is written by hand, no dataset data): offset
// velocities of -1 (not recorded), substitutions of three fingers, lines out of time order and
// flat spellings.
constexpr const char* kDatasetStyle =
    "//Version: PigletFormat 1.0\n"
    "0\t0.250000\t0.600000\tDb5\t74\t-1\t0\t2_4_5\n"
    "1\t0.000000\t1.000000\tC3\t70\t-1\t1\t-5\n"
    "2\t0.250000\t0.500000\tGb4\t60\t-1\t0\t1\n"
    "3\t1.000000\t1.250000\tE#2\t-1\t-1\t1\t-2_-1_-3\n";

TEST(PigFormatTest, ReadsDatasetStyleVelocitiesAndLongSubstitutions) {
  auto score = read_pig(kDatasetStyle, "style.txt");
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->notes.size(), 4u);
  const auto by_line = [&](int line) -> const Note& {
    for (const Note& n : score->notes) {
      if (n.source_index == line) return n;
    }
    ADD_FAILURE() << "no note from line " << line;
    return score->notes.front();
  };
  const Note& db5 = by_line(1);
  EXPECT_EQ(db5.pitch, 73);
  EXPECT_EQ(db5.finger, 2);
  EXPECT_EQ(db5.finger_substitute, 5);
  EXPECT_EQ(db5.finger_sequence, (std::vector<int>{2, 4, 5}));
  EXPECT_EQ(db5.release_velocity, 64);  // -1: not recorded
  const Note& e2 = by_line(4);
  EXPECT_EQ(e2.finger_sequence, (std::vector<int>{2, 1, 3}));
  EXPECT_EQ(e2.hand, Hand::left);
  EXPECT_EQ(e2.velocity, 64);
  // Written back: every line as it was, in its order, fingers included.
  EXPECT_EQ(write_pig(*score).substr(write_pig(*score).find('\n') + 1),
            std::string(kDatasetStyle).substr(std::string(kDatasetStyle).find('\n') + 1));
  // Only the finger column changes when the fingers do.
  Score refingered = *score;
  for (Note& n : refingered.notes) {
    n.finger = 3;
    n.finger_substitute = 0;
    n.finger_sequence.clear();
  }
  const std::string written = write_pig(refingered);
  EXPECT_NE(written.find("\n0\t0.250000\t0.600000\tDb5\t74\t-1\t0\t3\n"), std::string::npos)
      << written;
  EXPECT_NE(written.find("\n3\t1.000000\t1.250000\tE#2\t-1\t-1\t1\t-3\n"), std::string::npos)
      << written;
  // A first field that starts with "//" after a tab is a note, and stays one when written back.
  auto slashes = read_pig("\t//x\t0.5\t1.0\tC4\t64\t80\t0\t1\n", "slashes.txt");
  ASSERT_TRUE(slashes.ok()) << slashes.error().message;
  auto again = read_pig(write_pig(*slashes), "again.txt");
  ASSERT_TRUE(again.ok()) << again.error().message;
  EXPECT_EQ(again->notes.size(), 1u);
  // Still out of range: a velocity below -1, a sixth finger in a substitution.
  EXPECT_FALSE(read_pig("0\t0\t1\tC4\t64\t-2\t0\t1\n", "bad.txt").ok());
  EXPECT_FALSE(read_pig("0\t0\t1\tC4\t64\t64\t0\t1_2_3_4_5_1\n", "bad.txt").ok());
}

TEST(PigFormatTest, WriteThenReadRoundTrips) {
  auto first = read_pig(kTwoHands, "hand.txt");
  ASSERT_TRUE(first.ok());
  const std::string text = write_pig(*first);
  EXPECT_EQ(text.rfind("//", 0), 0u);
  auto second = read_pig(text, "again.txt");
  ASSERT_TRUE(second.ok()) << second.error().message;
  ASSERT_EQ(second->notes.size(), first->notes.size());
  for (std::size_t i = 0; i < first->notes.size(); ++i) {
    const Note& a = first->notes[i];
    const Note& b = second->notes[i];
    EXPECT_EQ(a.pitch, b.pitch);
    EXPECT_EQ(a.hand, b.hand);
    EXPECT_EQ(a.finger, b.finger);
    EXPECT_EQ(a.finger_substitute, b.finger_substitute);
    EXPECT_EQ(a.onset_ticks, b.onset_ticks);
    EXPECT_EQ(a.offset_ticks, b.offset_ticks);
    EXPECT_EQ(a.velocity, b.velocity);
  }
  // Same body apart from the header line, which names the source.
  const std::string again = write_pig(*second);
  EXPECT_EQ(again.substr(again.find('\n')), text.substr(text.find('\n')));
}

TEST(PigFormatTest, AcceptsCrLfSpacesAndBlankLines) {
  auto score = read_pig("//h\r\n\r\n0 0.0 0.5 A4 64 64 0 2\r\n", "crlf.txt");
  ASSERT_TRUE(score.ok()) << score.error().message;
  EXPECT_EQ(score->notes[0].pitch, 69);
}

struct BadCase {
  const char* text;
  const char* expected;
};

TEST(PigFormatTest, BrokenLinesNameFileAndLine) {
  const BadCase cases[] = {
      {"//h\n0\t0.0\t0.5\tC4\t64\t80\t0\n", "bad.txt: line 2: expected 8 fields"},
      {"//h\n0\tx\t0.5\tC4\t64\t80\t0\t1\n", "bad.txt: line 2: bad onset time 'x'"},
      {"//h\n0\t1.0\t0.5\tC4\t64\t80\t0\t1\n", "bad.txt: line 2: offset before onset"},
      {"//h\n0\t0\t0.5\tH4\t64\t80\t0\t1\n", "bad.txt: line 2: bad pitch 'H4'"},
      {"//h\n0\t0\t0.5\tC4\t640\t80\t0\t1\n", "bad.txt: line 2: bad onset velocity"},
      {"//h\n0\t0\t0.5\tC4\t64\t80\t2\t1\n", "bad.txt: line 2: channel must be 0"},
      {"//h\n0\t0\t0.5\tC4\t64\t80\t0\t7\n", "bad.txt: line 2: bad finger '7'"},
      {"//h\n0\t0\t0.5\tC4\t64\t80\t0\t3_\n", "bad.txt: line 2: bad finger '3_'"},
      {"//h\n0\tnan\t0.5\tC4\t64\t80\t0\t1\n", "bad.txt: line 2: bad onset time 'nan'"},
      {"//h\n0\t1e300\t1e301\tC4\t64\t80\t0\t1\n", "bad.txt: line 2: bad onset time"},
      {"//only a header\n", "bad.txt: no notes"},
      {"", "bad.txt: no notes"},
  };
  for (const BadCase& c : cases) {
    auto score = read_pig(c.text, "bad.txt");
    ASSERT_FALSE(score.ok()) << c.text;
    EXPECT_EQ(score.error().message.rfind(c.expected, 0), 0u) << score.error().message;
    EXPECT_EQ(score.error().message.find('\n'), std::string::npos);
  }
}

TEST(PigFormatTest, BinaryGarbageIsRejected) {
  const std::string garbage("MThd\x00\x00\x00\x06\x00\x01", 10);
  auto score = read_pig(garbage, "x.txt");
  ASSERT_FALSE(score.ok());
  EXPECT_EQ(score.error().message.rfind("x.txt: line 1:", 0), 0u);
}

TEST(PigFormatTest, WriterUsesHandFromPartNameWhenNoteHasNone) {
  Score score;
  score.parts.resize(2);
  score.parts[0].name = "Right Hand";
  score.parts[1].name = "Left Hand";
  Note a;
  a.pitch = 72;
  a.part = 1;  // left by part name, though high
  a.finger = 2;
  a.offset_ticks = 480;
  score.notes.push_back(a);
  finalize_score(score);
  const std::string text = write_pig(score);
  EXPECT_NE(text.find("\tC5\t64\t64\t1\t-2\n"), std::string::npos) << text;
}

}  // namespace
}  // namespace tutti::music
