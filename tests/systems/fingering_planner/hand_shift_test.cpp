// SPDX-License-Identifier: MIT
// Hand shifts between disjoint hand areas: the time a shift may take (effective_dt), the hand
// speed limit of the default preset, and the shifts the planner asks for on real pieces.
//
// The pieces test plans every MusicXML file of ../shared/testdata (plus bach_846.mid and the
// bundled music) with the default weights and measures, for every shift the plan asks for, the
// hand's mean speed: the gap between the two corridors over the time between them. A shift faster
// than the speed limit is allowed only where the music forces it: no fingering of the two
// events (of their struck keys alone, which can only widen the hand areas) leaves a gap small
// enough for the time the notes give.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <tutti/fingering_planner/exact_planner.hpp>
#include <tutti/fingering_planner/plan_score.hpp>
#include <tutti/fingering_planner/transition_cost.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/music/pitch.hpp>
#include "planner_test_util.hpp"
#include "testdata.hpp"

namespace tutti::fingering_planner {
namespace {

namespace fs = std::filesystem;
using music::Hand;

double white_keys(double mm) { return mm / test::model("default").keyboard.white_key_width_mm(); }

double gap_mm(double lo_a, double hi_a, double lo_b, double hi_b) {
  return std::max({0.0, lo_b - hi_a, lo_a - hi_b});
}

TEST(HandShift, PaperTimeIsTheNotatedRelease) {
  const CostWeights& paper = test::model("paper").weights;
  EXPECT_DOUBLE_EQ(effective_dt(0.0, 0.5, paper), 0.0);
  EXPECT_DOUBLE_EQ(effective_dt(0.1, 0.5, paper), 0.1);
  EXPECT_TRUE(std::isinf(paper.speed_limit));
  EXPECT_EQ(paper.thumb_on_fourth, 0.0);
}

TEST(HandShift, DefaultTimeLetsThePreviousKeyGoEarlyButHoldsItAQuarter) {
  const CostWeights& w = test::model("default").weights;
  ASSERT_GT(w.shift_time_s, 0.0);
  ASSERT_GT(w.shift_hold_fraction, 0.0);
  // Moderate notes: the shift takes shift_time_s; fast ones: all but the held fraction; slow
  // ones: the release fraction (0.25 s of a 1.2 s note is already longer than shift_time_s).
  EXPECT_DOUBLE_EQ(effective_dt(0.0, 0.5, w), w.shift_time_s);
  EXPECT_DOUBLE_EQ(effective_dt(0.0, 1.2, w), w.release_fraction * 1.2);
  EXPECT_DOUBLE_EQ(effective_dt(0.0, 0.125, w), (1 - w.shift_hold_fraction) * 0.125);
  // A notated rest longer than that is used whole.
  EXPECT_DOUBLE_EQ(effective_dt(0.6, 1.0, w), 0.6);
  // Never more than the interval minus the hold, never less than the release fraction.
  for (double ioi : {0.01, 0.05, 0.1, 0.2, 0.3, 0.5, 2.0}) {
    const double dt = effective_dt(0.0, ioi, w);
    EXPECT_LE(dt, std::max(w.release_fraction, 1 - w.shift_hold_fraction) * ioi + 1e-15) << ioi;
    EXPECT_GE(dt, w.release_fraction * ioi) << ioi;
  }
}

TEST(HandShift, GapCostRisesSteeplyAboveTheSpeedLimit) {
  const FingeringModel& m = test::model("default");
  const CostWeights& w = m.weights;
  ASSERT_TRUE(std::isfinite(w.speed_limit));
  const double d = m.keyboard.white_key_width_mm();
  // A gap of `wk` white keys travelled in 0.1 s: speed = 10 × wk white keys per second.
  auto cost_at = [&](double speed) {
    return area_transition_cost(0, d, d + speed * 0.1 * d, 3 * d + speed * 0.1 * d, 0.1, m);
  };
  const double at = cost_at(w.speed_limit);
  const double below_slope = at - cost_at(w.speed_limit - 1);
  const double above_slope = cost_at(w.speed_limit + 1) - at;
  EXPECT_NEAR(below_slope, w.gap_speed, 1e-9);
  EXPECT_NEAR(above_slope, w.gap_speed + w.over_speed, 1e-9);
  EXPECT_GE(above_slope, 100 * below_slope);  // steep: the limit acts as a wall
  EXPECT_TRUE(std::isinf(area_transition_cost(0, d, 2 * d, 3 * d, 0.0, m)));
}

TEST(HandShift, AGapNeverCostsLessThanAnOverlap) {
  for (const char* preset : {"paper", "default"}) {
    const FingeringModel& m = test::model(preset);
    const double d = m.keyboard.white_key_width_mm();
    const double touching = area_transition_cost(0, 2 * d, 2 * d, 4 * d, 1.0, m);
    const double tiny_gap = area_transition_cost(0, 2 * d, 2.01 * d, 4 * d, 1.0, m);
    EXPECT_GE(tiny_gap, touching) << preset;
    EXPECT_GE(tiny_gap, 1.0) << preset;  // the paper: a gap costs at least 1
  }
}

// C#4 to C#6 in a sixteenth: only the thumb on C#4 and the little finger on C#6 leave a gap the
// hand can cross within the limit; without the limit the thumb's black-key cost wins and the hand
// would fly (the index finger on C#4).
TEST(HandShift, PlannerTakesTheSlowShiftEvenWhenOtherTermsPreferTheFastOne) {
  const FingeringModel& m = test::model("default");
  FingeringModel unlimited = m;
  unlimited.weights.speed_limit = kInfiniteCost;
  const auto notes = test::melody({61, 85}, 0.125);
  auto shift_speed = [&](const HandPlan& plan) {
    const HandCorridor& a = plan.corridors[0];
    const HandCorridor& b = plan.corridors[1];
    return white_keys(gap_mm(a.lo_mm, a.hi_mm, b.lo_mm, b.hi_mm)) / (b.start_s - a.end_s);
  };
  auto limited = plan_hand_exact(notes, Hand::right, m);
  auto free = plan_hand_exact(notes, Hand::right, unlimited);
  ASSERT_TRUE(limited.ok() && free.ok());
  std::printf(
      "[ shift   ] C#4-C#6 in 0.125 s: limited %d%d at %.0f white keys/s, unlimited %d%d at "
      "%.0f (limit %.0f)\n",
      limited->fingers[0], limited->fingers[1], shift_speed(*limited), free->fingers[0],
      free->fingers[1], shift_speed(*free), m.weights.speed_limit);
  EXPECT_LE(shift_speed(*limited), m.weights.speed_limit);
  EXPECT_GT(shift_speed(*free), m.weights.speed_limit);
  EXPECT_EQ(limited->fingers, (std::vector<int>{1, 5}));
}

// --- the pieces -------------------------------------------------------------------------------

struct Piece {
  std::string name;
  fs::path file;
};

std::vector<Piece> pieces() {
  std::vector<Piece> out;
  for (const auto& entry : fs::recursive_directory_iterator(tutti::test::testdata("musicxml"))) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".xml" || ext == ".mxl" || ext == ".musicxml")) {
      out.push_back(
          {fs::relative(entry.path(), tutti::test::testdata_dir()).string(), entry.path()});
    }
  }
  out.push_back({"midi/tonejs/bach_846.mid", tutti::test::testdata("midi/tonejs/bach_846.mid")});
  for (const auto& entry : fs::directory_iterator(tutti::test::source_dir() / "content/music")) {
    out.push_back({"content/" + entry.path().filename().string(), entry.path()});
  }
  std::sort(out.begin(), out.end(), [](const Piece& a, const Piece& b) { return a.name < b.name; });
  return out;
}

// Every reachable hand area of the keys (one finger each, in the hand's finger order).
std::vector<EventFingering> areas(std::vector<int> keys, Hand side, const FingeringModel& m) {
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  std::vector<EventFingering> out;
  if (keys.empty() || keys.size() > 5) return out;
  for (unsigned mask = 1; mask < 32; ++mask) {
    if (std::popcount(mask) != static_cast<int>(keys.size())) continue;
    std::vector<FingeredKey> fingered;
    int i = side == Hand::right ? 0 : static_cast<int>(keys.size()) - 1;
    for (int f = 1; f <= 5; ++f) {
      if ((mask >> (f - 1) & 1u) == 0) continue;
      fingered.push_back({keys[static_cast<std::size_t>(i)], f, false});
      i += side == Hand::right ? 1 : -1;
    }
    const EventFingering e = make_event_fingering(fingered, side, m);
    if (e.lo_mm <= e.hi_mm) out.push_back(e);
  }
  return out;
}

TEST(HandShift, PiecesShiftFasterThanTheLimitOnlyWhereTheMusicForcesIt) {
  TUTTI_REQUIRE_TESTDATA();
  const FingeringModel& m = test::model("default");
  const double limit = m.weights.speed_limit;
  int planned = 0, shifts = 0, forced = 0;
  for (const Piece& piece : pieces()) {
    auto score = music::load_score(piece.file);
    if (!score.ok() || score->notes.empty()) continue;  // refused files: see broken_files.txt
    for (music::Note& n : score->notes) n.finger = 0;
    auto plan = plan_score(*score, m);
    if (!plan.ok()) continue;
    ++planned;
    double fastest = 0.0;
    for (const Hand side : {Hand::right, Hand::left}) {
      const HandPlan& hand = side == Hand::right ? plan->right : plan->left;
      const std::vector<int>& indices = side == Hand::right ? plan->right_notes : plan->left_notes;
      auto keys_at = [&](double onset) {
        std::vector<int> keys;
        for (int i : indices) {
          const music::Note& n = score->notes[static_cast<std::size_t>(i)];
          if (std::abs(n.onset_s - onset) <= m.weights.chord_tolerance_s) keys.push_back(n.pitch);
        }
        return keys;
      };
      for (std::size_t e = 1; e < hand.corridors.size(); ++e) {
        const HandCorridor& a = hand.corridors[e - 1];
        const HandCorridor& b = hand.corridors[e];
        const double gap = gap_mm(a.lo_mm, a.hi_mm, b.lo_mm, b.hi_mm);
        if (gap <= 0) continue;
        ++shifts;
        const double time = b.start_s - a.end_s;
        ASSERT_GT(time, 0.0) << piece.name << " at " << b.start_s;
        const double speed = white_keys(gap) / time;
        fastest = std::max(fastest, speed);
        if (speed <= limit * 1.01) continue;  // within 1 %: the cost rises steeply, not a wall
        // Over the limit: the smallest gap any fingering of these two events leaves.
        double least = 1e300;
        for (const EventFingering& fa : areas(keys_at(a.start_s), side, m)) {
          for (const EventFingering& fb : areas(keys_at(b.start_s), side, m)) {
            least = std::min(least, gap_mm(fa.lo_mm, fa.hi_mm, fb.lo_mm, fb.hi_mm));
          }
        }
        ++forced;
        std::printf(
            "[ shift   ] %s %s hand at %.3f s: %.0f white keys/s; forced: least gap %.0f mm "
            "in %.3f s = %.0f white keys/s\n",
            piece.name.c_str(), side == Hand::right ? "right" : "left", b.start_s, speed, least,
            time, least < 1e299 ? white_keys(least) / time : 0.0);
        EXPECT_GT(white_keys(least) / time, limit)
            << piece.name << ": a fingering of the events at " << a.start_s << " and " << b.start_s
            << " s shifts within the limit";
      }
    }
    if (fastest > 0) {
      std::printf("[ shift   ] %-58s fastest shift %5.1f white keys/s (%.2f m/s mean)\n",
                  piece.name.c_str(), fastest, fastest * m.keyboard.white_key_width_mm() / 1000);
    }
  }
  std::printf("[ shift   ] %d pieces, %d shifts, %d above the limit (all forced)\n", planned,
              shifts, forced);
  EXPECT_GE(planned, 100);
  EXPECT_GT(shifts, 1000);
}

}  // namespace
}  // namespace tutti::fingering_planner
