// SPDX-License-Identifier: MIT
// detect_instrument: part names in several languages, plurals, keys and transpositions, GM
// programs; the real parts of the Bach chorales with trumpets and of Beethoven's 7th.
#include <gtest/gtest.h>

#include <string>

#include "brass_fixture.hpp"
#include <tutti/music/load_score.hpp>
#include "testdata.hpp"

namespace tutti::brass_model {
namespace {

std::string detected(const std::string& name, int program = 0, int transpose = 0,
                     bool percussion = false) {
  music::Part part;
  part.name = name;
  part.program = program;
  part.transpose_semitones = transpose;
  part.percussion = percussion;
  const Instrument* i = detect_instrument(part, test::shipped());
  return i == nullptr ? "none" : i->id;
}

TEST(DetectInstrument, ByName) {
  EXPECT_EQ(detected("Trumpet in Bb", 0, -2), "trumpet_bb");
  EXPECT_EQ(detected("Trumpet in Bb"), "trumpet_bb");  // concert-pitch score, key in the name
  EXPECT_EQ(detected("Trumpet in C"), "trumpet_c");
  EXPECT_EQ(detected("C Trumpet"), "trumpet_c");
  EXPECT_EQ(detected("Trumpet", 56), "trumpet_bb");
  EXPECT_EQ(detected("Bb Trumpet 2"), "trumpet_bb");
  EXPECT_EQ(detected("B Trompete"), "trumpet_bb");  // German B = B flat
  EXPECT_EQ(detected("F Horn"), "horn_double");
  EXPECT_EQ(detected("Trumpet", 56, -2), "trumpet_bb");  // the part's transposition decides
  EXPECT_EQ(detected("Tromba I in Sib"), "trumpet_bb");
  EXPECT_EQ(detected("Trompeten in B"), "trumpet_bb");  // German B = B♭
  EXPECT_EQ(detected("Trompette en Ut"), "trumpet_c");
  EXPECT_EQ(detected("B-flat Trumpet 2", 0, -2), "trumpet_bb");
  EXPECT_EQ(detected("Posaune 1"), "trombone_tenor");
  EXPECT_EQ(detected("Trombones"), "trombone_tenor");
  EXPECT_EQ(detected("Bass Trombone"), "trombone_tenor");
  EXPECT_EQ(detected("Horn in F", 0, -7), "horn_double");
  EXPECT_EQ(detected("Corni in Fa"), "horn_double");
  EXPECT_EQ(detected("Cor 3"), "horn_double");
  EXPECT_EQ(detected("Hörner in F"), "horn_double");
  EXPECT_EQ(detected("Euphonium"), "euphonium");
  EXPECT_EQ(detected("Baritone Horn"), "euphonium");  // the longer name wins over "horn"
  EXPECT_EQ(detected("Tenor Tuba"), "euphonium");
  EXPECT_EQ(detected("Tuba"), "tuba");
  EXPECT_EQ(detected("Tubas"), "tuba");
}

TEST(DetectInstrument, LookalikesAreNotBrass) {
  EXPECT_EQ(detected("English Horn", 69), "none");
  EXPECT_EQ(detected("Cor anglais"), "none");
  EXPECT_EQ(detected("Corno di bassetto"), "none");
  EXPECT_EQ(detected("Cornet"), "none");
  EXPECT_EQ(detected("Wagner Tuba"), "none");
  EXPECT_EQ(detected("Trumpet", 56, 0, /*percussion=*/true), "none");
  // "Baritone" is a voice too: brass only with a brass GM program.
  EXPECT_EQ(detected("Baritone"), "none");
  EXPECT_EQ(detected("Baritone", 52), "none");
  EXPECT_EQ(detected("Baritone", 58), "euphonium");
  EXPECT_EQ(detected("Baritone Sax", 67), "none");
}

TEST(DetectInstrument, ByProgramWhenTheNameSaysNothing) {
  // MIDI at concert pitch on a trumpet program: the B♭ trumpet (most parts are played on it).
  EXPECT_EQ(detected("", 56), "trumpet_bb");
  EXPECT_EQ(detected("", 56, -2), "trumpet_bb");
  EXPECT_EQ(detected("Track 3", 57), "trombone_tenor");
  EXPECT_EQ(detected("", 58), "tuba");
  EXPECT_EQ(detected("", 59), "trumpet_bb");  // muted trumpet
  EXPECT_EQ(detected("", 60), "horn_double");
  EXPECT_EQ(detected("", 61), "none");  // brass section: no one instrument
  EXPECT_EQ(detected("Piano", 0), "none");
}

TEST(DetectInstrument, BachChoralesWithTrumpets) {
  TUTTI_REQUIRE_TESTDATA();
  for (const char* piece : {"musicxml/music21/bwv29.8.mxl", "musicxml/music21/bwv41.6.mxl",
                            "musicxml/music21/bwv69.6.xml"}) {
    auto score = music::load_score(tutti::test::testdata(piece));
    ASSERT_TRUE(score.ok()) << score.error().message;
    int trumpets = 0;
    for (const music::Part& part : score->parts) {
      const Instrument* i = detect_instrument(part, test::shipped());
      if (part.name.rfind("Trumpet", 0) == 0) {
        EXPECT_EQ(part.program, 0) << piece << " " << part.name;  // found by name, not program
        ASSERT_NE(i, nullptr) << piece << " " << part.name;
        EXPECT_EQ(i->id.rfind("trumpet", 0), 0u) << piece << " " << part.name;
        ++trumpets;
        // Every note of the part lies in the detected trumpet's range.
        for (const music::Note& n : score->notes) {
          if (&score->parts[std::size_t(n.part)] != &part) continue;
          EXPECT_TRUE(i->in_range_written(i->written(n.pitch))) << piece << " " << n.pitch;
        }
      } else {
        EXPECT_EQ(i, nullptr) << piece << " " << part.name << " → " << i->id;
      }
    }
    EXPECT_EQ(trumpets, 3) << piece;
  }
}

TEST(DetectInstrument, BeethovenSeventhBrass) {
  TUTTI_REQUIRE_TESTDATA();
  auto score = music::load_score(tutti::test::testdata("midi/tonejs/symphony_7_2.mid"));
  ASSERT_TRUE(score.ok()) << score.error().message;
  int horns = 0;
  int trumpets = 0;
  for (const music::Part& part : score->parts) {
    const Instrument* i = detect_instrument(part, test::shipped());
    if (part.name == "2 Horns in E") {
      EXPECT_EQ(part.program, 60);
      ASSERT_NE(i, nullptr);
      EXPECT_EQ(i->id, "horn_double");
      ++horns;
    } else if (part.name == "2 Trumpets in D") {
      EXPECT_EQ(part.program, 56);
      ASSERT_NE(i, nullptr);
      EXPECT_EQ(i->id.rfind("trumpet", 0), 0u) << i->id;
      ++trumpets;
    } else {
      EXPECT_EQ(i, nullptr) << part.name << " → " << i->id;
    }
  }
  EXPECT_EQ(horns, 1);
  EXPECT_EQ(trumpets, 1);
}

}  // namespace
}  // namespace tutti::brass_model
