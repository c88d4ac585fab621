// SPDX-License-Identifier: MIT
// Players' lines from a score's brass parts: voices, monophony, written pitch.
#include <tutti/fingering_planner/brass_lines.hpp>

#include <gtest/gtest.h>

#include <tutti/music/load_score.hpp>
#include "testdata.hpp"

namespace tutti::fingering_planner {

// The brass model's names used here (systems/brass_model).
using brass_model::BrassLine;
using brass_model::load_all_instruments;

namespace {

TEST(BrassLines, TwoPlayersInOnePartSplitTopAndBottom) {
  TUTTI_REQUIRE_TESTDATA();
  auto score = music::load_score(tutti::test::testdata("midi/tonejs/symphony_7_2.mid"));
  ASSERT_TRUE(score.ok()) << score.error().message;
  auto known = load_all_instruments();
  ASSERT_TRUE(known.ok()) << known.error().message;
  const std::vector<BrassPart> parts = find_brass_parts(*score, *known);
  const BrassPart* horns = nullptr;
  for (const BrassPart& p : parts) {
    if (score->parts[static_cast<std::size_t>(p.part)].name == "2 Horns in E") horns = &p;
  }
  ASSERT_NE(horns, nullptr);
  EXPECT_EQ(horns->voices, 2);
  auto top = extract_line(*score, horns->part, 0, *horns->instrument);
  auto bottom = extract_line(*score, horns->part, 1, *horns->instrument);
  ASSERT_TRUE(top.ok() && bottom.ok());
  ASSERT_EQ(top->notes.size(), bottom->notes.size());  // every chord gives each player a note
  int split = 0;
  for (std::size_t i = 0; i < top->notes.size(); ++i) {
    EXPECT_DOUBLE_EQ(top->notes[i].onset_s, bottom->notes[i].onset_s);
    EXPECT_GE(top->notes[i].sounding, bottom->notes[i].sounding);
    split += top->notes[i].sounding > bottom->notes[i].sounding;
    EXPECT_EQ(top->notes[i].written,
              top->notes[i].sounding - horns->instrument->transposition_semitones);
  }
  EXPECT_GT(split, 0);
  // Monophonic: no note sounds past the next onset.
  for (const BrassLine* line : {&*top, &*bottom}) {
    for (std::size_t i = 1; i < line->notes.size(); ++i) {
      EXPECT_LE(line->notes[i - 1].offset_s, line->notes[i].onset_s + 1e-12);
      EXPECT_LT(line->notes[i - 1].onset_s, line->notes[i].onset_s);
    }
  }
  EXPECT_FALSE(extract_line(*score, horns->part, 2, *horns->instrument).ok());
  EXPECT_FALSE(extract_line(*score, 99, 0, *horns->instrument).ok());
}

TEST(BrassLines, ChoraleTrumpetsAreOnePlayerEach) {
  TUTTI_REQUIRE_TESTDATA();
  auto score = music::load_score(tutti::test::testdata("musicxml/music21/bwv41.6.mxl"));
  ASSERT_TRUE(score.ok()) << score.error().message;
  auto known = load_all_instruments();
  ASSERT_TRUE(known.ok());
  const std::vector<BrassPart> parts = find_brass_parts(*score, *known);
  ASSERT_EQ(parts.size(), 3u);
  for (const BrassPart& p : parts) {
    EXPECT_EQ(p.voices, 1);
    auto line = extract_line(*score, p.part, 0, *p.instrument);
    ASSERT_TRUE(line.ok());
    std::size_t in_part = 0;
    for (const music::Note& n : score->notes) in_part += n.part == p.part;
    EXPECT_EQ(line->notes.size(), in_part);
  }
}

}  // namespace
}  // namespace tutti::fingering_planner
