// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "breath_fixture.hpp"
#include <tutti/content/json_reader.hpp>
#include "testdata.hpp"

namespace tutti::brass_motion {
namespace {

nlohmann::json content_json() {
  auto document = content::read_json_file(test::content_dir() / "brass" / "breath.json");
  EXPECT_TRUE(document.ok());
  return document.ok() ? *document : nlohmann::json::object();
}

TEST(BreathParams, ContentFileLoadsWithTheDocumentedValues) {
  auto p = load_breath_params(test::content_dir() / "brass" / "breath.json");
  ASSERT_TRUE(p.ok()) << p.error().message;
  const BreathParams expected = test::fixed_params();
  EXPECT_EQ(p->inhale_min_s, expected.inhale_min_s);
  EXPECT_EQ(p->inhale_max_s, expected.inhale_max_s);
  EXPECT_EQ(p->refill_per_s, expected.refill_per_s);
  EXPECT_EQ(p->prepare_s, expected.prepare_s);
  EXPECT_EQ(p->resting_air, expected.resting_air);
  EXPECT_EQ(p->capacity_s, expected.capacity_s);
  EXPECT_EQ(p->mf_velocity, expected.mf_velocity);
  EXPECT_EQ(p->drain_soft, expected.drain_soft);
  EXPECT_EQ(p->drain_loud, expected.drain_loud);
  EXPECT_EQ(p->drain_low, expected.drain_low);
  EXPECT_EQ(p->drain_high, expected.drain_high);
  EXPECT_EQ(p->strain_from_air, expected.strain_from_air);
  EXPECT_EQ(p->catch_reserve_air, expected.catch_reserve_air);
  EXPECT_EQ(p->catch_inhale_s, expected.catch_inhale_s);
  EXPECT_EQ(p->catch_min_s, expected.catch_min_s);
  EXPECT_EQ(p->catch_max_cut, expected.catch_max_cut);
  EXPECT_EQ(p->catch_below_air, expected.catch_below_air);
  EXPECT_EQ(p->catch_strong_beat_bonus, expected.catch_strong_beat_bonus);
  // The default location is the same file.
  EXPECT_EQ(breath_params_path().filename(), "breath.json");
  EXPECT_TRUE(load_breath_params().ok());
}

TEST(BreathParams, UnknownKeyIsNamed) {
  nlohmann::json doc = content_json();
  doc["capacity"] = 8;
  auto p = breath_params_from_json(doc, "breath.json");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().message,
            "breath.json: /capacity: unknown key (did you mean \"capacity_s\"?)");
}

TEST(BreathParams, BadValuesAreNamed) {
  nlohmann::json doc = content_json();
  doc["capacity_s"] = -1;
  auto p = breath_params_from_json(doc, "b.json");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().message, "b.json: /capacity_s: must be in [0.5, 120]");

  doc = content_json();
  doc["refill_per_s"] = "fast";
  p = breath_params_from_json(doc, "b.json");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().message, "b.json: /refill_per_s: expected a number");

  doc = content_json();
  doc.erase("prepare_s");
  p = breath_params_from_json(doc, "b.json");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().message, "b.json: /prepare_s: missing");

  doc = content_json();
  doc["inhale_min_s"] = 2.0;
  p = breath_params_from_json(doc, "b.json");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().message, "b.json: /inhale_min_s: above inhale_max_s");

  doc = content_json();
  doc["catch_min_s"] = 0.5;
  p = breath_params_from_json(doc, "b.json");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().message, "b.json: /catch_min_s: above catch_inhale_s");

  doc = content_json();
  doc["description"] = 3;
  p = breath_params_from_json(doc, "b.json");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().message, "b.json: /description: expected a string");

  p = breath_params_from_json(nlohmann::json::array(), "b.json");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().message, "b.json: /: expected an object");
}

TEST(BreathParams, FileErrorsAreOneLineNamingTheFile) {
  auto missing = load_breath_params("/nonexistent/breath.json");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().message.find("/nonexistent/breath.json"), std::string::npos);
  EXPECT_EQ(missing.error().message.find('\n'), std::string::npos);

  const auto path = tutti::test::unique_temp_path("breath.json");
  {
    std::ofstream out(path);
    out << "{\"inhale_min_s\": 0.15,\n \"inhale_max_s\": oops}\n";
  }
  auto broken = load_breath_params(path);
  ASSERT_FALSE(broken.ok());
  EXPECT_EQ(broken.error().message, path.string() + ": not valid JSON");

  nlohmann::json doc = content_json();
  doc["drain_high"] = 0;
  {
    std::ofstream out(path);
    out << doc.dump(2);
  }
  auto bad = load_breath_params(path);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().message, path.string() + ": /drain_high: must be in [0.01, 20]");
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace tutti::brass_motion
