// SPDX-License-Identifier: MIT
// The one contact detector: keys reach their beds and leave them, valves their stops, slides
// come to rest, players start to sound; each stop belongs to a performer, lies on the grid's
// range, and comes out the same on every run.
#include <tutti/stage/contact_detector.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string_view>
#include <utility>

#include <tutti/components/performer.hpp>
#include "bundled_stage.hpp"

namespace tutti::stage {
namespace {

// Stops are of the kinds their families name.
bool same(const std::vector<Stop>& a, const std::vector<Stop>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].t_s != b[i].t_s || a[i].kind != b[i].kind || a[i].performer != b[i].performer ||
        a[i].value != b[i].value || a[i].sounding != b[i].sounding) {
      return false;
    }
  }
  return true;
}

// The organist (content/scenes/organ.json): each pedal the feet play reaches its bottom as its
// note starts (the pedal is down by the onset), and comes back up, on the pedalboard's keys.
TEST(ContactDetector, EachPedalTheFeetPlayGoesDownByItsNoteAndComesBackUp) {
  auto stage = test::stage_bundled_scene("organ.json");
  ASSERT_NE(stage, nullptr);
  const StopGrid grid{stage->start_s(), stage->end_s(), 0.002, true};
  const std::vector<Stop> stops = detect_stops(*stage, grid);
  std::vector<double> pedal_downs;
  int held = 0, ups = 0;
  for (const Stop& stop : stops) {
    if (!test::stop_is(stop, "pedal_down") && !test::stop_is(stop, "pedal_up")) continue;
    EXPECT_GE(stop.value, 36);
    EXPECT_LE(stop.value, 67);
    ASSERT_NE(stage->world().try_get<components::Performer>(stop.performer), nullptr);
    if (test::stop_is(stop, "pedal_down")) {
      pedal_downs.push_back(stop.t_s);
      ++held;
    } else {
      EXPECT_GT(held, 0);
      --held;
      ++ups;
    }
  }
  // Every note of the pedals' staff (the third) has its pedal down within a grid step of its
  // onset; but a note at the range's start, whose pedal is already down at the first sample (a
  // stop is a crossing between two samples).
  const music::Score& score = stage->scores().front();
  std::size_t pedal_notes = 0;
  for (const music::Note& n : score.notes) {
    if (n.staff != 3 || n.onset_s < grid.from_s + 0.1) continue;
    ++pedal_notes;
    const bool found = std::any_of(pedal_downs.begin(), pedal_downs.end(), [&](double t) {
      return std::abs(t - n.onset_s) <= 0.0025;
    });
    EXPECT_TRUE(found) << "pedal " << n.pitch << " at " << n.onset_s << " s";
  }
  EXPECT_GT(pedal_notes, 25u);
  EXPECT_EQ(pedal_downs.size(), pedal_notes);
  EXPECT_EQ(ups, static_cast<int>(pedal_notes)) << "every pedal that went down comes back up";
  EXPECT_EQ(held, 0);
  EXPECT_TRUE(same(stops, detect_stops(*stage, grid))) << "the same stops on a second run";
}

// The pianist: every key that reaches its bed leaves it again on the same key (but those still
// down when the range ends), on the piano's keys, and the same stops on a second run.
TEST(ContactDetector, EveryKeyThePianistPressesComesBackUp) {
  auto stage = test::stage_bundled_scene("piano.json");
  ASSERT_NE(stage, nullptr);
  const StopGrid grid{stage->start_s(), stage->start_s() + 8.0, 0.002, false};
  const std::vector<Stop> stops = detect_stops(*stage, grid);
  std::map<std::pair<std::uint64_t, int>, int> down;  // (performer, key) -> keys down
  int downs = 0, ups = 0;
  for (const Stop& stop : stops) {
    EXPECT_GE(stop.t_s, grid.from_s);
    EXPECT_LE(stop.t_s, grid.to_s);
    ASSERT_NE(stage->world().try_get<components::Performer>(stop.performer), nullptr);
    ASSERT_TRUE(test::stop_is(stop, "key_down") || test::stop_is(stop, "key_up"));
    EXPECT_TRUE(stop.sounding);
    EXPECT_GE(stop.value, 21);
    EXPECT_LE(stop.value, 108);
    int& held = down[{stop.performer.bits(), stop.value}];
    if (test::stop_is(stop, "key_down")) {
      ++held;
      ++downs;
    } else {
      EXPECT_GT(held, 0) << "key " << stop.value << " up at " << stop.t_s << " s, never down";
      --held;
      ++ups;
    }
  }
  EXPECT_GT(downs, 20);
  EXPECT_GE(ups, downs - 10);
  EXPECT_TRUE(same(stops, detect_stops(*stage, grid)));
}

// The quartet: valves reach both stops, slides come to rest, players start to sound; a valve
// let go or a slide at rest counts as sounding only where the player sounds around it.
TEST(ContactDetector, TheBrassValvesSlidesAndTonguesAreFound) {
  auto stage = test::stage_bundled_scene("quartet.json");
  ASSERT_NE(stage, nullptr);
  const StopGrid grid{stage->start_s(), stage->start_s() + 20.0, 0.002, false};
  const std::vector<Stop> stops = detect_stops(*stage, grid);
  std::map<std::string_view, int> count;
  int silent = 0;
  for (const Stop& stop : stops) {
    ++count[stop.kind->name];
    EXPECT_NE(stage->world().try_get<components::Performer>(stop.performer), nullptr);
    if (!stop.sounding) {
      ++silent;
      EXPECT_TRUE(test::stop_is(stop, "valve_up") || test::stop_is(stop, "slide_arrives"));
    }
    if (test::stop_is(stop, "slide_arrives")) {
      EXPECT_GE(stop.value, 1);
      EXPECT_LE(stop.value, 7);
    }
  }
  EXPECT_GT(count["valve_down"], 8);
  EXPECT_GT(count["valve_up"], 8);
  EXPECT_GT(count["slide_arrives"], 2);
  EXPECT_GT(count["tongue"], 5);
  EXPECT_LT(silent, static_cast<int>(stops.size()));
  EXPECT_TRUE(same(stops, detect_stops(*stage, grid)));
}

TEST(ContactDetector, AnEmptyGridFindsNothing) {
  auto stage = test::stage_bundled_scene("piano.json");
  ASSERT_NE(stage, nullptr);
  EXPECT_TRUE(detect_stops(*stage, {1.0, 2.0, 0.0, false}).empty());
  EXPECT_TRUE(detect_stops(*stage, {2.0, 1.0, 0.001, false}).empty());
  EXPECT_TRUE(detect_stops(*stage, {1.0, 1.0, 0.001, false}).empty());
}

}  // namespace
}  // namespace tutti::stage
