// SPDX-License-Identifier: MIT
// The editor's performance marks in a scene file: breath marks, expressions, finger pins, cues.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

#include <tutti/brass/brass_players.hpp>
#include <tutti/piano/keyboard_players.hpp>
#include <tutti/scene/load_scene.hpp>
#include <tutti/performance/families.hpp>
#include "scene_test_support.hpp"

namespace tutti::scene {
namespace {

using nlohmann::json;
using test::error_of;
using test::scenes_dir;

json scene_with_marks() {
  return json::parse(R"({
    "music": "../music/quartet.musicxml",
    "performers": [
      {"name": "T1", "instrument": "trumpet_bb", "part": "Trumpet 1", "position_m": [-1, 0, 0],
       "breaths": {"add": [9.5, 3.25], "remove": [12]},
       "expressions": [{"kind": "relaxed", "start_s": 20, "end_s": 24},
                       {"kind": "strain", "start_s": 4, "end_s": 6.5, "amount": 0.7}]}
    ],
    "pianist": {"parts": ["Trombone 2"],
                "pins": [{"time_s": 2.5, "key": 50, "finger": 3},
                         {"time_s": 1.0, "key": 48, "finger": 1}]},
    "cues": [16, 4.5],
    "cameras": [{"name": "wide", "position_m": [0, 1.6, 6], "target_m": [0, 1.1, 0]}]
  })");
}

TEST(PerformanceMarks, AreReadAndSorted) {
  auto scene = parse_scene(scene_with_marks(), "s.json", scenes_dir(), performance::scene_load_options());
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  const brass::BrassPlayer& t1 = brass::brass_players(*scene)[0];
  EXPECT_EQ(t1.breaths.add_s, (std::vector<double>{3.25, 9.5}));
  EXPECT_EQ(t1.breaths.remove_s, (std::vector<double>{12.0}));
  ASSERT_EQ(t1.expressions.size(), 2u);
  EXPECT_EQ(t1.expressions[0].kind, ExpressionKind::strain);
  EXPECT_DOUBLE_EQ(t1.expressions[0].start_s, 4.0);
  EXPECT_DOUBLE_EQ(t1.expressions[0].end_s, 6.5);
  EXPECT_DOUBLE_EQ(t1.expressions[0].amount, 0.7);
  EXPECT_EQ(t1.expressions[1].kind, ExpressionKind::relaxed);
  EXPECT_DOUBLE_EQ(t1.expressions[1].amount, 1.0);  // the default
  ASSERT_EQ(piano::keyboard_players(*scene).size(), 1u);
  ASSERT_EQ(piano::keyboard_players(*scene).front().pins.size(), 2u);
  EXPECT_EQ(piano::keyboard_players(*scene).front().pins[0], (piano::FingerPin{2.5, 50, 3}))
      << "pins keep the file's order";
  EXPECT_EQ(piano::keyboard_players(*scene).front().pins[1], (piano::FingerPin{1.0, 48, 1}));
  ASSERT_TRUE(scene->cues_s.has_value());
  EXPECT_EQ(*scene->cues_s, (std::vector<double>{4.5, 16.0}));
}

TEST(PerformanceMarks, AbsentMeansNone) {
  json doc = scene_with_marks();
  doc.erase("cues");
  doc["performers"][0].erase("breaths");
  doc["performers"][0].erase("expressions");
  doc["pianist"].erase("pins");
  auto scene = parse_scene(doc, "s.json", scenes_dir(), performance::scene_load_options());
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_FALSE(scene->cues_s.has_value()) << "no list: the automatic cue";
  EXPECT_TRUE(brass::brass_players(*scene)[0].breaths.add_s.empty());
  EXPECT_TRUE(brass::brass_players(*scene)[0].expressions.empty());
  EXPECT_TRUE(piano::keyboard_players(*scene).front().pins.empty());
  doc["cues"] = json::array();
  auto no_cues = parse_scene(doc, "s.json", scenes_dir(), performance::scene_load_options());
  ASSERT_TRUE(no_cues.ok());
  ASSERT_TRUE(no_cues->cues_s.has_value()) << "an empty list: no cue at all";
  EXPECT_TRUE(no_cues->cues_s->empty());
}

TEST(PerformanceMarks, BadMarksAreOneLineErrors) {
  json doc = scene_with_marks();
  doc["performers"][0]["breaths"]["add"][1] = "soon";
  EXPECT_EQ(error_of(doc), "s.json: /performers/0/breaths/add/1: expected a time in seconds");
  doc = scene_with_marks();
  doc["performers"][0]["breaths"]["when"] = json::array();
  EXPECT_EQ(error_of(doc), "s.json: /performers/0/breaths/when: unknown key");
  doc = scene_with_marks();
  doc["performers"][0]["breaths"]["remove"] = 12;
  EXPECT_EQ(error_of(doc),
            "s.json: /performers/0/breaths/remove: expected an array of times in seconds");
  doc = scene_with_marks();
  doc["performers"][0]["expressions"][0]["kind"] = "angry";
  EXPECT_EQ(error_of(doc),
            "s.json: /performers/0/expressions/0/kind: must be \"strain\" or \"relaxed\"");
  doc = scene_with_marks();
  doc["performers"][0]["expressions"][1]["end_s"] = 4;
  EXPECT_EQ(error_of(doc),
            "s.json: /performers/0/expressions/1/end_s: must be later than start_s (4 s)");
  doc = scene_with_marks();
  doc["performers"][0]["expressions"][1]["amount"] = 2;
  EXPECT_EQ(error_of(doc), "s.json: /performers/0/expressions/1/amount: must be in [0, 1]");
  doc = scene_with_marks();
  doc["pianist"]["pins"][0]["finger"] = 6;
  EXPECT_EQ(error_of(doc), "s.json: /pianist/pins/0/finger: must be in [1, 5]");
  doc = scene_with_marks();
  doc["pianist"]["pins"][0].erase("key");
  EXPECT_EQ(error_of(doc), "s.json: /pianist/pins/0/key: missing");
  doc = scene_with_marks();
  doc["pianist"]["pins"][1] = doc["pianist"]["pins"][0];
  EXPECT_EQ(error_of(doc),
            "s.json: /pianist/pins/1: a second pin on the same note (also /pianist/pins/0)");
  doc = scene_with_marks();
  doc["cues"][0] = 1e9;
  EXPECT_EQ(error_of(doc), "s.json: /cues/0: must be in [-60, 86400] s");
}

}  // namespace
}  // namespace tutti::scene
