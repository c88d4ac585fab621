// SPDX-License-Identifier: MIT
// The keyboard family's instruments as data (content/piano/instruments.json): each one's compass,
// how a part's name (in four languages) or General MIDI program is recognised, and the loader's
// one-line errors.
#include <tutti/piano_model/keyboard_instruments.hpp>

#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include <tutti/piano_model/content_dir.hpp>
#include "scratch_dir.hpp"

namespace tutti::piano_model {
namespace {

KeyboardInstruments bundled() {
  auto loaded = KeyboardInstruments::load(keyboard_instruments_path(default_content_dir()));
  EXPECT_TRUE(loaded) << loaded.error().message;
  return loaded ? *loaded : KeyboardInstruments{};
}

std::string recognised(const KeyboardInstruments& all, std::vector<std::string> words,
                       int program) {
  const KeyboardInstrument* i = all.recognise(words, program);
  return i == nullptr ? "none" : i->id;
}

TEST(KeyboardInstruments, TheBundledFamilyAndItsCompasses) {
  const KeyboardInstruments all = bundled();
  EXPECT_EQ(all.ids(), (std::vector<std::string>{"celesta", "clavinet", "electric_piano",
                                                 "harpsichord", "organ", "piano", "synth"}));
  const KeyboardInstrument* piano = all.find("piano");
  ASSERT_NE(piano, nullptr);
  EXPECT_EQ(piano->lowest_key, 21);
  EXPECT_EQ(piano->highest_key, 108);
  EXPECT_EQ(piano->model, "piano.glb");
  const KeyboardInstrument* organ = all.find("organ");
  ASSERT_NE(organ, nullptr);
  EXPECT_EQ(organ->player, "organist");
  EXPECT_EQ(organ->highest_key - organ->lowest_key + 1, 61);
  EXPECT_TRUE(organ->contains(36) && organ->contains(96) && !organ->contains(35));
  // The organ's pedalboard: the AGO standard's 32 pedals C2-G4, naturals 63.5 mm apart.
  ASSERT_TRUE(organ->pedalboard);
  EXPECT_EQ(organ->pedalboard->lowest_key, 36);
  EXPECT_EQ(organ->pedalboard->highest_key, 67);
  EXPECT_DOUBLE_EQ(organ->pedalboard->natural_spacing_mm, 63.5);
  EXPECT_EQ(organ->pedalboard->split_below, 48);
  EXPECT_DOUBLE_EQ(organ->pedalboard->seat_raise_mm, 130.0);
  EXPECT_FALSE(organ->pedalboard->names.empty());
  EXPECT_FALSE(all.find("piano")->pedalboard) << "only the organ has pedals";
  EXPECT_DOUBLE_EQ(all.find("harpsichord")->octave_span_mm, 152.4);
  EXPECT_DOUBLE_EQ(organ->octave_span_mm, 0.0) << "the piano's keys";
  EXPECT_EQ(all.find("accordion"), nullptr) << "out of scope, named in the file's description";
}

TEST(KeyboardInstruments, PartsAreRecognisedByNameThenByProgram) {
  const KeyboardInstruments all = bundled();
  EXPECT_EQ(recognised(all, {"organ"}, -1), "organ");
  EXPECT_EQ(recognised(all, {"orgel"}, -1), "organ");
  EXPECT_EQ(recognised(all, {"organo"}, -1), "organ");
  EXPECT_EQ(recognised(all, {"orgue"}, -1), "organ");
  EXPECT_EQ(recognised(all, {"cembalo"}, -1), "harpsichord");
  EXPECT_EQ(recognised(all, {"clavecin"}, -1), "harpsichord");
  EXPECT_EQ(recognised(all, {"celesta"}, -1), "celesta");
  EXPECT_EQ(recognised(all, {"synthesizers"}, -1), "synth") << "a plural is the instrument";
  // The longest name wins: an electric piano is not the piano.
  EXPECT_EQ(recognised(all, {"electric", "piano"}, 0), "electric_piano");
  EXPECT_EQ(recognised(all, {"e", "piano"}, -1), "electric_piano");
  EXPECT_EQ(recognised(all, {"piano", "elettrico"}, -1), "electric_piano");
  EXPECT_EQ(recognised(all, {"piano", "right"}, -1), "piano");
  // No name: the General MIDI program (0-based).
  EXPECT_EQ(recognised(all, {"track", "3"}, 19), "organ");    // Church Organ
  EXPECT_EQ(recognised(all, {}, 80), "synth");                // Lead 1 (square)
  EXPECT_EQ(recognised(all, {}, 103), "synth");               // FX 8 (sci-fi)
  EXPECT_EQ(recognised(all, {}, 6), "harpsichord");
  EXPECT_EQ(recognised(all, {}, 21), "none");                 // Accordion
  EXPECT_EQ(recognised(all, {"violin"}, 40), "none");
  // A name beats the program: a part called "Organ" left at program 0.
  EXPECT_EQ(recognised(all, {"organ"}, 0), "organ");
}

class KeyboardInstrumentErrors : public ::testing::Test {
 protected:
  std::string error_of(const nlohmann::json& document) {
    const std::filesystem::path file = dir_.path() / "instruments.json";
    std::ofstream(file) << document.dump();
    auto loaded = KeyboardInstruments::load(file);
    return loaded ? "(loaded)" : loaded.error().message;
  }
  nlohmann::json valid() {
    return nlohmann::json::parse(R"({"instruments": {
      "organ": {"player": "organist", "lowest_key": 36, "highest_key": 96, "programs": [19],
                "names": ["organ"], "model": "keyboard_organ.glb"}}})");
  }
  tutti::test::ScratchDir dir_{"tutti_keyboards_"};
};

TEST_F(KeyboardInstrumentErrors, OneLineNamingTheFileAndPath) {
  EXPECT_EQ(error_of(valid()), "(loaded)");
  nlohmann::json doc = valid();
  doc["instruments"]["organ"]["pedals"] = true;
  EXPECT_NE(error_of(doc).find("instruments.json: /instruments/organ/pedals: unknown key"),
            std::string::npos)
      << error_of(doc);
  doc = valid();
  doc["instruments"]["organ"]["highest_key"] = 128;
  EXPECT_EQ(error_of(doc),
            "instruments.json: /instruments/organ/highest_key: must be a MIDI key, an integer in "
            "[0, 127]");
  doc = valid();
  doc["instruments"]["organ"]["highest_key"] = 40;
  EXPECT_EQ(error_of(doc),
            "instruments.json: /instruments/organ/highest_key: a keyboard spans at least two "
            "octaves");
  doc = valid();
  doc["instruments"]["harmonium"] = doc["instruments"]["organ"];  // read first: ids in order
  EXPECT_EQ(error_of(doc),
            "instruments.json: /instruments/organ/programs: program 19 is also harmonium's");
  doc = valid();
  doc["instruments"]["organ"]["names"] = nlohmann::json::array();
  EXPECT_EQ(error_of(doc),
            "instruments.json: /instruments/organ/names: expected a non-empty array of part names");
  doc = valid();
  doc["instruments"]["organ"]["case"] = {{"cheek_width_mm", 50},
                                         {"cabinet_height_mm", 100},
                                         {"cabinet_depth_mm", 500},
                                         {"color", {0.1, 0.1, 0.1}}};
  EXPECT_NE(error_of(doc).find("/instruments/organ/case/cabinet_height_mm"), std::string::npos)
      << error_of(doc);
  EXPECT_NE(error_of(nlohmann::json::object()).find("/instruments"), std::string::npos);
}

TEST_F(KeyboardInstrumentErrors, APedalboardIsCheckedToo) {
  nlohmann::json doc = valid();
  doc["instruments"]["organ"]["pedalboard"] = {{"lowest_key", 36}, {"highest_key", 67},
                                               {"natural_spacing_mm", 63.5}, {"split_below", 48},
                                               {"names", {"pedal"}}};
  EXPECT_EQ(error_of(doc), "(loaded)");
  nlohmann::json bad = doc;
  bad["instruments"]["organ"]["pedalboard"]["heels"] = true;
  EXPECT_NE(error_of(bad).find("instruments.json: /instruments/organ/pedalboard/heels: unknown key"),
            std::string::npos)
      << error_of(bad);
  bad = doc;
  bad["instruments"]["organ"]["pedalboard"]["highest_key"] = 40;
  EXPECT_EQ(error_of(bad), "instruments.json: /instruments/organ/pedalboard/highest_key: a "
                           "pedalboard spans at least an octave");
  bad = doc;
  bad["instruments"]["organ"]["pedalboard"]["natural_spacing_mm"] = 200;
  EXPECT_EQ(error_of(bad), "instruments.json: /instruments/organ/pedalboard/natural_spacing_mm: "
                           "must be in [40, 90] mm");
  bad = doc;
  bad["instruments"]["organ"]["pedalboard"].erase("split_below");
  EXPECT_NE(error_of(bad).find("/instruments/organ/pedalboard/split_below"), std::string::npos)
      << error_of(bad);
  bad = doc;
  bad["instruments"]["organ"]["pedalboard"]["names"] = {"", "pedal"};
  EXPECT_EQ(error_of(bad), "instruments.json: /instruments/organ/pedalboard/names/0: expected a "
                           "name with a word");
  bad = doc;
  bad["instruments"]["organ"]["pedalboard"]["seat_raise_mm"] = -5;
  EXPECT_EQ(error_of(bad), "instruments.json: /instruments/organ/pedalboard/seat_raise_mm: must "
                           "be in [0, 300] mm");
  bad = doc;
  bad["instruments"]["organ"]["octave_span_mm"] = 200;
  EXPECT_EQ(error_of(bad), "instruments.json: /instruments/organ/octave_span_mm: must be in "
                           "[125, 170] mm");
  bad = doc;
  bad["instruments"]["organ"]["pedalboard"] = 32;
  EXPECT_EQ(error_of(bad), "instruments.json: /instruments/organ/pedalboard: expected an object");
}

}  // namespace
}  // namespace tutti::piano_model
