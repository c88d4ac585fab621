// SPDX-License-Identifier: MIT
// Loading content/instruments: every shipped file loads; a broken file gives one line naming
// the file and the JSON path; overrides and optional parts of the format work.
#include <tutti/brass_model/instrument_file.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "brass_fixture.hpp"
#include <tutti/content/json_reader.hpp>
#include "testdata.hpp"

namespace tutti::brass_model {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::key;

fs::path shipped_file(const std::string& id) {
  return fs::path(TUTTI_CONTENT_DIR) / "instruments" / (id + ".json");
}

json shipped_json(const std::string& id) {
  auto doc = content::read_json_file(shipped_file(id));
  if (!doc) ADD_FAILURE() << doc.error().message;
  return doc ? *doc : json{};
}

// Writes `doc` as <tmp>/<stem>.json and loads it.
Result<Instrument> load_modified(const json& doc, const std::string& stem) {
  const fs::path folder = tutti::test::unique_temp_path("instruments");
  fs::create_directories(folder);
  const fs::path file = folder / (stem + ".json");
  std::ofstream(file) << doc.dump(2);
  auto result = load_instrument(file);
  fs::remove_all(folder);
  return result;
}

// The error of loading `doc`, which must fail; it names the file.
std::string error_of(const json& doc, const std::string& stem) {
  auto result = load_modified(doc, stem);
  if (result.ok()) {
    ADD_FAILURE() << "loaded a broken file";
    return {};
  }
  const std::string& message = result.error().message;
  EXPECT_NE(message.find(stem + ".json: "), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  return message;
}

TEST(InstrumentFile, EveryShippedFileLoads) {
  const std::vector<std::string> required = {"euphonium",  "horn_double", "trombone_tenor",
                                             "trumpet_bb", "trumpet_c",   "tuba"};
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(fs::path(TUTTI_CONTENT_DIR) / "instruments")) {
    if (entry.path().extension() != ".json") continue;
    files.push_back(entry.path().stem().string());
    auto one = load_instrument(entry.path());
    ASSERT_TRUE(one.ok()) << one.error().message;
    EXPECT_EQ(one->id, entry.path().stem().string());
    EXPECT_FALSE(one->names.empty());
    EXPECT_FALSE(one->chart.empty());
  }
  std::sort(files.begin(), files.end());
  for (const std::string& id : required) {
    EXPECT_NE(std::find(files.begin(), files.end(), id), files.end()) << id;
  }
  auto all = load_all_instruments();
  ASSERT_TRUE(all.ok()) << all.error().message;
  ASSERT_EQ(all->size(), files.size());
  for (std::size_t i = 0; i < files.size(); ++i) EXPECT_EQ((*all)[i].id, files[i]);  // sorted

  auto trumpet = load_instrument_by_id("trumpet_bb");
  ASSERT_TRUE(trumpet.ok()) << trumpet.error().message;
  EXPECT_EQ(trumpet->display_name, "B♭ trumpet");
  EXPECT_EQ(trumpet->gm_programs.front(), 56);
  EXPECT_EQ(test::instrument("trombone_tenor").gm_programs.front(), 57);
  EXPECT_EQ(test::instrument("tuba").gm_programs.front(), 58);
  EXPECT_EQ(test::instrument("horn_double").gm_programs.front(), 60);
  EXPECT_FALSE(load_instrument_by_id("../piano/hands").ok());
  auto missing = load_instrument_by_id("kazoo");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().message.find("kazoo.json: no such file"), std::string::npos);
}

TEST(InstrumentFile, ContentDirectoryFromTheEnvironment) {
  const fs::path folder = tutti::test::unique_temp_path("content");
  fs::create_directories(folder / "instruments");
  fs::copy_file(shipped_file("tuba"), folder / "instruments" / "tuba.json");
  ::setenv("TUTTI_CONTENT_DIR", folder.c_str(), 1);
  auto all = load_all_instruments();
  auto trumpet = load_instrument_by_id("trumpet_bb");
  fs::remove(folder / "instruments" / "tuba.json");
  auto none = load_all_instruments();
  ::unsetenv("TUTTI_CONTENT_DIR");
  fs::remove_all(folder);
  ASSERT_TRUE(all.ok()) << all.error().message;
  ASSERT_EQ(all->size(), 1u);
  EXPECT_EQ(all->front().id, "tuba");
  EXPECT_FALSE(trumpet.ok());
  ASSERT_FALSE(none.ok());
  EXPECT_NE(none.error().message.find("no instrument files"), std::string::npos);
}

TEST(InstrumentFile, BrokenFilesNameTheFileAndThePath) {
  const json good = shipped_json("trumpet_bb");
  ASSERT_TRUE(load_modified(good, "trumpet_bb").ok());
  struct Case {
    const char* what;
    json doc;
    const char* expected;  // substring of the message after "<file>: "
  };
  std::vector<Case> cases;
  auto with = [&](const char* what, auto edit, const char* expected) {
    json doc = good;
    edit(doc);
    cases.push_back({what, doc, expected});
  };
  with(
      "unknown top-level key", [](json& d) { d["colour"] = "gold"; }, "/colour: unknown key");
  with(
      "unknown nested key", [](json& d) { d["mechanism"]["valves"][1]["colour"] = 1; },
      "/mechanism/valves/1/colour: unknown key");
  with(
      "missing field", [](json& d) { d.erase("gm_programs"); }, "/gm_programs: missing");
  with(
      "model not a name", [](json& d) { d["model"] = "../trumpet"; },
      "/model: expected lower-case letters, digits and '_'");
  with(
      "model not a string", [](json& d) { d["model"] = 3; }, "/model: expected a string");
  with(
      "missing range end", [](json& d) { d["range"].erase("highest"); }, "/range/highest: missing");
  with(
      "range upside down", [](json& d) { d["range"]["lowest"] = "C7"; },
      "/range/highest: must not be below /range/lowest");
  with(
      "bad pitch", [](json& d) { d["range"]["lowest"] = "H2"; },
      "/range/lowest: \"H2\" is not a pitch name");
  with(
      "range the physics cannot play", [](json& d) { d["range"]["lowest"] = "C3"; },
      "/range: no fingering plays written C3");
  with(
      "wrong type", [](json& d) { d["transposition_semitones"] = "-2"; },
      "/transposition_semitones: expected a whole number");
  with(
      "program out of range", [](json& d) { d["gm_programs"][0] = 128; },
      "/gm_programs/0: must be in 0..127");
  with(
      "upper-case name", [](json& d) { d["names"][0] = "Trumpet"; },
      "/names/0: expected lower-case words");
  with(
      "id not the file name", [](json& d) { d["id"] = "cornet"; },
      "/id: \"cornet\" differs from the file name \"trumpet_bb\"");
  with(
      "unknown mechanism", [](json& d) { d["mechanism"]["kind"] = "keys"; },
      "/mechanism/kind: expected \"valves\" or \"slide\"");
  with(
      "valve without a lowering",
      [](json& d) { d["mechanism"]["valves"][2].erase("lowers_semitones"); },
      "/mechanism/valves/2/lowers_semitones: missing");
  with(
      "repeated valve", [](json& d) { d["mechanism"]["valves"][2]["name"] = "1"; },
      "/mechanism/valves/2/name: repeats \"1\"");
  with(
      "partials out of order",
      [](json& d) {
        d["harmonic_series"]["partials"] = {2, 4, 3};
      },
      "/harmonic_series/partials/2: partials must be in ascending order");
  with(
      "unknown valve in the preference",
      [](json& d) { d["conventions"]["combination_preference"][1] = "4"; },
      "/conventions/combination_preference/1: \"4\" is not a combination of the valves");
  with(
      "rule partial not in the series",
      [](json& d) {
        d["conventions"]["standard"][0]["partials"] = {2, 3, 20};
      },
      "/conventions/standard/0/partials/2: partial 20 is not in /harmonic_series/partials");
  with(
      "rule allowing nothing",
      [](json& d) {
        d["conventions"]["standard"][0]["valves_up"] = {"1", "2", "3"};
      },
      "/conventions/standard/0: allows no fingering of written F#3");
  with(
      "override of a fingering the chart lacks",
      [](json& d) {
        d["overrides"] = {{{"written", "G4"}, {"standard", "2"}}};
      },
      "/overrides/0/standard: the chart has no \"2\" for G4");
  with(
      "override outside the range",
      [](json& d) {
        d["overrides"] = {{{"written", "C2"}, {"standard", "open"}}};
      },
      "/overrides/0/written: outside the range");
  with(
      "added fingering that plays another note",
      [](json& d) {
        d["overrides"] = {{{"written", "G4"}, {"add", {{{"fingering", "1"}, {"partial", 7}}}}}};
      },
      "/overrides/0/add/0: \"1\" on partial 7 plays G#5, not G4");
  for (const Case& c : cases) {
    const std::string message = error_of(c.doc, "trumpet_bb");
    EXPECT_NE(message.find(std::string("trumpet_bb.json: ") + c.expected), std::string::npos)
        << c.what << ": " << message;
  }
}

TEST(InstrumentFile, NotJsonAndMissingFiles) {
  const fs::path folder = tutti::test::unique_temp_path("broken");
  fs::create_directories(folder);
  std::ofstream(folder / "bad.json") << "{ \"id\": \"bad\", ";
  auto not_json = load_instrument(folder / "bad.json");
  auto missing = load_instrument(folder / "nothing.json");
  fs::remove_all(folder);
  ASSERT_FALSE(not_json.ok());
  EXPECT_NE(not_json.error().message.find("bad.json: not valid JSON"), std::string::npos)
      << not_json.error().message;
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().message.find("nothing.json: no such file"), std::string::npos)
      << missing.error().message;
}

TEST(InstrumentFile, OverridesChangeTheChart) {
  json doc = shipped_json("trumpet_bb");
  doc["overrides"] = {{{"written", "D6"}, {"standard", "open"}, {"reason", "the 9th partial"}},
                      {{"written", "G#5"}, {"add", {{{"fingering", "1"}, {"partial", 7}}}}},
                      {{"written", "A4"}, {"remove", {"3"}}}};
  auto changed = load_modified(doc, "trumpet_bb");
  ASSERT_TRUE(changed.ok()) << changed.error().message;
  using V = std::vector<std::string>;
  const auto d6 = changed->fingerings(key("D6"));
  EXPECT_EQ(fingering_name(*changed, d6.front()), "open");
  EXPECT_EQ(d6.front().partial, 9);
  EXPECT_EQ(d6.front().rank, 0);
  EXPECT_EQ(fingering_name(*changed, d6[1]), "1");  // the former standard, now the first alternate
  // A 7th-partial valve fingering only when an override adds it: flat by the partial's 31 cents.
  const auto g5 = changed->fingerings(key("G#5"));
  EXPECT_EQ(fingering_name(*changed, g5.back()), "1");
  EXPECT_EQ(g5.back().partial, 7);
  EXPECT_NEAR(g5.back().cents, -31.2f, 0.1f);
  EXPECT_GT(g5.back().rank, 0);
  EXPECT_EQ(test::names(*changed, key("A4")), (V{"1-2"}));
  // Everything else as shipped.
  const Instrument& shipped = test::instrument("trumpet_bb");
  EXPECT_EQ(test::names(*changed, key("C#4")), test::names(shipped, key("C#4")));
}

TEST(InstrumentFile, ATromboneWithoutTheFAttachment) {
  json doc = shipped_json("trombone_tenor");
  doc["id"] = "trombone_straight";
  doc["mechanism"].erase("trigger");
  doc["conventions"]["combination_preference"] = {"open"};
  doc["conventions"]["standard"].erase(0);
  doc["conventions"]["standard"][0].erase("valves_up");
  // The gap below E2 is not playable any more; the loader says so.
  EXPECT_NE(error_of(doc, "trombone_straight").find("/range: no fingering plays written C#2"),
            std::string::npos);
  doc["range"]["lowest"] = "E2";
  auto straight = load_modified(doc, "trombone_straight");
  ASSERT_TRUE(straight.ok()) << straight.error().message;
  EXPECT_TRUE(straight->valves.empty());
  const Instrument& with_trigger = test::instrument("trombone_tenor");
  for (int w = key("E2"); w <= key("F5"); ++w) {
    EXPECT_EQ(test::standard(*straight, w), test::standard(with_trigger, w));
    for (const Fingering& f : straight->fingerings(w)) EXPECT_EQ(f.valves, 0);
  }
  EXPECT_EQ(test::names(*straight, key("C3")), (std::vector<std::string>{"6"}));
}

TEST(InstrumentFile, TheArmsReachIsOptionalAndChecked) {
  json doc = shipped_json("trombone_tenor");
  EXPECT_DOUBLE_EQ(test::instrument("trombone_tenor").slide_reach_mm,
                   doc["mechanism"]["reach_mm"].get<double>());
  doc["mechanism"]["reach_mm"] = -5;
  EXPECT_NE(error_of(doc, "trombone_tenor").find("/mechanism/reach_mm: must be a number in"),
            std::string::npos);
  doc["mechanism"]["reach_mm"] = "far";
  EXPECT_NE(error_of(doc, "trombone_tenor").find("/mechanism/reach_mm: "), std::string::npos);
  doc["mechanism"].erase("reach_mm");
  auto unlimited = load_modified(doc, "trombone_tenor");
  ASSERT_TRUE(unlimited.ok()) << unlimited.error().message;
  EXPECT_EQ(unlimited->slide_reach_mm, 0.0);
}

}  // namespace
}  // namespace tutti::brass_model
