// SPDX-License-Identifier: MIT
// Note::sounding from the frame time: a tiny world of notes, one schedule, frames played forward,
// backwards and out of order.
#include <tutti/note_sounding/note_sounding_system.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include <tutti/components/note.hpp>

namespace tutti::note_sounding {
namespace {

using components::Note;

struct NoteTimes {
  double onset_s;
  double offset_s;
};

// Notes of the little world: overlapping, legato (one ends where the next starts), zero-length,
// late, and one starting before 0.
const std::vector<NoteTimes> kNotes = {
    {0.0, 1.0}, {0.5, 2.0}, {1.0, 1.5}, {1.5, 1.5}, {2.0, 3.0}, {10.0, 11.0}, {-1.0, 0.25},
};

struct Fixture {
  ecs::World world;
  std::vector<ecs::Entity> notes;
  ecs::Schedule schedule;

  Fixture() {
    for (const NoteTimes& times : kNotes) {
      const ecs::Entity e = world.create();
      Note note;
      note.onset_s = times.onset_s;
      note.offset_s = times.offset_s;
      world.add<Note>(e, note);
      notes.push_back(e);
    }
    register_note_sounding(schedule);
  }

  std::vector<bool> run(double t_s) {
    schedule.run(world, {t_s, 1.0 / 60});
    std::vector<bool> flags;
    for (const ecs::Entity e : notes) flags.push_back(world.get<Note>(e).sounding);
    return flags;
  }
};

std::vector<bool> expected_at(double t_s) {
  std::vector<bool> flags;
  for (const NoteTimes& n : kNotes) flags.push_back(n.onset_s <= t_s && t_s < n.offset_s);
  return flags;
}

TEST(NoteSoundingSystem, RunsInEvaluate) {
  ecs::Schedule schedule;
  register_note_sounding(schedule);
  EXPECT_EQ(schedule.describe(), "evaluate: note_sounding\n");
}

TEST(NoteSoundingSystem, SoundsFromOnsetUntilJustBeforeOffset) {
  Fixture f;
  // At 1.0 the first note has ended, the third has just begun: the half-open interval.
  EXPECT_EQ(f.run(1.0), (std::vector<bool>{false, true, true, false, false, false, false}));
  EXPECT_EQ(f.run(std::nextafter(1.0, 0.0)),
            (std::vector<bool>{true, true, false, false, false, false, false}));
  EXPECT_EQ(f.run(0.0), (std::vector<bool>{true, false, false, false, false, false, true}));
  EXPECT_EQ(f.run(-0.5), (std::vector<bool>{false, false, false, false, false, false, true}));
  EXPECT_EQ(f.run(2.0), (std::vector<bool>{false, false, false, false, true, false, false}));
  EXPECT_EQ(f.run(10.5), (std::vector<bool>{false, false, false, false, false, true, false}));
  EXPECT_EQ(f.run(100.0), std::vector<bool>(kNotes.size(), false));
}

TEST(NoteSoundingSystem, ZeroLengthNoteNeverSounds) {
  Fixture f;
  const std::size_t zero = 3;  // {1.5, 1.5}
  for (double t : {std::nextafter(1.5, 0.0), 1.5, std::nextafter(1.5, 2.0)}) {
    f.run(t);
    EXPECT_FALSE(f.world.get<Note>(f.notes[zero]).sounding) << t;
  }
  // Its neighbour ending at the same instant stops there too.
  EXPECT_TRUE(f.run(std::nextafter(1.5, 0.0))[2]);
  EXPECT_FALSE(f.run(1.5)[2]);
}

TEST(NoteSoundingSystem, SeekingBackwardsAndOutOfOrderGivesTheSameFlags) {
  Fixture f;
  std::vector<std::vector<bool>> forward;
  for (int frame = -90; frame <= 720; ++frame) forward.push_back(f.run(frame / 60.0));
  // Backwards, frame by frame.
  for (int frame = 720; frame >= -90; --frame) {
    const std::vector<bool> flags = f.run(frame / 60.0);
    EXPECT_EQ(flags, forward[static_cast<std::size_t>(frame + 90)]) << frame;
    EXPECT_EQ(flags, expected_at(frame / 60.0)) << frame;
  }
  // Jumps: into the middle of a note, back before everything, forward past the end.
  for (double t : {10.5, -5.0, 1.25, 0.75, 12.0, 0.1, 2.5, 1.0}) {
    EXPECT_EQ(f.run(t), expected_at(t)) << t;
  }
}

TEST(NoteSoundingSystem, NonFiniteTimeSoundsNothingAndNoteAddedLaterIsCovered) {
  Fixture f;
  f.run(0.75);
  EXPECT_EQ(f.run(std::numeric_limits<double>::quiet_NaN()),
            std::vector<bool>(kNotes.size(), false));
  EXPECT_EQ(f.run(std::numeric_limits<double>::infinity()),
            std::vector<bool>(kNotes.size(), false));
  // A note created between frames gets its flag on the next frame; removing one is harmless.
  const ecs::Entity late = f.world.create();
  Note note;
  note.onset_s = 5.0;
  note.offset_s = 6.0;
  f.world.add<Note>(late, note);
  f.world.destroy(f.notes[0]);
  f.schedule.run(f.world, {5.5, 1.0 / 60});
  EXPECT_TRUE(f.world.get<Note>(late).sounding);
  EXPECT_FALSE(f.world.valid(f.notes[0]));
  f.schedule.run(f.world, {6.0, 1.0 / 60});
  EXPECT_FALSE(f.world.get<Note>(late).sounding);
}

TEST(NoteSoundingSystem, SoundsAtIsTheHalfOpenInterval) {
  static_assert(sounds_at(1.0, 2.0, 1.0));
  static_assert(!sounds_at(1.0, 2.0, 2.0));
  static_assert(!sounds_at(1.0, 1.0, 1.0));
  EXPECT_TRUE(sounds_at(1.0, 2.0, 1.999));
  EXPECT_FALSE(sounds_at(1.0, 2.0, 0.999));
  EXPECT_FALSE(sounds_at(1.0, 2.0, std::numeric_limits<double>::quiet_NaN()));
}

}  // namespace
}  // namespace tutti::note_sounding
