// SPDX-License-Identifier: MIT
// `tutti sync-report` (app/sync_report*.hpp): the animation's contact times against the onsets
// found in the rendered audio, on the shipped demo scenes; a deliberately delayed sound track is
// caught; bad options are one-line errors.
#include <tutti/cli/sync_report.hpp>

#include <gtest/gtest.h>

#include <tutti/performance/families.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include <nlohmann/json.hpp>

#include <tutti/cli/frame_range.hpp>
#include <tutti/cli/scene_audio.hpp>
#include <tutti/cli/sync_report_command.hpp>
#include <tutti/scene/load_scene.hpp>

namespace tutti::cli {
namespace {

std::filesystem::path scene_file(const char* name) {
  return std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "scenes" / name;
}

struct Measured {
  std::vector<Contact> contacts;
  audio::AudioBuffer audio;
  double start_s = 0.0;
  std::unique_ptr<stage::Stage> stage;
};

Measured measure(const char* scene_name) {
  Measured m;
  auto scene = scene::load_scene(scene_file(scene_name), performance::scene_load_options());
  EXPECT_TRUE(scene) << scene.error().message;
  if (!scene) return m;
  auto built = performance::build_stage(*scene, {});
  EXPECT_TRUE(built) << built.error().message;
  if (!built) return m;
  m.stage = std::move(*built);
  const int fps = scene->output.fps;
  const std::int64_t frames = frame_count(0.0, m.stage->end_s() - m.stage->start_s(), fps);
  auto audio = render_scene_audio(*m.stage, fps, 0, frames);
  EXPECT_TRUE(audio) << audio.error().message;
  if (audio) m.audio = std::move(*audio);
  m.start_s = m.stage->start_s();
  m.contacts = sample_contacts(*m.stage, m.stage->start_s(), m.stage->end_s(), 0.0005);
  return m;
}

TEST(SyncReport, EveryPianoKeyBottomIsAtItsNoteOnset) {
  Measured m = measure("piano.json");
  ASSERT_FALSE(m.contacts.empty());
  const music::Score& score = m.stage->scores().front();
  for (const Contact& c : m.contacts) {
    ASSERT_EQ(c.kind->name, "key_down");
    EXPECT_TRUE(c.struck) << "a piano's key starts a struck sound";
    double nearest = 1e9;
    for (const music::Note& n : score.notes) {
      if (n.pitch == c.detail && std::abs(n.onset_s - c.time_s) < std::abs(nearest)) {
        nearest = n.onset_s - c.time_s;
      }
    }
    EXPECT_LE(std::abs(nearest), 0.0005) << "key " << c.detail << " at " << c.time_s;
  }
}

// The organ's keys and pedals start blown sounds (its part's General MIDI program is a church
// organ's), heard at the onset detector's point as the attack compensation hears them, not
// where a struck string's energy jumps.
TEST(SyncReport, TheOrgansKeysAndPedalsSoundAsPipesNotStrings) {
  Measured m = measure("organ.json");
  ASSERT_FALSE(m.contacts.empty());
  std::size_t pedals = 0;
  for (const Contact& c : m.contacts) {
    EXPECT_FALSE(c.struck) << c.kind->name << " at " << c.time_s;
    pedals += c.kind->name == "pedal_down" ? 1 : 0;
  }
  EXPECT_GT(pedals, 20u);
  const SyncFigures f = measure_sync(m.contacts, m.audio, m.start_s, {});
  std::printf("organ: %zu expected, %zu detected, %zu matched, mean |%.2f| max |%.2f| ms\n",
              f.expected, f.detected, f.matches.size(), f.mean_abs_ms, f.max_abs_ms);
  EXPECT_GE(f.matches.size() * 10, f.expected * 8);
}

TEST(SyncReport, ThePianoDemoSoundsWhereItsKeysReachBottom) {
  Measured m = measure("piano.json");
  const SyncFigures f = measure_sync(m.contacts, m.audio, m.start_s, {});
  std::printf("piano: %zu expected, %zu detected, %zu matched, mean |%.2f| max |%.2f| ms\n",
              f.expected, f.detected, f.matches.size(), f.mean_abs_ms, f.max_abs_ms);
  EXPECT_GE(f.expected, 50u);
  EXPECT_EQ(f.matches.size(), f.expected) << "every contact has its sound";
  EXPECT_LE(f.unmatched_detected_s.size(), 2u);
  EXPECT_LE(f.mean_abs_ms, kSyncGoalMeanMs);
  EXPECT_LE(f.max_abs_ms, kSyncGoalMaxMs);
  // Centred on the key bottoms: within 0.2 ms on the sparse piece (JsonListsEveryMatchOf...);
  // here, where notes overlap, the earlier notes mask each new one's energy jump and the report
  // reads it some 3 ms late.
  EXPECT_LE(std::abs(f.mean_signed_ms), 4.0) << "centred on the key bottoms";

  // The same audio 20 ms late: the report must see it.
  audio::AudioBuffer late = m.audio;
  late.samples.insert(late.samples.begin(), static_cast<std::size_t>(0.020 * 48000) * 2, 0);
  const SyncFigures g = measure_sync(m.contacts, late, m.start_s, {});
  EXPECT_NEAR(g.mean_signed_ms, f.mean_signed_ms + 20.0, 0.5);
  EXPECT_GT(g.max_abs_ms, kSyncGoalMaxMs);
}

TEST(SyncReport, TheQuartetIsHeardWhereItsTonguesValvesAndSlidesLand) {
  Measured m = measure("quartet.json");
  ASSERT_FALSE(m.contacts.empty());
  std::size_t tongues = 0;
  for (const Contact& c : m.contacts) tongues += c.kind->name == "tongue";
  EXPECT_GE(tongues, 16u) << "four players, four phrases at least";
  const SyncFigures f = measure_sync(m.contacts, m.audio, m.start_s, {});
  std::printf("quartet: %zu expected, %zu detected, %zu matched, mean |%.2f| max |%.2f| ms\n",
              f.expected, f.detected, f.matches.size(), f.mean_abs_ms, f.max_abs_ms);
  EXPECT_GE(f.matches.size() * 10, f.expected * 9) << "at least 90 % heard";
  EXPECT_LE(f.mean_abs_ms, kSyncGoalMeanMs);
  EXPECT_LE(f.max_abs_ms, kSyncGoalMaxMs);
  // The four phrase entrances (everyone tongues after a breath) among them.
  std::size_t entrances = 0;
  for (const SyncMatch& match : f.matches) {
    std::size_t tongued = 0;
    for (const Contact* c : match.contacts) tongued += c->kind->name == "tongue";
    entrances += tongued >= 4;
  }
  EXPECT_GE(entrances, 4u);
}

// Without the attack compensation the same report hears the brass late: it can fail.
TEST(SyncReport, WithoutAttackCompensationTheQuartetIsHeardLate) {
  SyncReportOptions options;
  options.scene = scene_file("quartet.json");
  options.check = true;
  options.compensate_attacks = false;
  std::ostringstream out, err;
  EXPECT_EQ(run_sync_report(options, out, err), kExitSyncGoalMissed) << out.str() << err.str();
  EXPECT_NE(out.str().find(": missed ("), std::string::npos) << out.str();
  options.compensate_attacks = true;
  out.str("");
  EXPECT_EQ(run_sync_report(options, out, err), 0) << out.str() << err.str();
}

TEST(SyncReport, TheCommandPrintsTheFiguresAndChecksTheGoal) {
  SyncReportOptions options;
  options.scene = scene_file("piano.json");
  options.check = true;
  std::ostringstream out, err;
  EXPECT_EQ(run_sync_report(options, out, err), 0) << err.str();
  EXPECT_NE(out.str().find("goal (mean ≤ 5 ms, max ≤ 16.67 ms, ≥ 90 % of contacts heard): met"),
            std::string::npos)
      << out.str();
  EXPECT_NE(out.str().find("key bottom"), std::string::npos) << out.str();
}

// --json: every match with its contact and onset, the median and p95, and where the WAV starts —
// what scripts/sync-energy-check reads. The sparse two-hand piece: one note at a time, every key
// bottom heard within a few milliseconds by the project's detector.
TEST(SyncReport, JsonListsEveryMatchOfTheSparsePiece) {
  SyncReportOptions options;
  options.scene = std::filesystem::path(TUTTI_SOURCE_DIR) / "tests" / "data" / "sync" /
                  "sparse_two_hands.json";
  options.json = true;
  std::ostringstream out, err;
  ASSERT_EQ(run_sync_report(options, out, err), 0) << err.str();
  const auto doc = nlohmann::json::parse(out.str());
  // The first note sounds at 0 s, before the first sampled frame: its stroke is not seen.
  EXPECT_EQ(doc.at("expected"), 69);
  ASSERT_EQ(doc.at("matches").size(), 69u);
  EXPECT_EQ(doc.at("audio_start_s"), 0.0);
  // Issue 20's goal for sound against the key bottom: |median| <= 3 ms, p95 <= 10 ms.
  EXPECT_LE(std::abs(doc.at("median_ms").get<double>()), 3.0);
  EXPECT_LE(doc.at("p95_abs_ms").get<double>(), 10.0);
  for (const auto& m : doc.at("matches")) {
    EXPECT_NEAR(m.at("onset_s").get<double>() - m.at("contact_s").get<double>(),
                m.at("offset_ms").get<double>() / 1000.0, 1e-9);
    EXPECT_EQ(m.at("contacts").at(0).at("kind"), "key bottom");
  }
}

// The sparse brass piece: a trumpet and a trombone taking turns, one note at a time. Every note is
// heard on its tongue, the valves arriving with it (trumpet) and the slide arriving (trombone).
TEST(SyncReport, BrassNotesAreHeardOnTheirValvesAndSlide) {
  SyncReportOptions options;
  options.scene = std::filesystem::path(TUTTI_SOURCE_DIR) / "tests" / "data" / "sync" /
                  "sparse_brass.json";
  options.json = true;
  std::ostringstream out, err;
  ASSERT_EQ(run_sync_report(options, out, err), 0) << err.str();
  const auto doc = nlohmann::json::parse(out.str());
  EXPECT_GE(doc.at("expected").get<int>(), 38);
  EXPECT_EQ(doc.at("matches").size(), doc.at("expected").get<std::size_t>());
  EXPECT_LE(std::abs(doc.at("median_ms").get<double>()), 3.0);
  EXPECT_LE(doc.at("p95_abs_ms").get<double>(), 10.0);
  int valves = 0, slides = 0;
  for (const auto& m : doc.at("matches")) {
    for (const auto& c : m.at("contacts")) {
      valves += c.at("kind") == "valve down" ? 1 : 0;
      slides += c.at("kind") == "slide arrives" ? 1 : 0;
    }
  }
  EXPECT_GE(valves, 10);
  EXPECT_GE(slides, 10);
}

TEST(SyncReport, BadOptionsAreOneLineErrors) {
  std::ostringstream out, err;
  SyncReportOptions options;
  options.scene = scene_file("piano.json");
  options.tempo = 9.0;
  EXPECT_EQ(run_sync_report(options, out, err), 2);
  EXPECT_EQ(err.str(), "error: --tempo: must be in [0.1, 4]\n");
  err.str("");
  options.tempo = 1.0;
  options.step_ms = 0.0;
  EXPECT_EQ(run_sync_report(options, out, err), 2);
  EXPECT_EQ(err.str(), "error: --step-ms: must be in [0.05, 10]\n");
  err.str("");
  options.step_ms = 0.5;
  options.tolerance_ms = 1e9;
  EXPECT_EQ(run_sync_report(options, out, err), 2);
  EXPECT_EQ(err.str(), "error: --tolerance-ms: must be in [1, 500]\n");
  err.str("");
  options.tolerance_ms = 50.0;
  options.scene = "/nonexistent/scene.json";
  EXPECT_EQ(run_sync_report(options, out, err), 2);
  const std::string message = err.str();
  EXPECT_NE(message.find("/nonexistent/scene.json"), std::string::npos) << message;
  EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 1) << message;
}

}  // namespace
}  // namespace tutti::cli
