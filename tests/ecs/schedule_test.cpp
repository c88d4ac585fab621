// SPDX-License-Identifier: MIT
#include <tutti/ecs/schedule.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace tutti::ecs {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

struct Note {
  int pitch = 0;
};

TEST(ScheduleTest, PhaseNames) {
  EXPECT_EQ(phase_name(Phase::sync), "sync");
  EXPECT_EQ(phase_name(Phase::evaluate), "evaluate");
  EXPECT_EQ(phase_name(Phase::express), "express");
  EXPECT_EQ(phase_name(Phase::pose), "pose");
  EXPECT_EQ(phase_name(static_cast<Phase>(42)), "unknown");
}

TEST(ScheduleTest, RunsPhasesInOrderAndSystemsInAddedOrder) {
  Schedule schedule;
  std::vector<std::string> log;
  auto logger = [&log](std::string name) {
    return [&log, name](World&, const FrameTime&) { log.push_back(name); };
  };
  schedule.add(Phase::pose, "skin", logger("skin"));
  schedule.add(Phase::evaluate, "hand_pose", logger("hand_pose"));
  schedule.add(Phase::sync, "audio_clock", logger("audio_clock"));
  schedule.add(Phase::evaluate, "bow", logger("bow"));
  schedule.add(Phase::pose, "ik", logger("ik"));
  schedule.add(Phase::express, "breath", logger("breath"));

  World world;
  schedule.run(world, FrameTime{1.0, 0.5});
  EXPECT_THAT(log, ElementsAre("audio_clock", "hand_pose", "bow", "breath", "skin", "ik"));
  EXPECT_EQ(schedule.size(), 6U);
  EXPECT_TRUE(schedule.contains("bow"));
  EXPECT_FALSE(schedule.contains("Bow"));
}

TEST(ScheduleTest, PassesTheWorldAndTheFrame) {
  Schedule schedule;
  World world;
  const Entity e = world.create();
  FrameTime seen;
  schedule.add(Phase::sync, "clock", [&](World& w, const FrameTime& frame) {
    seen = frame;
    w.add<Note>(e, 60);
  });
  schedule.run(world, FrameTime{2.5, 1.0 / 60.0});
  EXPECT_EQ(seen.t_s, 2.5);
  EXPECT_EQ(seen.dt_s, 1.0 / 60.0);
  EXPECT_EQ(world.get<Note>(e).pitch, 60);
}

TEST(ScheduleTest, DescribeListsNonEmptyPhasesInRunOrder) {
  Schedule schedule;
  EXPECT_EQ(schedule.describe(), "");
  const auto noop = [](World&, const FrameTime&) {};
  schedule.add(Phase::evaluate, "hand_pose", noop);
  schedule.add(Phase::sync, "audio_clock", noop);
  schedule.add(Phase::evaluate, "bow", noop);
  schedule.add(Phase::pose, "ik", noop);
  EXPECT_EQ(schedule.describe(), "sync: audio_clock\nevaluate: hand_pose, bow\npose: ik\n");
}

TEST(ScheduleTest, RejectsDuplicateNamesAcrossPhases) {
  Schedule schedule;
  const auto noop = [](World&, const FrameTime&) {};
  schedule.add(Phase::evaluate, "hand_pose", noop);
  EXPECT_THAT([&] { schedule.add(Phase::evaluate, "hand_pose", noop); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("a system named 'hand_pose' is already scheduled")));
  EXPECT_THROW(schedule.add(Phase::pose, "hand_pose", noop), std::invalid_argument);
  EXPECT_THROW(schedule.add(Phase::pose, "", noop), std::invalid_argument);
  EXPECT_THROW(schedule.add(Phase::pose, "empty", System{}), std::invalid_argument);
  EXPECT_THROW(schedule.add(static_cast<Phase>(9), "bad_phase", noop), std::invalid_argument);
  EXPECT_EQ(schedule.size(), 1U);
  EXPECT_EQ(schedule.describe(), "evaluate: hand_pose\n");
}

TEST(ScheduleTest, FlushesDeferredCommandsAfterEachPhase) {
  Schedule schedule;
  World world;
  const Entity e = world.create();
  std::vector<std::string> log;
  schedule.add(Phase::evaluate, "spawn", [&](World& w, const FrameTime&) {
    w.view<Note>().each([](Note&) {});  // nothing yet
    w.defer([e](World& inner) { inner.add<Note>(e, 64); });
  });
  schedule.add(Phase::evaluate, "same_phase", [&](World& w, const FrameTime&) {
    log.push_back(w.has<Note>(e) ? "same phase sees it" : "same phase does not");
  });
  schedule.add(Phase::express, "next_phase", [&](World& w, const FrameTime&) {
    log.push_back(w.has<Note>(e) ? "next phase sees it" : "next phase does not");
  });
  schedule.run(world, FrameTime{});
  EXPECT_THAT(log, ElementsAre("same phase does not", "next phase sees it"));
  EXPECT_EQ(world.deferred(), 0U);
}

TEST(ScheduleTest, CommandsDeferredByTheLastPhaseAreFlushedByRun) {
  Schedule schedule;
  World world;
  const Entity e = world.create();
  schedule.add(Phase::pose, "late", [e](World& w, const FrameTime&) {
    w.defer([e](World& inner) { inner.add<Note>(e, 1); });
  });
  schedule.run(world, FrameTime{});
  EXPECT_TRUE(world.has<Note>(e));
}

TEST(ScheduleTest, CannotAddOrRunFromARunningSystem) {
  Schedule schedule;
  World world;
  bool add_rejected = false;
  bool run_rejected = false;
  schedule.add(Phase::sync, "meddler", [&](World& w, const FrameTime& frame) {
    try {
      schedule.add(Phase::pose, "late_comer", [](World&, const FrameTime&) {});
    } catch (const std::logic_error&) {
      add_rejected = true;
    }
    try {
      schedule.run(w, frame);
    } catch (const std::logic_error&) {
      run_rejected = true;
    }
  });
  schedule.run(world, FrameTime{});
  EXPECT_TRUE(add_rejected);
  EXPECT_TRUE(run_rejected);
  EXPECT_FALSE(schedule.contains("late_comer"));
}

TEST(ScheduleTest, ASystemExceptionPropagatesAndTheScheduleStaysUsable) {
  Schedule schedule;
  World world;
  int later_runs = 0;
  bool fail = true;
  schedule.add(Phase::sync, "flaky", [&](World&, const FrameTime&) {
    if (fail) throw std::runtime_error("device lost");
  });
  schedule.add(Phase::pose, "later", [&](World&, const FrameTime&) { ++later_runs; });
  EXPECT_THROW(schedule.run(world, FrameTime{}), std::runtime_error);
  EXPECT_EQ(later_runs, 0);
  fail = false;
  schedule.run(world, FrameTime{});
  EXPECT_EQ(later_runs, 1);
}

}  // namespace
}  // namespace tutti::ecs

namespace tutti::ecs {
namespace {

// A consumer runs the frame only as far as it needs: later phases are left alone.
TEST(ScheduleTest, RunStopsAfterTheLastPhaseAsked) {
  Schedule schedule;
  std::vector<std::string> log;
  for (Phase phase : {Phase::sync, Phase::evaluate, Phase::express, Phase::pose}) {
    schedule.add(phase, std::string(phase_name(phase)),
                 [&log, phase](World&, const FrameTime&) { log.emplace_back(phase_name(phase)); });
  }
  World world;
  schedule.run(world, FrameTime{}, Phase::evaluate);
  EXPECT_THAT(log, ElementsAre("sync", "evaluate"));
  log.clear();
  schedule.run(world, FrameTime{}, Phase::pose);
  EXPECT_THAT(log, ElementsAre("sync", "evaluate", "express", "pose"));
}

// The sync phase may replace the frame's time (the World's FrameTime resource): every later phase
// is given the new one, the sync phase's own systems the requested one.
TEST(ScheduleTest, TheSyncPhaseSetsTheTimeTheLaterPhasesSee) {
  Schedule schedule;
  std::vector<double> seen;
  schedule.add(Phase::sync, "clock", [&seen](World& world, const FrameTime& frame) {
    seen.push_back(frame.t_s);
    world.set_resource(FrameTime{frame.t_s + 10.0, 0.25});
  });
  schedule.add(Phase::sync, "after_clock",
               [&seen](World&, const FrameTime& frame) { seen.push_back(frame.t_s); });
  schedule.add(Phase::evaluate, "hands", [&seen](World&, const FrameTime& frame) {
    seen.push_back(frame.t_s);
    seen.push_back(frame.dt_s);
  });
  World world;
  schedule.run(world, FrameTime{1.0, 0.5});
  EXPECT_THAT(seen, ElementsAre(1.0, 1.0, 11.0, 0.25));
  ASSERT_NE(world.resource<FrameTime>(), nullptr);
  EXPECT_EQ(world.resource<FrameTime>()->t_s, 11.0);
}

struct Plan {};
struct Hand {};
struct Finger {};
struct Model {};

TEST(ScheduleTest, DescribeAccessListsEachSystemWithWhatItReadsAndWrites) {
  Schedule schedule;
  const auto nothing = [](World&, const FrameTime&) {};
  schedule.add(Phase::evaluate, "hand_pose", nothing, access(Reads<Plan>{}, Writes<Hand, Finger>{}));
  schedule.add(Phase::evaluate, "bow", nothing);
  schedule.add(Phase::pose, "skeleton", nothing,
               access(Reads<Hand>{}, WritesOwn<Model>{}).runs_before("camera"));
  schedule.add(Phase::pose, "camera", nothing, access(Reads<>{}, Writes<>{}));
  EXPECT_EQ(schedule.describe_access(),
            "evaluate\n"
            "  hand_pose  reads Plan; writes Hand, Finger\n"
            "  bow\n"
            "pose\n"
            "  skeleton   reads Hand; writes Model (own); before camera\n"
            "  camera\n");
  EXPECT_TRUE(schedule.check().empty());
}

TEST(ScheduleTest, TypesAreNamedWithoutTheirNamespaces) {
  EXPECT_EQ(ComponentRef::of<Finger>().name, "Finger");
  EXPECT_EQ(ComponentRef::of<FrameTime>().name, "FrameTime");
  EXPECT_EQ(ComponentRef::of<Finger>().type, type_index<Finger>());
  EXPECT_NE(ComponentRef::of<Finger>().type, ComponentRef::of<Hand>().type);
}

TEST(ScheduleTest, CheckFailsOnTwoUnorderedWritersOfOneComponentInAPhase) {
  const auto nothing = [](World&, const FrameTime&) {};
  Schedule schedule;
  schedule.add(Phase::pose, "piano_skeleton", nothing, access(Reads<Hand>{}, Writes<Model>{}));
  schedule.add(Phase::pose, "brass_skeleton", nothing, access(Reads<>{}, Writes<Model, Finger>{}));
  schedule.add(Phase::evaluate, "finger_motion", nothing, access(Reads<>{}, Writes<Finger>{}));
  EXPECT_THAT(schedule.check(),
              ElementsAre("pose: piano_skeleton and brass_skeleton both write Model, and neither "
                          "runs after the other"));

  // Ordered, the two writers are fine; so are two writers of only their own family's entities.
  Schedule ordered;
  ordered.add(Phase::pose, "piano_skeleton", nothing, access(Reads<>{}, Writes<Model>{}));
  ordered.add(Phase::pose, "brass_skeleton", nothing,
              access(Reads<>{}, Writes<Model>{}).runs_after("piano_skeleton"));
  EXPECT_TRUE(ordered.check().empty());
  Schedule own;
  own.add(Phase::pose, "piano_skeleton", nothing, access(Reads<>{}, WritesOwn<Model>{}));
  own.add(Phase::pose, "brass_skeleton", nothing, access(Reads<>{}, WritesOwn<Model>{}));
  EXPECT_TRUE(own.check().empty());
  // One writing every entity's and one its own still conflict.
  own.add(Phase::pose, "camera_rig", nothing, access(Reads<>{}, Writes<Model>{}));
  EXPECT_EQ(own.check().size(), 2u);
}

TEST(ScheduleTest, CheckFailsOnAnOrderNamingNoSystemOrAgainstTheAddedOrder) {
  const auto nothing = [](World&, const FrameTime&) {};
  Schedule schedule;
  schedule.add(Phase::pose, "a", nothing, Access{}.runs_after("b"));
  schedule.add(Phase::pose, "b", nothing, Access{}.runs_before("nobody"));
  schedule.add(Phase::evaluate, "c", nothing, Access{}.runs_after("a"));
  EXPECT_THAT(schedule.check(),
              ElementsAre("evaluate: c runs after 'a', no system of its phase",
                          "pose: a runs after b, but was added before it",
                          "pose: b runs before 'nobody', no system of its phase"));
}

}  // namespace
}  // namespace tutti::ecs
