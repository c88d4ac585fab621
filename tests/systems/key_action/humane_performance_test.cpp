// SPDX-License-Identifier: MIT
// The acceptance on tutti's piano demo (the Ode to Joy of content/scenes/piano.json) and
// on third-party piano pieces: the precise style sounds within 2 ms of the score on average,
// the beginner is uneven in time and loudness and now and then loses a note, deterministically.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "key_action_fixture.hpp"
#include "testdata.hpp"

namespace tutti::key_action {
namespace {

void print(const std::string& what, const PerformanceReport& r) {
  std::cout << what << ": " << format_report(r) << "\n";
}

TEST(HumanePerformance, PreciseIsWithinTwoMillisecondsOnThePianoDemo) {
  const test::Performed p = test::perform_score(test::ode_to_joy(), test::style("precise"), 3);
  const PerformanceReport& r = p.result.report;
  print("demo, precise", r);
  EXPECT_EQ(r.notes, p.score.notes.size());
  EXPECT_EQ(r.sounded, r.notes);
  EXPECT_LE(r.onset_mean_abs_ms, 2.0);
  EXPECT_LE(r.onset_max_abs_ms, 5.0);
  EXPECT_LE(r.velocity_error_mean_abs, 2.0);
}

TEST(HumanePerformance, TheBeginnerIsUnevenInTimeAndLoudness) {
  const test::Performed precise =
      test::perform_score(test::ode_to_joy(), test::style("precise"), 3);
  const test::Performed beginner =
      test::perform_score(test::ode_to_joy(), test::style("beginner"), 3);
  const test::Performed gentle = test::perform_score(test::ode_to_joy(), test::style("gentle"), 3);
  const PerformanceReport& b = beginner.result.report;
  const PerformanceReport& g = gentle.result.report;
  print("demo, gentle", g);
  print("demo, beginner", b);
  EXPECT_GT(b.onset_mean_abs_ms, 10.0);
  EXPECT_GT(b.onset_std_ms, 10.0);
  EXPECT_GT(b.onset_mean_ms, 0.0);  // slow, weak fingers: late more than early
  EXPECT_GT(b.velocity_std, 4.0 * precise.result.report.velocity_std + 5.0);
  // Gentle: softer than written, slightly late, far steadier than the beginner.
  EXPECT_LT(g.velocity_mean, precise.result.report.velocity_mean - 15.0);
  EXPECT_LT(g.onset_std_ms, b.onset_std_ms / 2.0);
}

TEST(HumanePerformance, TheWeakFingersAreTheLateOnes) {
  const test::Performed p = test::perform_score(test::ode_to_joy(), test::style("beginner"), 3);
  std::array<double, 5> late_ms{};
  std::array<int, 5> count{};
  for (std::size_t i = 0; i < p.score.notes.size(); ++i) {
    if (p.result.played[i].outcome != KeyOutcome::sounded) continue;
    const auto f = static_cast<std::size_t>(p.plan.fingering.fingers[i] - 1);
    late_ms[f] += 1000.0 * (p.result.played[i].onset_s - p.score.notes[i].onset_s);
    ++count[f];
  }
  ASSERT_GT(count[1], 0);
  ASSERT_GT(count[4], 0);
  // Little finger (speed 0.62) later on average than the index finger (1.0).
  EXPECT_GT(late_ms[4] / count[4], late_ms[1] / count[1] + 10.0);
}

TEST(HumanePerformance, TheSameSeedGivesTheSamePerformance) {
  const test::Performed a = test::perform_score(test::ode_to_joy(), test::style("beginner"), 11);
  const test::Performed b = test::perform_score(test::ode_to_joy(), test::style("beginner"), 11);
  const test::Performed c = test::perform_score(test::ode_to_joy(), test::style("beginner"), 12);
  const music::Score heard_a = performed_score(a.score, a.result.played);
  const music::Score heard_b = performed_score(b.score, b.result.played);
  ASSERT_EQ(heard_a.notes.size(), heard_b.notes.size());
  int differ = 0;
  for (std::size_t i = 0; i < heard_a.notes.size(); ++i) {
    EXPECT_EQ(heard_a.notes[i].onset_s, heard_b.notes[i].onset_s);
    EXPECT_EQ(heard_a.notes[i].velocity, heard_b.notes[i].velocity);
  }
  for (std::size_t i = 0; i < a.result.played.size(); ++i) {
    differ += a.result.played[i].onset_s != c.result.played[i].onset_s;
  }
  EXPECT_GT(differ, 50);  // another seed, another performance
}

TEST(HumanePerformance, ThePerformedScoreIsWhatTheKeysSounded) {
  const test::Performed p = test::perform_score(test::ode_to_joy(), test::style("beginner"), 3);
  const music::Score heard = performed_score(p.score, p.result.played);
  EXPECT_EQ(heard.notes.size(), p.result.report.sounded);
  std::size_t j = 0;
  for (std::size_t i = 0; i < p.score.notes.size(); ++i) {
    if (p.result.played[i].outcome != KeyOutcome::sounded) continue;
    ASSERT_LT(j, heard.notes.size());
    const music::Note& note = heard.notes[j++];
    EXPECT_EQ(note.onset_s, std::max(0.0, p.result.played[i].onset_s));
    EXPECT_EQ(note.velocity, p.result.played[i].velocity);
    // Ticks follow the seconds to within half a tick.
    EXPECT_NEAR(heard.tempo_map.seconds_at(static_cast<double>(note.onset_ticks)), note.onset_s,
                0.5 * (heard.tempo_map.seconds_at(1.0) - heard.tempo_map.seconds_at(0.0)) + 1e-9);
    EXPECT_GE(note.offset_ticks, note.onset_ticks);
  }
}

// Third-party piano music (../shared/testdata/musicxml/pianoplayer, MIT; see NOTICE.md).
TEST(HumanePerformance, ThirdPartyPieces) {
  TUTTI_REQUIRE_TESTDATA();
  std::size_t beginner_missed = 0;
  for (const char* file :
       {"musicxml/pianoplayer/bach_invention4.xml", "musicxml/pianoplayer/pachelbel_canon.xml",
        "musicxml/pianoplayer/scarlatti_k027.xml"}) {
    const music::Score score = test::load(tutti::test::testdata(file));
    ASSERT_FALSE(score.notes.empty()) << file;
    const test::Performed precise = test::perform_score(score, test::style("precise"), 1);
    const test::Performed beginner = test::perform_score(score, test::style("beginner"), 1);
    print(std::string(file) + ", precise", precise.result.report);
    print(std::string(file) + ", beginner", beginner.result.report);
    EXPECT_LE(precise.result.report.onset_mean_abs_ms, 2.0) << file;
    EXPECT_GE(precise.result.report.sounded + 2, precise.result.report.notes) << file;
    EXPECT_GT(beginner.result.report.onset_std_ms, 10.0) << file;
    beginner_missed += beginner.result.report.missed();
  }
  EXPECT_GT(beginner_missed, 0u);  // "occasional weak or missed notes"
}

}  // namespace
}  // namespace tutti::key_action
