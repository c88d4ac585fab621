// SPDX-License-Identifier: MIT
// The editor's model: each edit re-plans the stage before it is accepted, the timeline follows,
// and the models are shared so a renderer survives the re-plan.
#include <tutti/editor/session.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <tutti/brass/brass_players.hpp>
#include <tutti/components/body_motion.hpp>
#include "editor_test_support.hpp"

namespace tutti::editor {
namespace {

using test::performer_at;
using test::ScratchDir;

components::BodyMotion body_at(Session& session, std::size_t performer, double t) {
  stage::evaluate_stage(session.stage(), t);
  return session.stage().world().get<components::BodyMotion>(
      session.stage().find_performer("brass", performer));
}

// Each lane is what the player's family describes (FamilyPlugin::describe_player): the editor
// knows no family, so these come from the brass and keyboard plugins.
TEST(Session, EachLaneIsWhatThePlayersFamilyDescribes) {
  ScratchDir dir;
  auto quartet = Session::open(dir.copy_scene("quartet.json"));
  ASSERT_TRUE(quartet) << quartet.error().message;
  const TimelineLane& lead = (*quartet)->timeline().lanes.at(0);
  EXPECT_EQ(lead.family, "brass");
  EXPECT_EQ(lead.player, "/performers/0");
  EXPECT_EQ(lead.summary, "trumpet_bb, part \"Trumpet 1\", lead");
  EXPECT_TRUE(lead.expressive);
  EXPECT_TRUE(lead.breathes);
  EXPECT_FALSE(lead.fingered);
  EXPECT_EQ((*quartet)->timeline().lanes.at(2).summary, "trombone_tenor, part \"Trombone 1\"");

  auto piano = Session::open(dir.copy_scene("piano.json"));
  ASSERT_TRUE(piano) << piano.error().message;
  const TimelineLane& pianist = (*piano)->timeline().lanes.at(0);
  EXPECT_EQ(pianist.family, "piano");
  EXPECT_EQ(pianist.player, "/pianist");
  EXPECT_EQ(pianist.name, "Pianist");
  EXPECT_EQ(pianist.summary, "medium hands");
  EXPECT_TRUE(pianist.fingered);
  EXPECT_FALSE(pianist.expressive);
  EXPECT_FALSE(pianist.breathes);
  EXPECT_FALSE(pianist.corridors[0].empty());
  EXPECT_FALSE(pianist.hand_path[1].empty());
  int fingered_notes = 0;
  for (const TimelineNote& n : pianist.notes) fingered_notes += n.finger >= 1 && n.finger <= 5;
  EXPECT_EQ(fingered_notes, static_cast<int>(pianist.notes.size()));
}

TEST(Session, AVariationEditReplansThatPlayersMotion) {
  ScratchDir dir;
  auto session = Session::open(dir.copy_scene("quartet.json"));
  ASSERT_TRUE(session) << session.error().message;
  Session& s = **session;
  const auto models = s.stage().model_list();
  const auto before = body_at(s, 1, 6.0);
  ASSERT_TRUE(s.apply(set_variation(s.document().json(), performer_at(1), "sway_amount", 1.0)));
  EXPECT_FALSE(s.models_changed()) << "the same cast: the models are shared";
  EXPECT_EQ(s.stage().model_list(), models);
  const auto after = body_at(s, 1, 6.0);
  EXPECT_NE(before.sway_rad, after.sway_rad);
  EXPECT_GT(s.last_replan_ms(), 0.0);
  ASSERT_TRUE(s.undo());
  EXPECT_EQ(body_at(s, 1, 6.0).sway_rad, before.sway_rad) << "undo re-plans back exactly";
}

TEST(Session, TheTimelineShowsTheScene) {
  ScratchDir dir;
  auto session = Session::open(dir.copy_scene("quartet.json"));
  ASSERT_TRUE(session) << session.error().message;
  const Timeline& t = (*session)->timeline();
  ASSERT_EQ(t.lanes.size(), 4u);
  EXPECT_EQ(t.lanes[0].name, "Trumpet 1");
  EXPECT_FALSE(t.lanes[0].notes.empty());
  EXPECT_FALSE(t.lanes[0].breaths.empty());
  for (const TimelineLane& lane : t.lanes) {
    for (const TimelineBreath& b : lane.breaths) {
      EXPECT_LE(b.start_s, b.end_s);
      EXPECT_LE(b.end_s, b.boundary_s + 1e-9) << lane.name << ": a breath ends by its note";
    }
  }
  ASSERT_GE(t.bars_s.size(), 8u);
  EXPECT_GT(t.beats_s.size(), t.bars_s.size());
  EXPECT_EQ(t.shots.size(), (*session)->document().scene().shots.size());
  ASSERT_EQ(t.cues_s.size(), 1u) << "the automatic cue";
  EXPECT_TRUE(t.cues_automatic);
  EXPECT_DOUBLE_EQ(snap_to_beat(t, t.beats_s[3] + 0.01, 0.05), t.beats_s[3]);
  EXPECT_DOUBLE_EQ(snap_to_beat(t, t.beats_s[3] + 0.2, 0.05), t.beats_s[3] + 0.2);
}

// An organist's lane: the pedal notes carry their foot (drawn apart, never pinned to a finger),
// the manual's notes their hand and finger.
TEST(Session, TheOrganistsLaneShowsTheFeet) {
  ScratchDir dir;
  std::string text = test::read_text(test::source_dir() / "tests" / "data" / "keyboards" / "piano_and_organ.json");
  const std::string music = "\"../../../content/music/";
  text.replace(text.find(music), music.size(),
               "\"" + (test::source_dir() / "content" / "music").string() + "/");
  auto session = Session::open(dir.write("piano_and_organ.json", text));
  ASSERT_TRUE(session) << session.error().message;
  const Timeline& t = (*session)->timeline();
  ASSERT_EQ(t.lanes.size(), 2u);
  const TimelineLane& organist = t.lanes[1];
  EXPECT_EQ(organist.name, "organist");
  std::size_t feet = 0, hands = 0;
  for (const TimelineNote& n : organist.notes) {
    if (n.foot >= 0) {
      ++feet;
      EXPECT_EQ(n.finger, 0);
    } else {
      ++hands;
      EXPECT_GE(n.finger, 1);
    }
  }
  EXPECT_EQ(feet, 32u) << "as the plan says: 32 notes on the pedals";
  EXPECT_GT(hands, 50u);
  for (const TimelineNote& n : t.lanes[0].notes) EXPECT_EQ(n.foot, -1) << "the pianist's";
}

TEST(Session, PinningAFingerReplansTheFingering) {
  ScratchDir dir;
  auto session = Session::open(dir.copy_scene("piano.json"));
  ASSERT_TRUE(session) << session.error().message;
  Session& s = **session;
  const TimelineLane& lane = s.timeline().lanes.back();
  ASSERT_TRUE(lane.fingered);
  EXPECT_EQ(lane.player, "/pianist");
  const PlayerRef pianist{lane.player, lane.name};
  const TimelineNote note = lane.notes[12];
  const int finger = note.finger == 5 ? 4 : 5;
  ASSERT_TRUE(s.apply(pin_finger(s.document().json(), pianist, note.start_s, note.key, finger)));
  EXPECT_EQ(s.timeline().lanes.back().notes[12].finger, finger);
  EXPECT_TRUE(s.timeline().lanes.back().notes[12].pinned);
  // Only the span around the pin was searched again; the unpinned fingering was shared.
  ASSERT_EQ(s.stage().replanned().size(), 2u);
  EXPECT_EQ(s.stage().replanned()[0].rfind("pianist fingering around the pins (", 0), 0u)
      << s.stage().replanned()[0];
  EXPECT_EQ(s.stage().replanned()[1], "pianist motion");
  EXPECT_FALSE(s.timeline().lanes.back().corridors[0].empty());
  // The hand's path, as the panel draws it, keeps to the allowed areas.
  int inside = 0, samples = 0;
  for (const auto& [t, x] : s.timeline().lanes.back().hand_path[0]) {
    for (const HandCorridorView& c : s.timeline().lanes.back().corridors[0]) {
      if (t < c.start_s || t > c.end_s) continue;
      ++samples;
      inside += x >= c.lo_mm - 1.0 && x <= c.hi_mm + 1.0 ? 1 : 0;
    }
  }
  ASSERT_GT(samples, 100);
  EXPECT_GE(inside, samples * 95 / 100) << inside << " of " << samples;
  // A pin on a note that is not there: the planner refuses it, nothing changes.
  const std::uint64_t revision = s.document().revision();
  const Status wrong =
      s.apply(pin_finger(s.document().json(), pianist, note.start_s + 0.3333, 20, 1));
  ASSERT_FALSE(wrong);
  EXPECT_NE(wrong.error().message.find("/pianist/pins/1: no note of key 20"), std::string::npos)
      << wrong.error().message;
  EXPECT_EQ(s.document().revision(), revision);
  ASSERT_TRUE(s.undo());
  EXPECT_EQ(s.timeline().lanes.back().notes[12].finger, note.finger);
}

// Only what an edit touches is planned again: a breath mark re-plans that player (and the
// ensemble's body motion, which reads every player's breaths); a variation only the ensemble.
TEST(Session, AnEditReplansOnlyWhatItTouches) {
  ScratchDir dir;
  auto session = Session::open(dir.copy_scene("quartet.json"));
  ASSERT_TRUE(session) << session.error().message;
  Session& s = **session;
  const TimelineLane& lane = s.timeline().lanes[2];  // Trombone 1
  // A legato boundary (the note before runs into it) where nobody planned a breath.
  double boundary = -1.0;
  for (std::size_t i = 4; i < lane.notes.size() && boundary < 0; ++i) {
    const bool legato = lane.notes[i - 1].end_s >= lane.notes[i].start_s - 1e-6;
    const bool breath = std::any_of(lane.breaths.begin(), lane.breaths.end(), [&](const auto& b) {
      return std::abs(b.boundary_s - lane.notes[i].start_s) < 1e-6;
    });
    if (legato && !breath) boundary = lane.notes[i].start_s;
  }
  ASSERT_GT(boundary, 0.0);
  ASSERT_TRUE(s.apply(add_breath(s.document().json(), performer_at(2),
                                 s.breath_boundary(performer_at(2), boundary - 0.01))));
  EXPECT_EQ(s.stage().replanned(), (std::vector<std::string>{"Trombone 1", "ensemble"}));
  const auto& breaths = s.timeline().lanes[2].breaths;
  const auto marked = std::find_if(breaths.begin(), breaths.end(), [&](const auto& b) {
    return std::abs(b.boundary_s - boundary) < 1e-6;
  });
  ASSERT_NE(marked, breaths.end()) << "the mark made a breath at " << boundary;
  EXPECT_TRUE(marked->marked);
  EXPECT_TRUE(marked->catch_breath) << "legato: a catch-breath";
  const bool marked_only = marked->marked;  // the timeline is replaced by the next edit
  ASSERT_TRUE(s.apply(set_variation(s.document().json(), performer_at(0), "sway_amount", 0.1)));
  EXPECT_EQ(s.stage().replanned(), std::vector<std::string>{"ensemble"});
  // Deleting the marked breath leaves no mark behind.
  ASSERT_TRUE(s.apply(delete_breath(s.document().json(), performer_at(2), boundary, marked_only)));
  EXPECT_FALSE(s.document().json()["performers"][2].contains("breaths"));
}

TEST(Session, ASliderDragIsOneUndoStep) {
  ScratchDir dir;
  auto session = Session::open(dir.copy_scene("quartet.json"));
  ASSERT_TRUE(session);
  Session& s = **session;
  for (double v : {0.1, 0.2, 0.3, 0.4}) {
    ASSERT_TRUE(s.apply(set_variation(s.document().json(), performer_at(0), "head_motion", v),
                        /*coalesce=*/v > 0.1));
  }
  EXPECT_EQ(s.document().history().size(), 1u);
  EXPECT_DOUBLE_EQ(*brass::brass_players(s.document().scene())[0].variation.head_motion, 0.4);
  ASSERT_TRUE(s.undo());
  EXPECT_DOUBLE_EQ(*brass::brass_players(s.document().scene())[0].variation.head_motion, 0.5);
}

}  // namespace
}  // namespace tutti::editor
