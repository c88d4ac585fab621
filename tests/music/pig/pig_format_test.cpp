#include <tutti/music/pig/pig_format.hpp>

#include <gtest/gtest.h>

#include <string>

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
