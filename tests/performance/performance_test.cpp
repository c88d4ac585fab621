// SPDX-License-Identifier: MIT
// tutti::performance: a host opens a scene and samples any time t — every model's node transforms
// under its own node names, morph weights, and each performer's events around t — the same at
// the same t whatever came before, and agreeing with what the stage shows.
#include <tutti/performance/performance.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <string_view>

#include <tutti/components/note.hpp>
#include <tutti/performance/families.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::performance {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "scenes";

std::unique_ptr<Performance> open_scene(const char* name, const Options& options = {}) {
  auto opened = Performance::open(kScenes / name, options);
  EXPECT_TRUE(opened) << opened.error().message;
  return opened ? std::move(*opened) : nullptr;
}

// Kinds are looked up by name: their numbers depend on the families in the list.
bool is(const Event& e, std::string_view kind) { return event_kind_name(e.kind) == kind; }

std::size_t model_named(const Performance& p, const std::string& name) {
  for (std::size_t m = 0; m < p.models().size(); ++m) {
    if (p.models()[m].name == name) return m;
  }
  ADD_FAILURE() << "no model " << name;
  return 0;
}

std::size_t node_named(const ModelInfo& model, const std::string& name) {
  const auto it = std::find(model.nodes.begin(), model.nodes.end(), name);
  EXPECT_NE(it, model.nodes.end()) << model.name << " has no node " << name;
  return static_cast<std::size_t>(it - model.nodes.begin());
}

bool same_pose(const Sample& a, const Sample& b) {
  if (a.models.size() != b.models.size()) return false;
  for (std::size_t m = 0; m < a.models.size(); ++m) {
    const ModelPose& x = a.models[m];
    const ModelPose& y = b.models[m];
    if (x.local.size() != y.local.size() || x.morph_weights != y.morph_weights) return false;
    for (std::size_t n = 0; n < x.local.size(); ++n) {
      if (x.local[n].translation != y.local[n].translation ||
          x.local[n].rotation != y.local[n].rotation || x.local[n].scale != y.local[n].scale) {
        return false;
      }
    }
    if (x.root.translation != y.root.translation || x.root.rotation != y.root.rotation) return false;
  }
  return true;
}

// Each instrument on its own model, named "<performer> <model>" like the others.
TEST(Performance, TheQuintetsInstrumentsAreTheirOwnModels) {
  auto p = open_scene("quintet.json");
  ASSERT_TRUE(p);
  for (const char* name : {"Trumpet 1 trumpet", "Trumpet 2 trumpet", "Horn horn",
                           "Trombone trombone", "Tuba tuba"}) {
    const ModelInfo& model = p->models()[model_named(*p, name)];
    EXPECT_EQ(model.name, name);
  }
  const ModelInfo& tuba = p->models()[model_named(*p, "Tuba tuba")];
  node_named(tuba, "valve_4");
  const ModelInfo& horn = p->models()[model_named(*p, "Horn horn")];
  node_named(horn, "rotor_1");
}

// Each performer's instrument by its id, whatever the family: a keyboard player's is their own
// keyboard's (it was "piano" for every keyboard player).
TEST(Performance, EachPerformerSaysWhichInstrumentTheyPlay) {
  auto opened = Performance::open(std::filesystem::path(TUTTI_SOURCE_DIR) / "tests" / "data" /
                                  "keyboards" / "piano_and_organ.json");
  ASSERT_TRUE(opened) << opened.error().message;
  const Performance& p = **opened;
  ASSERT_EQ(p.performers().size(), 2u);
  EXPECT_EQ(p.performers()[0].family, "piano");
  EXPECT_EQ(p.performers()[0].instrument, "piano");
  EXPECT_EQ(p.performers()[1].family, "piano");
  EXPECT_EQ(p.performers()[1].instrument, "organ");
  auto quintet = open_scene("quintet.json");
  ASSERT_TRUE(quintet);
  for (const PerformerInfo& performer : quintet->performers()) {
    EXPECT_FALSE(performer.instrument.empty()) << performer.name;
  }
}

TEST(Performance, TheQuartetsPerformersAndTheirModels) {
  auto p = open_scene("quartet.json");
  ASSERT_TRUE(p);
  ASSERT_EQ(p->performers().size(), 4u);
  EXPECT_EQ(p->performers()[0].name, "Trumpet 1");
  EXPECT_EQ(p->performers()[0].family, "brass");
  EXPECT_EQ(p->performers()[0].instrument, "trumpet_bb");
  EXPECT_EQ(p->performers()[2].instrument, "trombone_tenor");
  for (std::size_t i = 0; i < p->performers().size(); ++i) {
    const PerformerInfo& performer = p->performers()[i];
    ASSERT_EQ(performer.models.size(), 2u) << performer.name;  // body and instrument
    for (std::size_t m : performer.models) {
      EXPECT_EQ(p->models()[m].performer, static_cast<std::int32_t>(i));
    }
  }
  const ModelInfo& trumpet = p->models()[model_named(*p, "Trumpet 1 trumpet")];
  node_named(trumpet, "valve_1");
  const ModelInfo& body = p->models()[model_named(*p, "Trumpet 1")];
  node_named(body, "hips");
  EXPECT_NE(std::find(body.morphs.begin(), body.morphs.end(), "tension"), body.morphs.end());
  ASSERT_EQ(body.parents.size(), body.nodes.size());
  EXPECT_EQ(body.parents[node_named(body, "spine")], static_cast<std::int32_t>(node_named(body, "hips")));
  std::set<std::string> names;
  for (const ModelInfo& m : p->models()) names.insert(m.name);
  EXPECT_EQ(names.size(), p->models().size()) << "model names are unique";
}

TEST(Performance, SampleAtTIsAPureFunctionOfT) {
  auto p = open_scene("quartet.json");
  ASSERT_TRUE(p);
  Sample first, other, again;
  p->sample(12.5, first);
  p->sample(3.0, other);
  EXPECT_FALSE(same_pose(first, other));
  p->sample(12.5, again);
  EXPECT_TRUE(same_pose(first, again));
  auto fresh = open_scene("quartet.json");
  ASSERT_TRUE(fresh);
  Sample from_fresh;
  fresh->sample(12.5, from_fresh);
  EXPECT_TRUE(same_pose(first, from_fresh));
  for (const ModelPose& model : first.models) {
    for (const Trs& local : model.local) {
      const float norm = std::sqrt(local.rotation[0] * local.rotation[0] +
                                   local.rotation[1] * local.rotation[1] +
                                   local.rotation[2] * local.rotation[2] +
                                   local.rotation[3] * local.rotation[3]);
      ASSERT_NEAR(norm, 1.0f, 1e-5f);
    }
  }
}

// A valve's node goes down while the valve is down, and the events say when that happens.
TEST(Performance, ValveEventsMatchTheValveNode) {
  auto p = open_scene("quartet.json");
  ASSERT_TRUE(p);
  const std::size_t horn = model_named(*p, "Trumpet 1 trumpet");
  const std::size_t valve = node_named(p->models()[horn], "valve_1");
  Sample rest;
  p->sample(p->start_s(), rest);
  const float up_y = rest.models[horn].local[valve].translation[1];
  std::size_t checked = 0;
  Sample sample;
  for (const Event& e : p->events()) {
    if (e.performer != 0 || !is(e, "valve_down") || e.value != 1) continue;
    p->sample(e.t_s + 0.002, sample);
    EXPECT_LT(sample.models[horn].local[valve].translation[1], up_y - 0.015f) << e.t_s;
    ++checked;
  }
  EXPECT_GT(checked, 3u);
}

TEST(Performance, EventsCoverNotesBreathsCuesAndContacts) {
  auto p = open_scene("quartet.json");
  ASSERT_TRUE(p);
  std::map<std::string_view, std::size_t> count;
  for (const Event& e : p->events()) ++count[event_kind_name(e.kind)];
  auto& world = p->stage().world();
  std::size_t heard = 0;
  world.view<const components::Note>().each([&](const components::Note& n) {
    heard += !n.performer.is_null() && !n.silent ? 1 : 0;
  });
  EXPECT_EQ(count["note_on"], heard);
  EXPECT_EQ(count["note_off"], heard);
  EXPECT_GT(count["valve_down"], 10u);
  EXPECT_GT(count["valve_up"], 10u);
  EXPECT_GT(count["slide_arrives"], 10u);
  EXPECT_GT(count["breath_start"], 4u);
  EXPECT_EQ(count["breath_start"], count["breath_end"]);
  EXPECT_GE(count["cue"], 1u);
  EXPECT_TRUE(std::is_sorted(p->events().begin(), p->events().end(),
                             [](const Event& a, const Event& b) { return a.t_s < b.t_s; }));
  // sample(t) hands each performer its own events around t.
  Sample sample;
  p->sample(12.0, sample, 1.0);
  ASSERT_EQ(sample.events.size(), 4u);
  std::size_t around = 0;
  for (std::size_t i = 0; i < sample.events.size(); ++i) {
    for (const Event& e : sample.events[i]) {
      EXPECT_EQ(e.performer, static_cast<std::int32_t>(i));
      EXPECT_LE(std::abs(e.t_s - 12.0), 1.0);
      ++around;
    }
  }
  EXPECT_EQ(around, p->events_between(11.0, std::nextafter(13.0, 14.0)).size());
}

// The pianist's keys: every key that reaches its bed is the key of a note starting then, and the
// keys of (nearly) every note go down (a finger holding two keys of a big chord presses them as
// one contact).
TEST(Performance, ThePianistsKeysGoDownForTheirNotes) {
  auto p = open_scene("piano.json");
  ASSERT_TRUE(p);
  ASSERT_EQ(p->performers().size(), 1u);
  EXPECT_EQ(p->performers()[0].family, "piano");
  EXPECT_EQ(p->performers()[0].models.size(), 4u);  // piano, two hands, the body
  std::vector<Event> notes, keys;
  for (const Event& e : p->events()) {
    if (is(e, "note_on")) notes.push_back(e);
    if (is(e, "key_down")) keys.push_back(e);
  }
  ASSERT_FALSE(notes.empty());
  const auto near = [](const std::vector<Event>& list, const Event& e) {
    return std::any_of(list.begin(), list.end(), [&](const Event& other) {
      return other.value == e.value && std::abs(other.t_s - e.t_s) < 0.05;
    });
  };
  for (const Event& key : keys) EXPECT_TRUE(near(notes, key)) << "key " << key.value << " at " << key.t_s;
  std::size_t pressed = 0;
  for (const Event& note : notes) pressed += near(keys, note) ? 1 : 0;
  EXPECT_GE(pressed * 100, notes.size() * 95) << pressed << " of " << notes.size();
  std::printf("piano: %zu notes, %zu key_down events, %zu notes with their key down\n",
              notes.size(), keys.size(), pressed);
}

// Contacts as data: each key the pianist presses to its bed is inside a span of a fingertip on
// that key's node, stopping that pitch; none are recorded at contact_fps 0.
TEST(Performance, EveryKeyDownIsInsideAFingertipsContactWithThatKey) {
  auto p = open_scene("piano.json");
  ASSERT_TRUE(p);
  const std::vector<Contact>& contacts = p->contacts();
  ASSERT_FALSE(contacts.empty());
  EXPECT_TRUE(std::is_sorted(contacts.begin(), contacts.end(),
                             [](const Contact& a, const Contact& b) { return a.from_s < b.from_s; }));
  constexpr double kFrame = 1.0 / 30.0;  // Options::contact_fps
  std::size_t keys = 0;
  for (const Event& e : p->events()) {
    if (!is(e, "key_down")) continue;
    ++keys;
    const bool covered = std::any_of(contacts.begin(), contacts.end(), [&](const Contact& c) {
      const ModelInfo& part = p->models()[static_cast<std::size_t>(c.part_model)];
      const ModelInfo& body = p->models()[static_cast<std::size_t>(c.body_model)];
      return c.performer == e.performer && c.midi == e.value &&
             part.nodes[static_cast<std::size_t>(c.part_node)] == "key_" + std::to_string(e.value) &&
             body.nodes[static_cast<std::size_t>(c.body_node)].find("_tip_") != std::string::npos &&
             c.from_s - kFrame <= e.t_s && e.t_s <= c.to_s + kFrame;
    });
    EXPECT_TRUE(covered) << "key " << e.value << " down at " << e.t_s << " s";
  }
  EXPECT_GT(keys, 20u);
  Options none;
  none.contact_fps = 0.0;
  auto q = open_scene("piano.json", none);
  ASSERT_TRUE(q);
  EXPECT_TRUE(q->contacts().empty());
}

// The event kinds are the performance's own, then each default family's stops, by name: every
// name once, each found by its name, and a name nobody registers found nowhere.
TEST(Performance, EventKindsAreTheFamiliesStopsByName) {
  const auto kinds = event_kinds();
  ASSERT_GE(kinds.size(), 5u);
  EXPECT_EQ(kinds[0], "note_on");
  std::set<std::string_view> names(kinds.begin(), kinds.end());
  EXPECT_EQ(names.size(), kinds.size()) << "a name twice";
  for (std::size_t k = 0; k < kinds.size(); ++k) {
    EXPECT_EQ(find_event_kind(kinds[k]), static_cast<std::int32_t>(k)) << kinds[k];
    EXPECT_EQ(event_kind_name(static_cast<std::uint16_t>(k)), kinds[k]);
  }
  for (const stage::FamilyPlugin* family : default_families()) {
    for (const stage::StopKind* kind : family->stop_kinds()) {
      EXPECT_EQ(find_event_kind(kind->name) >= 0, kind->host_event) << kind->name;
    }
  }
  for (const char* name : {"key_down", "valve_down", "slide_arrives", "pedal_up"}) {
    EXPECT_GE(find_event_kind(name), 0) << name;
  }
  EXPECT_EQ(find_event_kind("tongue"), -1) << "the note_on says it";
  EXPECT_EQ(find_event_kind("bow_change"), -1);
  EXPECT_EQ(event_kind_name(static_cast<std::uint16_t>(kinds.size())), "");
}

TEST(Performance, NoContactEventsWhenAskedForNone) {
  Options options;
  options.contact_step_s = 0.0;
  auto p = open_scene("quartet.json", options);
  ASSERT_TRUE(p);
  for (const Event& e : p->events()) {
    EXPECT_TRUE(is(e, "note_on") || is(e, "note_off") ||
                is(e, "breath_start") || is(e, "breath_end") ||
                is(e, "cue"))
        << event_kind_name(e.kind);
  }
}

TEST(Performance, BadInputIsOneLineNamingTheFile) {
  auto missing = Performance::open(kScenes / "no_such_scene.json");
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().code, ErrorCode::bad_input);
  EXPECT_NE(missing.error().message.find("no_such_scene.json"), std::string::npos);
  EXPECT_EQ(missing.error().message.find('\n'), std::string::npos);
  Options options;
  options.asset_dir = "/no/such/assets";
  auto no_assets = Performance::open(kScenes / "piano.json", options);
  ASSERT_FALSE(no_assets);
  EXPECT_NE(no_assets.error().message.find("piano.json: "), std::string::npos)
      << no_assets.error().message;
  EXPECT_NE(no_assets.error().message.find("/no/such/assets"), std::string::npos)
      << no_assets.error().message;
}

}  // namespace
}  // namespace tutti::performance
