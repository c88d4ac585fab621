// SPDX-License-Identifier: MIT
// The breath plan of real trumpet parts: the Bach chorales with trumpets in
// ../shared/testdata/musicxml/music21. Lines are built here from the score (top note of each
// chord, ends cut at the next onset); instrument ranges come from the line itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "breath_fixture.hpp"
#include <tutti/music/load_score.hpp>
#include "testdata.hpp"

namespace tutti::brass_motion {

// The brass model's names used here (systems/brass_model).
using brass_model::BrassLine;
using brass_model::LineNote;

namespace {

BrassLine trumpet_line(const music::Score& score, int part) {
  BrassLine line;
  line.part = part;
  line.part_name = score.parts[static_cast<std::size_t>(part)].name;
  const int transpose = score.parts[static_cast<std::size_t>(part)].transpose_semitones;
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    const music::Note& n = score.notes[i];
    if (n.part != part) continue;
    if (!line.notes.empty() && line.notes.back().onset_beats == n.onset_beats) {
      if (n.pitch <= line.notes.back().sounding) continue;  // keep the top note of a chord
      line.notes.pop_back();
    }
    LineNote note;
    note.score_index = static_cast<int>(i);
    note.onset_s = n.onset_s;
    note.offset_s = n.offset_s;
    note.onset_beats = n.onset_beats;
    note.offset_beats = n.offset_beats;
    note.sounding = n.pitch;
    note.written = n.pitch - transpose;
    note.velocity = n.velocity;
    line.notes.push_back(note);
  }
  for (std::size_t k = 0; k + 1 < line.notes.size(); ++k) {
    LineNote& a = line.notes[k];
    const LineNote& b = line.notes[k + 1];
    if (a.offset_s > b.onset_s) {
      a.offset_s = b.onset_s;
      a.offset_beats = b.onset_beats;
    }
  }
  return line;
}

double offset_of(const BrassLine& line, const BreathPlan& plan, int note) {
  for (const ShortenedNote& s : plan.shortened) {
    if (s.note == note) return s.offset_s;
  }
  return line.notes[static_cast<std::size_t>(note)].offset_s;
}

void check_part(const music::Score& score, int part, const BreathParams& params,
                int& trumpet_parts) {
  const BrassLine line = trumpet_line(score, part);
  SCOPED_TRACE(score.source + " part " + std::to_string(part + 1) + " " + line.part_name);
  ASSERT_FALSE(line.notes.empty());
  ++trumpet_parts;
  const BreathPlan plan = plan_breaths(line, score, params);

  // Breaths only in rests or as catch-breaths, in time order.
  int rule_breaths = 0;
  int prepared = 0;
  for (std::size_t i = 0; i < plan.events.size(); ++i) {
    const BreathEvent& e = plan.events[i];
    ASSERT_GE(e.before_note, 0);
    const LineNote& next = line.notes[static_cast<std::size_t>(e.before_note)];
    EXPECT_NEAR(e.end_s, next.onset_s, 1e-9);
    EXPECT_LE(e.prepare_start_s, e.start_s);
    EXPECT_LT(e.start_s, e.end_s);
    if (i > 0) {
      EXPECT_GE(e.prepare_start_s, plan.events[i - 1].end_s);
    }
    if (e.kind == BreathKind::before_entrance) {
      EXPECT_EQ(i, 0u);
      EXPECT_EQ(e.before_note, 0);
      continue;
    }
    ASSERT_GT(e.before_note, 0);
    const int previous = e.before_note - 1;
    EXPECT_GE(e.start_s, offset_of(line, plan, previous) - 1e-9);
    if (e.kind == BreathKind::catch_breath) continue;
    ++rule_breaths;
    prepared += e.kind == BreathKind::prepared ? 1 : 0;
    EXPECT_GE(e.rest_beats, 0.5 - 1e-6);
    EXPECT_GE(e.prepare_start_s, line.notes[static_cast<std::size_t>(previous)].offset_s - 1e-9);
  }
  ASSERT_FALSE(plan.events.empty());
  EXPECT_EQ(plan.events[0].kind, BreathKind::before_entrance);
  EXPECT_GE(rule_breaths, 1);

  // Air within [0, 1] everywhere, continuous.
  const double end = line.notes.back().offset_s + 1.0;
  double lowest = 1.0;
  double highest_strain = 0.0;
  for (double t = -2.0; t <= end; t += 0.005) {
    const BreathState s = evaluate_breath(plan, t);
    ASSERT_GE(s.air, 0.0);
    ASSERT_LE(s.air, 1.0);
    if (t >= plan.events[0].end_s) lowest = std::min(lowest, s.air);
    highest_strain = std::max(highest_strain, s.strain);
  }
  EXPECT_NEAR(lowest, plan.min_air, 0.01);
  EXPECT_NEAR(highest_strain, plan.max_strain, 0.01);
  test::expect_continuous(plan, -2.0, end);

  // Deterministic.
  const BreathPlan again = plan_breaths(line, score, params);
  ASSERT_EQ(again.events.size(), plan.events.size());
  for (std::size_t i = 0; i < plan.events.size(); ++i) {
    EXPECT_EQ(again.events[i].start_s, plan.events[i].start_s);
    EXPECT_EQ(again.events[i].depth, plan.events[i].depth);
  }
  EXPECT_EQ(again.min_air, plan.min_air);

  std::printf(
      "  %-12s %-10s %3zu notes: %2zu breaths (%d prepared, %d catch), min air %.2f, "
      "max strain %.2f, out of air %d\n",
      std::filesystem::path(score.source).filename().string().c_str(), line.part_name.c_str(),
      line.notes.size(), plan.events.size(), prepared, plan.catch_breaths, plan.min_air,
      plan.max_strain, plan.out_of_air);
  std::string catches;
  for (const BreathEvent& e : plan.events) {
    if (e.kind != BreathKind::catch_breath) continue;
    char at[32];
    std::snprintf(at, sizeof at, " %.2f",
                  line.notes[static_cast<std::size_t>(e.before_note)].onset_beats);
    catches += at;
  }
  if (!catches.empty()) std::printf("    catch-breaths before quarters%s\n", catches.c_str());
}

TEST(BreathBach, TrumpetPartsOfTheChorales) {
  TUTTI_REQUIRE_TESTDATA();
  auto params = load_breath_params(test::content_dir() / "brass" / "breath.json");
  ASSERT_TRUE(params.ok()) << params.error().message;
  int trumpet_parts = 0;
  for (const char* file : {"bwv29.8.mxl", "bwv41.6.mxl", "bwv69.6.xml"}) {
    auto score = music::load_score(tutti::test::testdata(std::string("musicxml/music21/") + file));
    ASSERT_TRUE(score.ok()) << score.error().message;
    for (std::size_t p = 0; p < score->parts.size(); ++p) {
      if (score->parts[p].name.find("Trumpet") == std::string::npos) continue;
      check_part(*score, static_cast<int>(p), *params, trumpet_parts);
    }
  }
  EXPECT_EQ(trumpet_parts, 9);
}

// The editor's marks on a real part (bwv69.6, its first trumpet: 26 quarters without a rest,
// catch-breaths): every breath the rules take in a rest removed, an add mark at every 7th note
// boundary. The removed boundaries stay without a breath, the added ones get one, the air stays
// in [0, 1] and continuous, and the plan is deterministic.
TEST(BreathBach, MarksOnTheFirstTrumpetOfBwv69_6) {
  TUTTI_REQUIRE_TESTDATA();
  auto params = load_breath_params(test::content_dir() / "brass" / "breath.json");
  ASSERT_TRUE(params.ok()) << params.error().message;
  auto score = music::load_score(tutti::test::testdata("musicxml/music21/bwv69.6.xml"));
  ASSERT_TRUE(score.ok()) << score.error().message;
  int part = -1;
  for (std::size_t p = 0; p < score->parts.size() && part < 0; ++p) {
    if (score->parts[p].name.find("Trumpet") != std::string::npos) part = static_cast<int>(p);
  }
  ASSERT_GE(part, 0);
  const BrassLine line = trumpet_line(*score, part);
  const BreathPlan rules = plan_breaths(line, *score, *params);

  BreathMarks marks;
  std::vector<int> removed;
  for (const BreathEvent& e : rules.events) {
    if (e.kind == BreathKind::catch_breath || e.kind == BreathKind::before_entrance) continue;
    removed.push_back(e.before_note);
    marks.remove_s.push_back(line.notes[static_cast<std::size_t>(e.before_note)].onset_s);
  }
  ASSERT_GE(removed.size(), 5u);
  std::vector<int> added;
  for (int n = 3; n < static_cast<int>(line.notes.size()); n += 7) {
    if (std::find(removed.begin(), removed.end(), n) != removed.end()) continue;
    added.push_back(n);
    marks.add_s.push_back(line.notes[static_cast<std::size_t>(n)].onset_s - 0.01);
  }
  marks.add_s.push_back(line.notes.back().onset_s + 5.0);  // after the last note
  const BreathPlan plan = plan_breaths(line, *score, *params, marks);
  EXPECT_EQ(plan.ignored_marks, 1);

  const auto event_before = [&](int note) -> const BreathEvent* {
    for (const BreathEvent& e : plan.events) {
      if (e.before_note == note) return &e;
    }
    return nullptr;
  };
  for (int n : removed) EXPECT_EQ(event_before(n), nullptr) << "removed, before note " << n;
  int marked = 0;
  for (int n : added) {
    const BreathEvent* e = event_before(n);
    ASSERT_NE(e, nullptr) << "added, before note " << n;
    marked += e->marked ? 1 : 0;
    EXPECT_GE(e->start_s, offset_of(line, plan, n - 1) - 1e-9);
    EXPECT_LT(e->start_s, e->end_s);
  }
  EXPECT_GT(marked, 0);
  for (std::size_t i = 1; i < plan.events.size(); ++i) {
    EXPECT_GE(plan.events[i].prepare_start_s, plan.events[i - 1].end_s - 1e-9) << i;
  }
  const double end = line.notes.back().offset_s + 1.0;
  for (double t = -2.0; t <= end; t += 0.005) {
    const BreathState s = evaluate_breath(plan, t);
    ASSERT_GE(s.air, 0.0);
    ASSERT_LE(s.air, 1.0);
  }
  test::expect_continuous(plan, -2.0, end);
  const BreathPlan again = plan_breaths(line, *score, *params, marks);
  ASSERT_EQ(again.events.size(), plan.events.size());
  for (std::size_t i = 0; i < plan.events.size(); ++i) {
    EXPECT_EQ(again.events[i].start_s, plan.events[i].start_s);
    EXPECT_EQ(again.events[i].depth, plan.events[i].depth);
  }
  std::printf(
      "  bwv69.6 %s: %zu rule breaths removed, %zu marks added (%d new): %zu breaths "
      "(%d catch), min air %.2f, out of air %d\n",
      line.part_name.c_str(), removed.size(), added.size(), marked, plan.events.size(),
      plan.catch_breaths, plan.min_air, plan.out_of_air);
}

}  // namespace
}  // namespace tutti::brass_motion
