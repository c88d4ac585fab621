// SPDX-License-Identifier: MIT
// Brass fingering planner: standard fingerings by default, alternates only where they help,
// slide timing, out-of-range notes, real parts.
#include <tutti/fingering_planner/brass_planner.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include <tutti/fingering_planner/brass_lines.hpp>
#include <tutti/music/load_score.hpp>
#include "testdata.hpp"

namespace tutti::fingering_planner {

// The brass model's names used here (systems/brass_model).
using brass_model::BrassLine;
using brass_model::detect_instrument;
using brass_model::Fingering;
using brass_model::fingering_name;
using brass_model::Instrument;
using brass_model::LineNote;
using brass_model::load_all_instruments;

namespace {

const Instrument& instrument(const std::string& id) {
  static std::vector<Instrument> all = [] {
    auto loaded = load_all_instruments();
    if (!loaded) ADD_FAILURE() << loaded.error().message;
    return loaded ? std::move(*loaded) : std::vector<Instrument>{};
  }();
  for (const Instrument& i : all) {
    if (i.id == id) return i;
  }
  ADD_FAILURE() << "no instrument " << id;
  static const Instrument none;
  return none;
}

const PlannerWeights& weights() {
  static const PlannerWeights w = [] {
    auto loaded = load_planner_weights();
    if (!loaded) ADD_FAILURE() << loaded.error().message;
    return loaded ? *loaded : PlannerWeights{};
  }();
  return w;
}

// A line of sounding pitches, each `step_s` long (legato), on `instrument`.
BrassLine line_of(const Instrument& on, const std::vector<int>& sounding, double step_s) {
  BrassLine line;
  line.instrument = &on;
  line.part_name = "test";
  for (std::size_t i = 0; i < sounding.size(); ++i) {
    LineNote n;
    n.onset_s = double(i) * step_s;
    n.offset_s = n.onset_s + step_s;
    n.onset_beats = double(i) * step_s * 2.0;  // 120 bpm
    n.offset_beats = n.onset_beats + step_s * 2.0;
    n.sounding = sounding[i];
    n.written = on.written(sounding[i]);
    line.notes.push_back(n);
  }
  return line;
}

const Fingering& chosen(const BrassLine& line, std::size_t i) {
  return line.instrument->chart[static_cast<std::size_t>(line.notes[i].fingering)];
}

// Total slide travel when every note takes its standard (rank 0) position.
double standard_travel(const BrassLine& line) {
  double travel = 0.0;
  for (std::size_t i = 1; i < line.notes.size(); ++i) {
    const auto a = line.instrument->fingerings(line.notes[i - 1].written);
    const auto b = line.instrument->fingerings(line.notes[i].written);
    travel += std::abs(double(a.front().slide_mm) - double(b.front().slide_mm));
  }
  return travel;
}

TEST(BrassPlanner, SlowPassagesUseTheStandardFingerings) {
  // The source's table, as a slow melody: every note standard.
  for (const char* id : {"trumpet_bb", "trombone_tenor"}) {
    BrassLine line = line_of(instrument(id), {57, 59, 60, 62, 64, 65, 67, 69}, 1.0);
    const BrassPlanSummary summary = plan_line(line, weights());
    EXPECT_EQ(summary.alternates, 0) << id;
    EXPECT_EQ(summary.unplayable, 0) << id;
    EXPECT_EQ(summary.infeasible_moves, 0) << id;
    for (std::size_t i = 0; i < line.notes.size(); ++i) {
      EXPECT_EQ(chosen(line, i).rank, 0) << id << " note " << i;
    }
  }
}

TEST(BrassPlanner, TromboneAlternatePositionsCutSlideTravelInAFastPassage) {
  // D4-Eb4 trill-like figure then F4-D4 in sixteenths at 150 bpm (0.1 s per note).
  std::vector<int> fast;
  for (int i = 0; i < 12; ++i) fast.push_back(i % 2 == 0 ? 62 : 63);
  BrassLine line = line_of(instrument("trombone_tenor"), fast, 0.1);
  const double standard = standard_travel(line);
  const BrassPlanSummary summary = plan_line(line, weights());
  std::printf(
      "fast D4-Eb4: slide travel %.0f mm planned vs %.0f mm in standard positions, "
      "%d alternates\n",
      summary.slide_travel_mm, standard, summary.alternates);
  EXPECT_GT(summary.alternates, 0);
  EXPECT_LT(summary.slide_travel_mm, 0.6 * standard);
  EXPECT_EQ(summary.infeasible_moves, 0);
  // The same figure slowly keeps the standard positions.
  BrassLine slow = line_of(instrument("trombone_tenor"), fast, 1.0);
  EXPECT_EQ(plan_line(slow, weights()).alternates, 0);
}

TEST(BrassPlanner, SlideMovesThatCannotFinishAreAvoidedOrReported) {
  // B2 (7th position) and Bb2 (1st) alternating in eighths at 120 bpm: 7th to 1st and back is too
  // far for the slide's top speed in the time legato allows; the F attachment's T2 is not.
  std::vector<int> leap;
  for (int i = 0; i < 8; ++i) leap.push_back(i % 2 == 0 ? 47 : 46);
  BrassLine line = line_of(instrument("trombone_tenor"), leap, 0.25);
  const BrassPlanSummary summary = plan_line(line, weights());
  EXPECT_EQ(summary.infeasible_moves, 0);
  EXPECT_GT(summary.alternates, 0);
  EXPECT_LT(summary.slide_travel_mm, 0.5 * standard_travel(line));
  // Far too fast for any fingering: reported, and every note still gets one.
  BrassLine impossible = line_of(instrument("trombone_tenor"), {46, 53, 46, 53, 46}, 0.02);
  impossible.notes[2].sounding = impossible.notes[2].written = 40;  // E2: 7th position only
  const BrassPlanSummary worst = plan_line(impossible, weights());
  for (const LineNote& n : impossible.notes) EXPECT_GE(n.fingering, 0);
  ASSERT_GT(worst.infeasible_moves, 0);
  EXPECT_NE(worst.diagnostics.front().message.find("slide cannot move"), std::string::npos);
}

// The trombone without its F attachment: only the slide's own positions.
Instrument without_trigger(const Instrument& trombone) {
  Instrument plain = trombone;
  plain.chart.clear();
  plain.chart_begin.assign(1, 0);
  for (int p = trombone.lowest_written; p <= trombone.highest_written; ++p) {
    for (const Fingering& f : trombone.fingerings(p)) {
      if (f.valves == 0) plain.chart.push_back(f);
    }
    plain.chart_begin.push_back(static_cast<int>(plain.chart.size()));
  }
  return plain;
}

TEST(BrassPlanner, SlidePositionsPastTheArmsReachTakeTheTrigger) {
  // B2 held alone, slowly: 7th position is standard, but 609 mm out is past a player's reach
  // (trombone_tenor.json "reach_mm"), so the F attachment's T2 plays it.
  const Instrument& trombone = instrument("trombone_tenor");
  ASSERT_GT(trombone.slide_reach_mm, 0.0);
  BrassLine line = line_of(trombone, {47}, 2.0);
  BrassPlanSummary summary = plan_line(line, weights());
  EXPECT_EQ(fingering_name(trombone, chosen(line, 0)), "T2");
  EXPECT_LE(double(chosen(line, 0).slide_mm), trombone.slide_reach_mm);
  EXPECT_TRUE(summary.diagnostics.empty());
  // Without a reach limit the standard 7th stays.
  Instrument unlimited = trombone;
  unlimited.slide_reach_mm = 0.0;
  BrassLine free_line = line_of(unlimited, {47}, 2.0);
  plan_line(free_line, weights());
  EXPECT_EQ(fingering_name(unlimited, chosen(free_line, 0)), "7");
  // Without a trigger there is no other way: played in 7th and said so.
  const Instrument plain = without_trigger(trombone);
  BrassLine plain_line = line_of(plain, {47}, 2.0);
  plain_line.part_name = "Trombone 1";
  summary = plan_line(plain_line, weights());
  EXPECT_EQ(fingering_name(plain, chosen(plain_line, 0)), "7");
  ASSERT_EQ(summary.diagnostics.size(), 1u);
  EXPECT_EQ(summary.diagnostics.front().kind, BrassIssue::beyond_reach);
  EXPECT_EQ(summary.diagnostics.front().note, 0);
  const std::string& message = summary.diagnostics.front().message;
  EXPECT_NE(message.find("Trombone 1"), std::string::npos) << message;
  EXPECT_NE(message.find("B2 needs position 7"), std::string::npos) << message;
  EXPECT_NE(message.find("beyond the arm's reach (550 mm)"), std::string::npos) << message;
}

TEST(BrassPlanner, TrumpetTrillTakesTheThirdValveAlternate) {
  // Written G#4 (2-3) to A4 (1-2 standard, 3 alternate), trilled: sounding F#4 / G4.
  std::vector<int> trill;
  for (int i = 0; i < 16; ++i) trill.push_back(i % 2 == 0 ? 66 : 67);
  BrassLine line = line_of(instrument("trumpet_bb"), trill, 0.07);
  const BrassPlanSummary summary = plan_line(line, weights());
  EXPECT_GT(summary.alternates, 0);
  for (std::size_t i = 1; i < line.notes.size(); i += 2) {
    EXPECT_EQ(fingering_name(instrument("trumpet_bb"), chosen(line, i)), "3") << i;
  }
  BrassLine slow = line_of(instrument("trumpet_bb"), trill, 0.6);
  EXPECT_EQ(plan_line(slow, weights()).alternates, 0);
}

TEST(BrassPlanner, OutOfRangeNotesAreReportedAndLeftUnplayed) {
  const Instrument& trumpet = instrument("trumpet_bb");
  BrassLine line = line_of(trumpet, {60, 40, 62, 100, 64}, 0.5);
  line.part_name = "Trumpet 1";
  const BrassPlanSummary summary = plan_line(line, weights());
  EXPECT_EQ(summary.unplayable, 2);
  ASSERT_EQ(summary.diagnostics.size(), 2u);
  EXPECT_FALSE(line.notes[1].playable);
  EXPECT_EQ(line.notes[1].fingering, -1);
  EXPECT_FALSE(line.notes[3].playable);
  for (std::size_t i : {0u, 2u, 4u}) EXPECT_GE(line.notes[i].fingering, 0);
  const std::string& message = summary.diagnostics.front().message;
  EXPECT_NE(message.find("Trumpet 1"), std::string::npos) << message;
  EXPECT_NE(message.find("bar 1"), std::string::npos) << message;
  EXPECT_NE(message.find("E2"), std::string::npos) << message;
  EXPECT_NE(message.find("0.50 s"), std::string::npos) << message;
}

TEST(BrassPlanner, EveryBrassPartOfTheTestPiecesPlans) {
  TUTTI_REQUIRE_TESTDATA();
  auto known = load_all_instruments();
  ASSERT_TRUE(known.ok());
  int players = 0;
  for (const char* piece : {"musicxml/music21/bwv29.8.mxl", "musicxml/music21/bwv41.6.mxl",
                            "musicxml/music21/bwv69.6.xml", "midi/tonejs/symphony_7_2.mid"}) {
    auto score = music::load_score(tutti::test::testdata(piece));
    ASSERT_TRUE(score.ok()) << score.error().message;
    const std::vector<BrassPart> parts = find_brass_parts(*score, *known);
    ASSERT_FALSE(parts.empty()) << piece;
    for (const BrassPart& part : parts) {
      for (int voice = 0; voice < part.voices; ++voice) {
        auto line = extract_line(*score, part.part, voice, *part.instrument);
        ASSERT_TRUE(line.ok()) << line.error().message;
        const BrassPlanSummary summary = plan_line(*line, weights(), &*score);
        std::printf(
            "%s: %s voice %d on %s: %d notes, %d alternates, %d out of range, "
            "%d late moves\n",
            piece, line->part_name.c_str(), voice + 1, part.instrument->id.c_str(), summary.notes,
            summary.alternates, summary.unplayable, summary.infeasible_moves);
        EXPECT_GT(summary.notes, 0);
        EXPECT_EQ(summary.unplayable, 0) << piece << " " << line->part_name;
        for (const LineNote& n : line->notes) EXPECT_GE(n.fingering, 0);
        ++players;
      }
    }
  }
  EXPECT_GE(players, 11);  // 3 × 3 trumpets, 2 horns and 2 trumpets in the symphony
}

TEST(BrassPlanner, SameLineSamePlan) {
  std::vector<int> notes;
  for (int i = 0; i < 200; ++i) notes.push_back(55 + (i * 7) % 17);
  BrassLine a = line_of(instrument("trombone_tenor"), notes, 0.12);
  BrassLine b = a;
  const BrassPlanSummary sa = plan_line(a, weights());
  const BrassPlanSummary sb = plan_line(b, weights());
  for (std::size_t i = 0; i < a.notes.size(); ++i)
    EXPECT_EQ(a.notes[i].fingering, b.notes[i].fingering);
  EXPECT_EQ(sa.total_cost, sb.total_cost);
}

TEST(BrassPlanner, BadWeightsFileIsAOneLineError) {
  const auto path = tutti::test::unique_temp_path("planner.json");
  {
    std::ofstream file(path);
    file << R"({"alternate_rank": 1.0, "valve_chnage": 2})";
  }
  auto loaded = load_planner_weights(path.string());
  ASSERT_FALSE(loaded.ok());
  EXPECT_NE(loaded.error().message.find("valve_chnage"), std::string::npos);
  EXPECT_NE(loaded.error().message.find(path.filename().string()), std::string::npos);
  EXPECT_EQ(loaded.error().message.find('\n'), std::string::npos);
  std::filesystem::remove(path);
  EXPECT_FALSE(load_planner_weights(path.string()).ok());
}

}  // namespace
}  // namespace tutti::fingering_planner

namespace tutti::fingering_planner {
namespace {

// Horii's claim made true: a new instrument is only a new data file. An E♭ soprano cornet
// (sounds a minor third above written, three valves) added to a copy of content/ is found by
// name, transposes by its own data and gets the same valve logic.
TEST(BrassPlanner, ANewInstrumentNeedsOnlyADataFile) {
  namespace fs = std::filesystem;
  const fs::path folder = tutti::test::unique_temp_path("content");
  fs::create_directories(folder);
  fs::copy(TUTTI_CONTENT_DIR, folder, fs::copy_options::recursive);
  auto trumpet = nlohmann::json::parse(std::ifstream(folder / "instruments" / "trumpet_bb.json"));
  trumpet["id"] = "cornet_eb";
  trumpet["display_name"] = "E♭ soprano cornet";
  trumpet["names"] = {"cornet", "kornett", "cornetto"};
  trumpet["gm_programs"] = nlohmann::json::array();
  trumpet["transposition_semitones"] = 3;
  trumpet["range"] = {{"lowest", "F#3"}, {"highest", "D6"}};
  std::ofstream(folder / "instruments" / "cornet_eb.json") << trumpet.dump(2);
  ::setenv("TUTTI_CONTENT_DIR", folder.c_str(), 1);
  auto known = load_all_instruments();
  auto weights = load_planner_weights();
  ::unsetenv("TUTTI_CONTENT_DIR");
  ASSERT_TRUE(known.ok()) << known.error().message;
  ASSERT_TRUE(weights.ok());
  music::Part part;
  part.name = "Soprano Cornet in Eb";
  const Instrument* cornet = detect_instrument(part, *known);
  ASSERT_NE(cornet, nullptr);
  EXPECT_EQ(cornet->id, "cornet_eb");
  // Concert G4 is written E4 on an E♭ instrument: valves 1-2, as on any three-valve horn.
  BrassLine line;
  line.instrument = cornet;
  LineNote n;
  n.onset_s = 0.0;
  n.offset_s = 1.0;
  n.sounding = 67;
  n.written = cornet->written(67);
  line.notes.push_back(n);
  const BrassPlanSummary summary = plan_line(line, *weights);
  EXPECT_EQ(summary.unplayable, 0);
  EXPECT_EQ(line.notes[0].written, 64);
  EXPECT_EQ(fingering_name(*cornet, cornet->chart[std::size_t(line.notes[0].fingering)]), "1-2");
  fs::remove_all(folder);
}

}  // namespace
}  // namespace tutti::fingering_planner
