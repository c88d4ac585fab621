// SPDX-License-Identifier: MIT
// Contacts as data: every key the pianist presses to its bed lies inside a span of a fingertip's
// contact with that key, stopping that pitch; brass players hold their instruments by fingertips,
// palms and lips; each span's point is where its body node was; the same frames give the same
// contacts.
#include <tutti/stage/contact_recorder.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "bundled_stage.hpp"
#include <tutti/stage/contact_detector.hpp>

namespace tutti::stage {
namespace {

// Stops are of the kinds their families name.
constexpr double kFps = 60.0;

std::vector<Contact> record(Stage& stage, double seconds) {
  ContactRecorder recorder;
  for (int k = 0; k < static_cast<int>(seconds * kFps); ++k) {
    const double t = stage.start_s() + k / kFps;
    evaluate_stage(stage, t);
    recorder.record(stage, t);
  }
  return recorder.contacts();
}

const std::string& node_name(const Stage& stage, std::size_t instance, int node) {
  return stage.placed(instance).asset->nodes[static_cast<std::size_t>(node)].name;
}

TEST(ContactRecorder, EveryKeyThePianistPressesIsInsideAFingertipsContactWithIt) {
  auto stage = test::stage_bundled_scene("piano.json");
  ASSERT_NE(stage, nullptr);
  const std::vector<Contact> contacts = record(*stage, 8.0);
  ASSERT_FALSE(contacts.empty());
  for (const Contact& contact : contacts) {
    EXPECT_NE(node_name(*stage, contact.body_instance, contact.body_node).find("_tip_"),
              std::string::npos);
    const std::string key = node_name(*stage, contact.part_instance, contact.part_node);
    ASSERT_EQ(key.rfind("key_", 0), 0U) << key;
    for (const ContactSpan& span : contact.spans) {
      EXPECT_LE(span.from_s, span.to_s);
      EXPECT_EQ("key_" + std::to_string(span.midi), key);
    }
    for (std::size_t i = 1; i < contact.spans.size(); ++i) {
      EXPECT_GT(contact.spans[i].from_s, contact.spans[i - 1].to_s);
    }
  }
  const std::vector<Stop> stops = detect_stops(*stage, {stage->start_s(), stage->start_s() + 7.9,
                                                        0.002, false});
  int downs = 0;
  for (const Stop& stop : stops) {
    if (!test::stop_is(stop, "key_down")) continue;
    ++downs;
    const bool covered = std::any_of(contacts.begin(), contacts.end(), [&](const Contact& c) {
      return c.performer == stop.performer &&
             std::any_of(c.spans.begin(), c.spans.end(), [&](const ContactSpan& span) {
               // Frames see a span; the stop lies between two of them.
               return span.midi == stop.value && span.from_s - 1.0 / kFps <= stop.t_s &&
                      stop.t_s <= span.to_s + 1.0 / kFps;
             });
    });
    EXPECT_TRUE(covered) << "key " << stop.value << " down at " << stop.t_s << " s";
  }
  EXPECT_GT(downs, 10);
}

TEST(ContactRecorder, BrassPlayersHoldTheirInstrumentsByFingertipsPalmsAndLips) {
  auto stage = test::stage_bundled_scene("quartet.json");
  ASSERT_NE(stage, nullptr);
  const std::vector<Contact> contacts = record(*stage, 6.0);
  int valves = 0, lips = 0, slide_grips = 0;
  for (const Contact& contact : contacts) {
    const std::string body = node_name(*stage, contact.body_instance, contact.body_node);
    const std::string part = node_name(*stage, contact.part_instance, contact.part_node);
    EXPECT_EQ(stage->placed(contact.body_instance).performer, contact.performer);
    EXPECT_EQ(stage->placed(contact.part_instance).performer, contact.performer);
    if (part.rfind("valve_", 0) == 0) ++valves;
    if (part == "mouthpiece" && body == "mouth") ++lips;
    if (part == "grip_right" && body == "grip_r") ++slide_grips;
    for (const ContactSpan& span : contact.spans) EXPECT_EQ(span.midi, -1);
  }
  EXPECT_EQ(valves, 6);       // two trumpets, three buttons each
  EXPECT_EQ(lips, 4);         // every player's lips on the mouthpiece
  EXPECT_EQ(slide_grips, 2);  // each trombonist's right palm on the slide
}

TEST(ContactRecorder, APointIsWhereItsBodyNodeWasInThePartsFrame) {
  auto stage = test::stage_bundled_scene("piano.json");
  ASSERT_NE(stage, nullptr);
  const std::vector<Contact> contacts = record(*stage, 4.0);
  ASSERT_FALSE(contacts.empty());
  // A fingertip holding a key rests on its top: within a few centimetres of the key node's
  // origin across and above it, and along the key's length.
  for (const Contact& contact : contacts) {
    for (const ContactSpan& span : contact.spans) {
      EXPECT_LT(std::abs(span.part_point_m.x), 0.015);
      EXPECT_GT(span.part_point_m.y, -0.01);
      EXPECT_LT(span.part_point_m.y, 0.03);
      EXPECT_GT(span.part_point_m.z, 0.0);
      EXPECT_LT(span.part_point_m.z, 0.2);
    }
  }
}

// Where a finger holds its key down, its tip stays on its spot on the key while the hand moves
// in or out for other fingers (it slid up to 12 mm along the key before the fingers took up the
// hand's move). Fingers 2-5, from 100 ms after a span starts to 100 ms before it ends (the
// stroke and the release move the tip with the key).
TEST(ContactRecorder, AFingerHoldingItsKeyStaysOnItsSpot) {
  auto stage = test::stage_bundled_scene("piano.json");
  ASSERT_NE(stage, nullptr);
  const double seconds = stage->end_s() - stage->start_s();
  const std::vector<Contact> contacts = record(*stage, seconds);
  std::vector<glm::mat4> body_world, part_world;
  double worst = 0.0;
  std::size_t held = 0;
  for (int k = 0; k < static_cast<int>(seconds * kFps); ++k) {
    const double t = stage->start_s() + k / kFps;
    bool posed = false;
    for (const Contact& c : contacts) {
      if (node_name(*stage, c.body_instance, c.body_node).rfind("thumb", 0) == 0) continue;
      for (const ContactSpan& span : c.spans) {
        if (t < span.from_s + 0.1 || t > span.to_s - 0.1) continue;
        if (!posed) {
          evaluate_stage(*stage, t);
          posed = true;
        }
        const PlacedModel& body = stage->placed(c.body_instance);
        const PlacedModel& part = stage->placed(c.part_instance);
        body_world.resize(body.asset->nodes.size());
        part_world.resize(part.asset->nodes.size());
        model::compute_world_matrices(*body.asset, body.pose, body.root, body_world);
        model::compute_world_matrices(*part.asset, part.pose, part.root, part_world);
        const glm::dvec3 at(part_world[static_cast<std::size_t>(c.part_node)] *
                            glm::vec4(glm::vec3(span.part_point_m), 1.0f));
        const glm::dvec3 tip(body_world[static_cast<std::size_t>(c.body_node)][3]);
        worst = std::max(worst, 1000.0 * glm::distance(at, tip));
        ++held;
      }
    }
  }
  EXPECT_GT(held, 500U);
  EXPECT_LT(worst, 3.0) << "a held fingertip " << worst << " mm off its spot";
}

TEST(ContactRecorder, TheSameFramesGiveTheSameContacts) {
  auto a = test::stage_bundled_scene("quartet.json");
  auto b = test::stage_bundled_scene("quartet.json");
  ASSERT_NE(a, nullptr);
  ASSERT_NE(b, nullptr);
  const std::vector<Contact> first = record(*a, 2.0);
  const std::vector<Contact> second = record(*b, 2.0);
  ASSERT_EQ(first.size(), second.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].body_node, second[i].body_node);
    EXPECT_EQ(first[i].part_node, second[i].part_node);
    ASSERT_EQ(first[i].spans.size(), second[i].spans.size());
    for (std::size_t s = 0; s < first[i].spans.size(); ++s) {
      EXPECT_EQ(first[i].spans[s].from_s, second[i].spans[s].from_s);
      EXPECT_EQ(first[i].spans[s].to_s, second[i].spans[s].to_s);
      EXPECT_EQ(first[i].spans[s].part_point_m, second[i].spans[s].part_point_m);
    }
  }
}

}  // namespace
}  // namespace tutti::stage
