// SPDX-License-Identifier: MIT
// Valve, slide and embouchure motion: valves down at every onset, the slide at its position at
// every onset and never faster than the instrument allows, tension by register, pure evaluation,
// and the ECS system writing the components.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <vector>

#include <tutti/brass_motion/brass_pose_system.hpp>
#include <tutti/brass_motion/evaluate_brass_pose.hpp>
#include <tutti/brass_motion/plan_brass_motion.hpp>
#include <tutti/brass_motion/plan_brass_player.hpp>
#include <tutti/components/breath.hpp>
#include <tutti/components/instrument.hpp>
#include <tutti/components/mouth.hpp>
#include <tutti/components/slide.hpp>
#include <tutti/components/valve.hpp>
#include <tutti/fingering_planner/brass_lines.hpp>
#include <tutti/fingering_planner/brass_planner.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/spline_motion/plateau_envelope.hpp>
#include "testdata.hpp"

namespace tutti::brass_motion {

// The brass planner's names used here (systems/fingering_planner).
using fingering_planner::BrassDiagnostic;
using fingering_planner::BrassIssue;
using fingering_planner::BrassPart;
using fingering_planner::BrassPlanSummary;
using fingering_planner::extract_line;
using fingering_planner::find_brass_parts;
using fingering_planner::load_planner_weights;
using fingering_planner::plan_line;
using fingering_planner::PlannerWeights;

// The brass model's names used here (systems/brass_model).
using brass_model::BrassLine;
using brass_model::Fingering;
using brass_model::Instrument;
using brass_model::LineNote;
using brass_model::load_all_instruments;

namespace {

struct Setup {
  std::vector<Instrument> instruments;
  PlannerWeights weights;
  BrassMotionParams params;
};

const Setup& setup() {
  static const Setup s = [] {
    Setup out;
    auto instruments = load_all_instruments();
    auto weights = load_planner_weights();
    auto params = load_brass_motion_params();
    if (!instruments || !weights || !params) ADD_FAILURE() << "content did not load";
    if (instruments) out.instruments = std::move(*instruments);
    if (weights) out.weights = *weights;
    if (params) out.params = *params;
    return out;
  }();
  return s;
}

const Instrument& instrument(const std::string& id) {
  for (const Instrument& i : setup().instruments) {
    if (i.id == id) return i;
  }
  ADD_FAILURE() << id;
  return setup().instruments.front();
}

BrassLine planned_line(const Instrument& on, const std::vector<int>& sounding,
                       const std::vector<double>& steps_s) {
  BrassLine line;
  line.instrument = &on;
  double t = 0.5;
  for (std::size_t i = 0; i < sounding.size(); ++i) {
    const double step = steps_s[i % steps_s.size()];
    LineNote n;
    n.onset_s = t;
    n.offset_s = t + 0.9 * step;
    n.onset_beats = 2.0 * n.onset_s;
    n.offset_beats = 2.0 * n.offset_s;
    n.sounding = sounding[i];
    n.written = on.written(sounding[i]);
    line.notes.push_back(n);
    t += step;
  }
  plan_line(line, setup().weights);
  return line;
}

const Fingering& fingering_of(const BrassLine& line, const LineNote& n) {
  return line.instrument->chart[static_cast<std::size_t>(n.fingering)];
}

// Every onset: the note's valves fully down, the others fully up; the slide at its place.
void expect_fingered_at_onsets(const BrassLine& line, const BrassMotionPlan& plan) {
  for (const LineNote& n : line.notes) {
    if (n.fingering < 0) continue;
    const Fingering& f = fingering_of(line, n);
    const BrassPose pose = evaluate_brass_pose(plan, n.onset_s);
    for (int v = 0; v < plan.valve_count; ++v) {
      const bool down = (f.valves >> v) & 1u;
      EXPECT_NEAR(pose.valve_press[std::size_t(v)], down ? 1.0 : 0.0, 1e-6)
          << "valve " << v << " at " << n.onset_s;
    }
    if (plan.has_slide && plan.late_slide_moves == 0) {
      EXPECT_NEAR(pose.slide_mm, f.slide_mm, 1e-3) << n.onset_s;
      EXPECT_NEAR(pose.slide_position, f.position, 1e-4) << n.onset_s;
    }
    EXPECT_TRUE(pose.buzzing || n.offset_s <= n.onset_s);
    EXPECT_NEAR(pose.tension, embouchure_tension(*line.instrument, n.written, setup().params),
                1e-6);
  }
}

TEST(BrassPose, ValvesAreDownAtEveryOnsetOfARealTrumpetPart) {
  TUTTI_REQUIRE_TESTDATA();
  auto score = music::load_score(tutti::test::testdata("musicxml/music21/bwv69.6.xml"));
  ASSERT_TRUE(score.ok());
  const auto parts = find_brass_parts(*score, setup().instruments);
  ASSERT_FALSE(parts.empty());
  for (const BrassPart& part : parts) {
    auto line = extract_line(*score, part.part, 0, *part.instrument);
    ASSERT_TRUE(line.ok());
    plan_line(*line, setup().weights, &*score);
    const BrassMotionPlan plan = plan_brass_motion(*line, setup().params, setup().weights.change);
    EXPECT_EQ(plan.valve_count, 3);
    expect_fingered_at_onsets(*line, plan);
    // A valve held by consecutive notes does not bounce: no press below 1 between two onsets
    // that both need it (and less than valve_hold_rest_s apart).
    for (std::size_t i = 1; i < line->notes.size(); ++i) {
      const LineNote& a = line->notes[i - 1];
      const LineNote& b = line->notes[i];
      const unsigned both = fingering_of(*line, a).valves & fingering_of(*line, b).valves;
      if (b.onset_s - a.offset_s >= setup().params.valve_hold_rest_s) continue;
      for (double t = a.onset_s; t <= b.onset_s; t += 0.005) {
        const BrassPose pose = evaluate_brass_pose(plan, t);
        for (int v = 0; v < 3; ++v) {
          if ((both >> v) & 1u) {
            ASSERT_EQ(pose.valve_press[std::size_t(v)], 1.0f) << t;
          }
        }
      }
    }
  }
}

TEST(BrassPose, SlideArrivesOnTimeSmoothlyAndWithinItsSpeed) {
  const Instrument& trombone = instrument("trombone_tenor");
  // Leaps across the positions at several speeds.
  const BrassLine line = planned_line(trombone, {46, 53, 47, 58, 52, 62, 59, 65, 56, 60, 45, 53},
                                      {0.5, 0.25, 0.3, 0.7});
  const BrassMotionPlan plan = plan_brass_motion(line, setup().params, setup().weights.change);
  ASSERT_TRUE(plan.has_slide);
  EXPECT_EQ(plan.late_slide_moves, 0);
  EXPECT_GT(plan.slide.size(), 5u);
  expect_fingered_at_onsets(line, plan);
  const double top = trombone.max_slide_speed_mm_per_s;
  double previous_mm = evaluate_brass_pose(plan, 0.0).slide_mm;
  double previous_v = 0.0;
  const double dt = 1e-4;
  for (double t = dt; t < line.notes.back().offset_s + 0.5; t += dt) {
    const BrassPose pose = evaluate_brass_pose(plan, t);
    ASSERT_LE(std::abs(pose.slide_speed_mm_per_s), top * (1.0 + 1e-9)) << t;
    // Continuous position and velocity (no jumps): finite differences stay bounded.
    ASSERT_LE(std::abs(pose.slide_mm - previous_mm), top * dt * 1.01) << t;
    ASSERT_LE(std::abs(pose.slide_speed_mm_per_s - previous_v), 0.02 * top) << t;
    previous_mm = pose.slide_mm;
    previous_v = pose.slide_speed_mm_per_s;
  }
}

// The reach the trombonist's body is set for (plan_slide_reach): never short of the slide, and it
// eases (within a ramp's minimum-jerk speed of the farthest extension) where the slide leaps.
TEST(BrassPose, TheBodyIsSetForTheSlidesReachAheadOfItAndSmoothly) {
  const Instrument& trombone = instrument("trombone_tenor");
  const BrassLine line = planned_line(trombone, {46, 53, 47, 58, 52, 62, 59, 65, 56, 60, 45, 53},
                                      {0.5, 0.25, 0.3, 0.7});
  const BrassMotionPlan plan = plan_brass_motion(line, setup().params, setup().weights.change);
  ASSERT_FALSE(plan.slide_reach.values.empty());
  double farthest = 0.0;
  for (const SlideMove& m : plan.slide) {
    farthest = std::max<double>(farthest, std::max(m.from_mm, m.to_mm));
  }
  const double ramp = setup().params.slide_reach_ramp_s;
  const double dt = 1e-3;
  double fastest = 0.0, slide_fastest = 0.0;
  double previous = tutti::spline_motion::evaluate_plateau_envelope(plan.slide_reach, 0.0);
  double previous_slide = evaluate_brass_pose(plan, 0.0).slide_mm;
  for (double t = dt; t < line.notes.back().offset_s + 0.5; t += dt) {
    const double reach = tutti::spline_motion::evaluate_plateau_envelope(plan.slide_reach, t);
    const double slide = evaluate_brass_pose(plan, t).slide_mm;
    ASSERT_GE(reach, slide - 1e-3) << t;  // slide_mm is a float
    fastest = std::max(fastest, std::abs(reach - previous) / dt);
    slide_fastest = std::max(slide_fastest, std::abs(slide - previous_slide) / dt);
    previous = reach;
    previous_slide = slide;
  }
  EXPECT_LE(fastest, 1.875 * farthest / ramp * 1.01);
  EXPECT_LT(fastest, 0.5 * slide_fastest);
}

// content/brass/motion.json: a bad value or an unknown key is refused naming the file and the
// key, never read as garbage (the slide-reach ease included).
TEST(BrassMotionParams, BrokenFilesAreOneLineErrors) {
  const std::filesystem::path dir = test::unique_temp_path("motion");
  std::filesystem::create_directories(dir);
  const struct {
    const char* text;
    const char* expected;
  } cases[] = {
      {R"({"slide_reach_ramp_s": 0})", "slide_reach_ramp_s"},
      {R"({"slide_reach_bridge_s": "long"})", "slide_reach_bridge_s"},
      {R"({"slide_reach": 1})", "slide_reach"},
      {R"({"valve_lead_s": )", "motion.json"},
  };
  for (const auto& c : cases) {
    const std::filesystem::path file = dir / "motion.json";
    std::ofstream(file) << c.text;
    auto params = load_brass_motion_params(file.string());
    ASSERT_FALSE(params) << c.text;
    const std::string& message = params.error().message;
    EXPECT_NE(message.find("motion.json"), std::string::npos) << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  std::filesystem::remove_all(dir);
}

TEST(BrassPose, TensionRisesWithTheRegisterAndRelaxesInRests) {
  const Instrument& trumpet = instrument("trumpet_bb");
  const double low = embouchure_tension(trumpet, trumpet.lowest_written, setup().params);
  const double mid = embouchure_tension(trumpet, trumpet.written(67), setup().params);
  const double high = embouchure_tension(trumpet, trumpet.highest_written, setup().params);
  EXPECT_LT(low, mid);
  EXPECT_LT(mid, high);
  EXPECT_DOUBLE_EQ(high, 1.0);
  // Two phrases with a long rest: relaxed in the middle, corners pulled only up high.
  BrassLine line = planned_line(trumpet, {60, 64, 67, 84}, {0.5});
  line.notes.push_back(line.notes.back());
  line.notes.back().onset_s += 3.0;
  line.notes.back().offset_s += 3.0;
  const BrassMotionPlan plan = plan_brass_motion(line, setup().params, setup().weights.change);
  const BrassPose rest = evaluate_brass_pose(plan, line.notes[3].offset_s + 1.0);
  EXPECT_NEAR(rest.tension, setup().params.mouth_rest_tension, 1e-6);
  EXPECT_FALSE(rest.buzzing);
  EXPECT_EQ(evaluate_brass_pose(plan, line.notes[0].onset_s + 0.1).corner_pull, 0.0);
  EXPECT_GT(evaluate_brass_pose(plan, line.notes[3].onset_s + 0.1).corner_pull, 0.5);
}

TEST(BrassPose, EvaluationIsPureAndSeekable) {
  const BrassLine line =
      planned_line(instrument("trombone_tenor"), {46, 53, 47, 58, 52, 62, 59, 65}, {0.2, 0.4});
  const BrassMotionPlan plan = plan_brass_motion(line, setup().params, setup().weights.change);
  std::vector<BrassPose> forward;
  for (int k = 0; k < 400; ++k) forward.push_back(evaluate_brass_pose(plan, k / 100.0));
  for (int k = 399; k >= 0; --k) {
    const BrassPose again = evaluate_brass_pose(plan, k / 100.0);
    const BrassPose& first = forward[std::size_t(k)];
    EXPECT_EQ(again.slide_mm, first.slide_mm);
    EXPECT_EQ(again.tension, first.tension);
    EXPECT_EQ(again.valve_press, first.valve_press);
  }
}

TEST(BrassPose, SystemWritesThePerformerAndInstrumentComponents) {
  const Instrument& trombone = instrument("trombone_tenor");
  const BrassLine line = planned_line(trombone, {46, 53, 47, 58}, {0.5});
  auto motion = std::make_shared<BrassPlayerMotion>();
  motion->motion = plan_brass_motion(line, setup().params, setup().weights.change);
  ecs::World world;
  const ecs::Entity player = world.create();
  world.emplace<BrassPlayerMotionHandle>(player, BrassPlayerMotionHandle{motion});
  world.emplace<components::Mouth>(player);
  world.emplace<components::Breath>(player);
  const ecs::Entity horn = world.create();
  world.emplace<components::Instrument>(horn, components::Instrument{"trombone_tenor", player});
  world.emplace<components::Slide>(horn);
  world.emplace<components::Valve>(horn);
  ecs::Schedule schedule;
  register_brass_motion(schedule);
  const LineNote& third = line.notes[2];
  schedule.run(world, ecs::FrameTime{third.onset_s + 0.01, 0.0});
  const auto& slide = world.get<components::Slide>(horn);
  EXPECT_NEAR(slide.extension_mm, fingering_of(line, third).slide_mm, 1.0);
  EXPECT_TRUE(world.get<components::Mouth>(player).buzzing);
  EXPECT_GT(world.get<components::Mouth>(player).tension, 0.0);
  EXPECT_EQ(world.get<components::Valve>(horn).count,
            plan_brass_motion(line, setup().params, setup().weights.change).valve_count);
}

}  // namespace
}  // namespace tutti::brass_motion

namespace tutti::brass_motion {
namespace {

// A phrase longer than one breath: the catch-breath shortens a note, and the motion follows
// the line as played (silent, mouth opening, while the player breathes).
TEST(BrassPlayer, CatchBreathsSilenceTheShortenedNotes) {
  const Instrument& trumpet = instrument("trumpet_bb");
  music::Score score;
  score.tempo_map = music::TempoMap::with_ticks_per_quarter(480);
  score.tempo_map.set_tempo(0, 500'000.0);  // 120 bpm: a quarter is 0.5 s
  score.time_signatures.push_back({0, 0.0, 4, 4});
  BrassLine line;
  line.instrument = &trumpet;
  for (int q = 0; q < 80; ++q) {  // 40 s of legato quarters, no rest
    LineNote n;
    n.onset_beats = 4.0 + q;
    n.offset_beats = n.onset_beats + 1.0;
    n.onset_s = 0.5 * n.onset_beats;
    n.offset_s = 0.5 * n.offset_beats;
    n.sounding = 65 + (q % 8);
    n.written = trumpet.written(n.sounding);
    n.velocity = 90;
    line.notes.push_back(n);
  }
  plan_line(line, setup().weights);
  auto breath = load_breath_params();
  ASSERT_TRUE(breath.ok()) << breath.error().message;
  const BrassPlayerMotion player =
      plan_brass_player(line, score, setup().params, *breath, setup().weights.change);
  ASSERT_GT(player.breaths.catch_breaths, 0);
  ASSERT_FALSE(player.breaths.shortened.empty());
  const BrassLine played = as_played(line, player.breaths);
  for (const ShortenedNote& s : player.breaths.shortened) {
    const LineNote& before = line.notes[std::size_t(s.note)];
    const LineNote& next = line.notes[std::size_t(s.note) + 1];
    EXPECT_LT(played.notes[std::size_t(s.note)].offset_s, before.offset_s);
    const double breathing = 0.5 * (played.notes[std::size_t(s.note)].offset_s + next.onset_s);
    EXPECT_FALSE(evaluate_brass_pose(player.motion, breathing).buzzing) << breathing;
    EXPECT_GT(evaluate_breath(player.breaths, breathing).inhale, 0.0) << breathing;
    EXPECT_TRUE(evaluate_brass_pose(player.motion, next.onset_s + 0.01).buzzing);
  }
}

// The bundled quartet's second trombone (bar 2): G3 in 4th position, F3, a catch-breath, B-flat2
// in 1st. The F3 in 1st position is 277 mm away with 100 ms to move: late. Planned on the line
// as played, the breath frees the time after the F3, so the F3 takes an alternate near 4th
// position and the slide still reaches the B-flat2: no move is late.
TEST(BrassPlayer, TheFingeringIsPlannedAroundTheBreaths) {
  auto score = music::load_score(std::string(TUTTI_CONTENT_DIR) + "/music/quartet.musicxml");
  ASSERT_TRUE(score.ok()) << score.error().message;
  auto breath = load_breath_params();
  ASSERT_TRUE(breath.ok()) << breath.error().message;
  const Instrument& trombone = instrument("trombone_tenor");
  int part = -1;
  for (std::size_t p = 0; p < score->parts.size(); ++p) {
    if (score->parts[p].name == "Trombone 2") part = static_cast<int>(p);
  }
  ASSERT_GE(part, 0);
  auto written = extract_line(*score, part, 0, trombone);
  ASSERT_TRUE(written.ok());
  BrassLine alone = *written;
  const BrassPlanSummary before = plan_line(alone, setup().weights, &*score);
  BrassLine around = *written;
  const BrassPlanSummary after =
      plan_line_around_breaths(around, *score, setup().weights, *breath);
  EXPECT_GT(before.infeasible_moves, 0);
  EXPECT_EQ(after.infeasible_moves, 0);
  for (const BrassDiagnostic& d : after.diagnostics) {
    EXPECT_NE(d.kind, BrassIssue::slide_too_slow) << d.message;
  }
  // The written offsets are kept: the line is the score's, the breath only shortens it as played.
  ASSERT_EQ(around.notes.size(), written->notes.size());
  for (std::size_t i = 0; i < around.notes.size(); ++i) {
    EXPECT_EQ(around.notes[i].offset_s, written->notes[i].offset_s);
  }
  // And the motion on the line as played has the slide at every onset.
  const BrassPlayerMotion player =
      plan_brass_player(around, *score, setup().params, *breath, setup().weights.change);
  EXPECT_EQ(player.motion.late_slide_moves, 0);
  expect_fingered_at_onsets(as_played(around, player.breaths), player.motion);
}

}  // namespace
}  // namespace tutti::brass_motion
