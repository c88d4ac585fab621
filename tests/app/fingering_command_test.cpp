// SPDX-License-Identifier: MIT
// `tutti fingering`: every output format, pins, round trips, determinism, errors, the plot.
#include <tutti/cli/fingering_command.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <tuple>

#include <tutti/core/exit_codes.hpp>
#include <tutti/cli/fingering_output.hpp>
#include "command_run.hpp"
#include <tutti/core/file_io.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/music/pig/pig_format.hpp>
#include "testdata.hpp"

namespace tutti::cli {
namespace {

namespace fs = std::filesystem;

using test::CommandRun;

CommandRun run(const FingeringOptions& options) {
  return test::run_command(run_fingering, options);
}

std::string bytes_of(const fs::path& path) {
  auto bytes = read_file_bytes(path);
  return bytes ? std::string(bytes->begin(), bytes->end()) : std::string{};
}

fs::path ode() { return test::source_dir() / "content/music/ode_to_joy.musicxml"; }

class FingeringCommandTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::unique_temp_path("fingering");
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path file(const std::string& name) const { return dir_ / name; }

  // Runs to a JSON file and parses it; checks every note fingered, the path inside.
  nlohmann::json plan_json(FingeringOptions o) {
    o.output = file("plan.json");
    const CommandRun r = run(o);
    EXPECT_EQ(r.code, kExitOk) << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;
    auto doc = nlohmann::json::parse(bytes_of(o.output), nullptr, false);
    EXPECT_FALSE(doc.is_discarded());
    for (const auto& note : doc["notes"]) {
      EXPECT_GE(note["finger"].get<int>(), 1) << note.dump();
      EXPECT_LE(note["finger"].get<int>(), 5) << note.dump();
      EXPECT_NE(note["hand"], "unknown");
    }
    for (const char* hand : {"right", "left"}) {
      const auto& h = doc["hands"][hand];
      EXPECT_EQ(h["path_error"], "") << hand;
      EXPECT_EQ(h["violations_planned_corridors"]["violating_corridors"], 0) << hand;
    }
    return doc;
  }

  fs::path dir_;
};

TEST_F(FingeringCommandTest, OdeToJoyJsonIsCompleteAndDeterministic) {
  FingeringOptions o{.input = ode()};
  const nlohmann::json doc = plan_json(o);
  EXPECT_EQ(doc["notes"].size(), 94u);
  const std::string first = bytes_of(file("plan.json"));
  plan_json(o);
  EXPECT_EQ(bytes_of(file("plan.json")), first);
}

TEST_F(FingeringCommandTest, ReportGoesToStdoutWithOutputFile) {
  const CommandRun r = run({.input = ode(), .output = file("o.json")});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.out.find("right hand: 62 notes"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("notes/s"), std::string::npos);
  // Without -o: the listing on stdout, the report on stderr.
  const CommandRun listing = run({.input = ode()});
  ASSERT_EQ(listing.code, kExitOk);
  EXPECT_NE(listing.out.find("onset_s"), std::string::npos);
  EXPECT_NE(listing.err.find("repairs:"), std::string::npos);
}

TEST_F(FingeringCommandTest, ThirdPartyPiecesAreFullyFingeredAndInside) {
  TUTTI_REQUIRE_TESTDATA();
  for (const auto& entry : fs::directory_iterator(test::testdata("musicxml/pianoplayer"))) {
    if (entry.path().extension() != ".xml") continue;
    SCOPED_TRACE(entry.path().string());
    plan_json({.input = entry.path()});
  }
  const nlohmann::json bach = plan_json({.input = test::testdata("midi/tonejs/bach_846.mid")});
  EXPECT_EQ(bach["notes"].size(), 1284u);
  // The default weights budget travel time for every hand shift (release_fraction), and the
  // corridors end when that travel starts: the path never has to jump, and it stays inside the
  // planner's own corridors.
  for (const char* hand : {"right", "left"}) {
    EXPECT_EQ(bach["hands"][hand]["repairs"]["jumps"].get<int>(), 0) << hand;
    EXPECT_EQ(
        bach["hands"][hand]["violations_original_corridors"]["violating_corridors"].get<int>(), 0)
        << hand;
  }
  // The paper's rules allow no early release, so legato shifts in the prelude become jumps that
  // the performance plan must repair (and reports).
  const nlohmann::json paper =
      plan_json({.input = test::testdata("midi/tonejs/bach_846.mid"), .weights = "paper"});
  EXPECT_GT(paper["hands"]["right"]["repairs"]["jumps"].get<int>(), 0);
}

TEST_F(FingeringCommandTest, LookaheadModeAndOtherOptionsWork) {
  const nlohmann::json doc = plan_json({.input = ode(),
                                        .mode = "lookahead",
                                        .lookahead = 3,
                                        .hand_size = "small",
                                        .weights = "paper"});
  EXPECT_EQ(doc["notes"].size(), 94u);
}

TEST_F(FingeringCommandTest, SmoothingOptionChoosesThePathAndReportsIt) {
  // The provably-inside smoothings: no violation of the planned corridors (plan_json checks).
  for (const char* smoothing : {"monotone_quintic", "pchip", "none"}) {
    SCOPED_TRACE(smoothing);
    const nlohmann::json doc = plan_json({.input = ode(), .smoothing = smoothing});
    EXPECT_EQ(doc["smoothing"], smoothing);
  }
  const nlohmann::json quintic = plan_json({.input = ode()});
  EXPECT_EQ(quintic["smoothing"], "monotone_quintic");  // the default

  // The paper's natural spline: the same fingering; the text report and the JSON agree on its
  // violations of the planned corridors, hand by hand.
  const CommandRun r =
      run({.input = ode(), .output = file("natural.json"), .smoothing = "natural_spline"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto natural = nlohmann::json::parse(bytes_of(file("natural.json")));
  EXPECT_EQ(natural["smoothing"], "natural_spline");
  EXPECT_EQ(natural["notes"], quintic["notes"]);  // smoothing never changes the fingering
  EXPECT_NE(r.out.find("hand paths: natural_spline smoothing\n"), std::string::npos) << r.out;
  for (const char* hand : {"right", "left"}) {
    const auto& h = natural["hands"][hand];
    char line[160];
    std::snprintf(line, sizeof line,
                  "%s hand: %d notes, %d events, %d diagnostics; path: %d violations (planned "
                  "corridors, worst %.1f mm)",
                  hand, h["notes"].get<int>(), h["events"].get<int>(), h["diagnostics"].get<int>(),
                  h["violations_planned_corridors"]["violating_corridors"].get<int>(),
                  h["violations_planned_corridors"]["worst_violation_mm"].get<double>());
    EXPECT_NE(r.out.find(line), std::string::npos) << line << "\n" << r.out;
  }

  const CommandRun bad = run({.input = ode(), .smoothing = "cubic"});
  EXPECT_EQ(bad.code, kExitBadInput);
  EXPECT_EQ(bad.err,
            "error: --smoothing: unknown smoothing 'cubic' (monotone_quintic, pchip, "
            "natural_spline or none)\n");
}

TEST_F(FingeringCommandTest, NaturalSplineLeavesTheCorridorsTheDefaultKeeps) {
  TUTTI_REQUIRE_TESTDATA();
  // A long two-hand piece: the paper's smoothing overshoots between the string's bends (issue 3
  // reports its violations beside the default's zero; the root README has every test piece).
  const fs::path bach = test::testdata("midi/tonejs/bach_846.mid");
  const nlohmann::json quintic = plan_json({.input = bach});
  const CommandRun r =
      run({.input = bach, .output = file("natural.json"), .smoothing = "natural_spline"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto natural = nlohmann::json::parse(bytes_of(file("natural.json")));
  std::size_t violating = 0;
  double worst = 0.0;
  for (const char* hand : {"right", "left"}) {
    const auto& used = natural["hands"][hand]["violations_planned_corridors"];
    violating += used["violating_corridors"].get<std::size_t>();
    worst = std::max(worst, used["worst_violation_mm"].get<double>());
    EXPECT_EQ(quintic["hands"][hand]["violations_planned_corridors"]["violating_corridors"], 0);
  }
  EXPECT_GT(violating, 0u);
  EXPECT_GT(worst, 0.0);
}

TEST_F(FingeringCommandTest, KeepFingersRespectsTheFilesMarks) {
  auto original = music::load_score(ode());
  ASSERT_TRUE(original.ok());
  int marked = 0;
  for (const auto& n : original->notes) marked += n.finger > 0;
  ASSERT_GT(marked, 0) << "the bundled Ode to Joy carries fingering";
  const nlohmann::json doc = plan_json({.input = ode(), .keep_fingers = true});
  ASSERT_EQ(doc["notes"].size(), original->notes.size());
  for (std::size_t i = 0; i < original->notes.size(); ++i) {
    if (original->notes[i].finger == 0) continue;
    EXPECT_EQ(doc["notes"][i]["finger"], original->notes[i].finger) << "note " << i;
  }
}

TEST_F(FingeringCommandTest, MusicXmlRoundTrip) {
  const nlohmann::json doc = plan_json({.input = ode()});
  const CommandRun r = run({.input = ode(), .output = file("out.musicxml")});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  auto original = music::load_score(ode());
  auto written = music::load_score(file("out.musicxml"));
  ASSERT_TRUE(original.ok() && written.ok());
  ASSERT_EQ(written->notes.size(), original->notes.size());
  for (std::size_t i = 0; i < written->notes.size(); ++i) {
    const music::Note& a = original->notes[i];
    const music::Note& b = written->notes[i];
    EXPECT_EQ(std::tie(a.pitch, a.onset_ticks, a.offset_ticks, a.part, a.staff, a.voice),
              std::tie(b.pitch, b.onset_ticks, b.offset_ticks, b.part, b.staff, b.voice))
        << i;
    EXPECT_EQ(b.finger, doc["notes"][i]["finger"].get<int>()) << i;
  }
}

TEST_F(FingeringCommandTest, MidiCarriesOneLyricLabelPerNote) {
  TUTTI_REQUIRE_TESTDATA();
  const fs::path in = test::testdata("midi/tonejs/bach_846.mid");
  const nlohmann::json doc = plan_json({.input = in});
  const CommandRun r = run({.input = in, .output = file("out.mid")});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  auto written = music::load_score(file("out.mid"));
  ASSERT_TRUE(written.ok()) << written.error().message;
  ASSERT_EQ(written->notes.size(), doc["notes"].size());
  // Labels by (tick, key): the fingers of the notes struck there, in any order.
  std::map<std::pair<std::int64_t, int>, std::multiset<int>> labels;
  for (const music::TextEvent& t : written->texts) {
    if (t.kind != music::TextKind::lyric) continue;
    auto label = parse_finger_label(t.text);
    ASSERT_TRUE(label.has_value()) << t.text;
    labels[{t.tick, label->key}].insert(label->finger);
  }
  std::multiset<std::tuple<int, int>> expected;  // (pitch, finger)
  std::multiset<std::tuple<int, int>> read_back;
  for (const auto& note : doc["notes"])
    expected.insert({note["pitch"].get<int>(), note["finger"].get<int>()});
  for (const music::Note& n : written->notes) {
    auto it = labels.find({n.onset_ticks, n.pitch});
    ASSERT_NE(it, labels.end()) << "no label at tick " << n.onset_ticks << " key " << n.pitch;
    ASSERT_FALSE(it->second.empty());
    read_back.insert({n.pitch, *it->second.begin()});
    it->second.erase(it->second.begin());
  }
  EXPECT_EQ(read_back, expected);
}

TEST_F(FingeringCommandTest, MidiLabelsArePinsWithKeepFingersAndNeverDuplicated) {
  const CommandRun first = run({.input = ode(), .output = file("a.mid"), .weights = "paper"});
  ASSERT_EQ(first.code, kExitOk) << first.err;
  // Re-planned with other weights but pinned to the labels: the same fingers come back.
  const CommandRun again =
      run({.input = file("a.mid"), .output = file("b.mid"), .keep_fingers = true});
  ASSERT_EQ(again.code, kExitOk) << again.err;
  auto a = music::load_score(file("a.mid"));
  auto b = music::load_score(file("b.mid"));
  ASSERT_TRUE(a.ok() && b.ok());
  std::size_t labels = 0;
  for (const auto& t : b->texts) labels += parse_finger_label(t.text).has_value();
  EXPECT_EQ(labels, b->notes.size());
  music::Score pa = *a;
  music::Score pb = *b;
  ASSERT_EQ(apply_finger_labels(pa), int(pa.notes.size()));
  ASSERT_EQ(apply_finger_labels(pb), int(pb.notes.size()));
  for (std::size_t i = 0; i < pa.notes.size(); ++i) {
    EXPECT_EQ(pa.notes[i].finger, pb.notes[i].finger) << i;
    EXPECT_EQ(pa.notes[i].hand, pb.notes[i].hand) << i;
  }
}

TEST_F(FingeringCommandTest, FingerLabelsParseStrictly) {
  EXPECT_EQ(finger_label(music::Hand::right, 3, 64), "RH3:64");
  auto label = parse_finger_label("LH5:48");
  ASSERT_TRUE(label.has_value());
  EXPECT_EQ(label->hand, music::Hand::left);
  EXPECT_EQ(label->finger, 5);
  EXPECT_EQ(label->key, 48);
  for (const char* bad : {"", "RH6:60", "XH1:60", "RH1:", "RH1:128", "RH1:60x", "Freude"}) {
    EXPECT_FALSE(parse_finger_label(bad).has_value()) << bad;
  }
}

TEST_F(FingeringCommandTest, PigOutputReadsBackAndIsDeterministic) {
  const nlohmann::json doc = plan_json({.input = ode()});
  const CommandRun r = run({.input = ode(), .output = file("out.txt")});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const std::string first = bytes_of(file("out.txt"));
  ASSERT_EQ(run({.input = ode(), .output = file("out.txt")}).code, kExitOk);
  EXPECT_EQ(bytes_of(file("out.txt")), first);
  auto pig = music::read_pig_file(file("out.txt"));
  ASSERT_TRUE(pig.ok()) << pig.error().message;
  std::multiset<std::tuple<int, int, std::string>> expected;
  std::multiset<std::tuple<int, int, std::string>> read_back;
  for (const auto& n : doc["notes"])
    expected.insert({n["pitch"].get<int>(), n["finger"].get<int>(), n["hand"].get<std::string>()});
  for (const auto& n : pig->notes) {
    read_back.insert({n.pitch, n.finger, n.hand == music::Hand::right ? "right" : "left"});
  }
  EXPECT_EQ(read_back, expected);
  // A PIG input's finger column is ignored unless --keep-fingers.
  EXPECT_EQ(run({.input = file("out.txt"), .output = file("again.json")}).code, kExitOk);
}

// PIG in, PIG out: the input's lines come back in their order with their ids, times, spellings and
// velocities; only the finger column is tutti's (a file written here in the dataset's style).
TEST_F(FingeringCommandTest, PigInPigOutKeepsTheLinesAndChangesOnlyTheFingers) {
  const std::string input =
      "//Version: PigletFormat 1.0\n"
      "0\t0.500000\t0.900000\tE4\t64\t-1\t0\t3\n"
      "1\t0.000000\t0.400000\tC4\t64\t-1\t0\t1_2_3\n"
      "2\t0.250000\t0.500000\tDb4\t64\t-1\t0\t2\n"
      "3\t0.000000\t1.000000\tC3\t64\t-1\t1\t-5\n"
      "4\t1.000000\t1.400000\tF#4\t64\t-1\t0\t4\n";
  std::ofstream(file("in.txt")) << input;
  const CommandRun r = run({.input = file("in.txt"), .output = file("out.txt"), .format = "pig"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  std::istringstream in_lines(input), out_lines(bytes_of(file("out.txt")));
  std::string a, b;
  std::getline(in_lines, a);
  std::getline(out_lines, b);  // the header line
  int lines = 0;
  while (std::getline(in_lines, a)) {
    ASSERT_TRUE(std::getline(out_lines, b)) << "missing line " << lines;
    EXPECT_EQ(a.substr(0, a.rfind('\t')), b.substr(0, b.rfind('\t'))) << b;
    const std::string finger = b.substr(b.rfind('\t') + 1);
    EXPECT_FALSE(finger.empty());
    EXPECT_NE(finger, "0") << b;
    ++lines;
  }
  EXPECT_EQ(lines, 5);
  EXPECT_FALSE(std::getline(out_lines, b)) << "extra line " << b;
}

void expect_one_error_line(const CommandRun& r) {
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST_F(FingeringCommandTest, ErrorsAreOneLineAndExitTwo) {
  expect_one_error_line(run({.input = file("missing.mid")}));
  expect_one_error_line(run({.input = ode(), .format = "svg"}));
  expect_one_error_line(run({.input = ode(), .mode = "greedy"}));
  expect_one_error_line(run({.input = ode(), .hand_size = "enormous"}));
  expect_one_error_line(run({.input = ode(), .output = file("out.docx")}));
  expect_one_error_line(run({.input = ode(), .weights = "no_such_weights"}));
  expect_one_error_line(run({.input = ode(), .format = "midi"}));  // binary needs -o
  expect_one_error_line(run({.input = ode(), .plot = file("p.png"), .plot_seconds = "3:1"}));
  EXPECT_FALSE(fs::exists(file("p.png")));
}

TEST_F(FingeringCommandTest, MusicXmlOutputNeedsMusicXmlInput) {
  TUTTI_REQUIRE_TESTDATA();
  const CommandRun r =
      run({.input = test::testdata("midi/tonejs/bach_846.mid"), .output = file("out.musicxml")});
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("MusicXML output needs a MusicXML input"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(file("out.musicxml")));
}

// PNG: 8-byte signature, then the IHDR chunk with big-endian width and height.
std::pair<std::uint32_t, std::uint32_t> png_size(const std::string& png) {
  EXPECT_GE(png.size(), 24u);
  if (png.size() < 24) return {0, 0};
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(png.substr(12, 4), "IHDR");
  const auto be32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t k = 0; k < 4; ++k) v = (v << 8) | std::uint8_t(png[at + k]);
    return v;
  };
  return {be32(16), be32(20)};
}

TEST_F(FingeringCommandTest, PlotHasTheDocumentedSizeAndIsDeterministic) {
  // 2 s window at 200 px/s + 10 px margins.
  ASSERT_EQ(
      run({.input = ode(), .output = file("a.json"), .plot = file("a.png"), .plot_seconds = "0:2"})
          .code,
      kExitOk);
  const std::string png = bytes_of(file("a.png"));
  const auto [width, height] = png_size(png);
  EXPECT_EQ(width, 420u);
  EXPECT_GT(height, 100u);
  EXPECT_LT(height, 1400u);
  ASSERT_EQ(
      run({.input = ode(), .output = file("a.json"), .plot = file("a.png"), .plot_seconds = "0:2"})
          .code,
      kExitOk);
  EXPECT_EQ(bytes_of(file("a.png")), png);
  // The whole piece is capped at 4000 px + margins.
  ASSERT_EQ(run({.input = ode(), .output = file("b.json"), .plot = file("b.png")}).code, kExitOk);
  EXPECT_EQ(png_size(bytes_of(file("b.png"))).first, 4020u);
}

}  // namespace
}  // namespace tutti::cli
