#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "fingering_planner/cost_weights.hpp"
#include "fingering_planner/fingering_model.hpp"

namespace tutti::piano {
namespace {

TEST(CostWeights, BothPresetsLoad) {
  auto paper = load_fingering_model("paper");
  ASSERT_TRUE(paper.ok()) << paper.error().message;
  EXPECT_TRUE(std::isinf(paper->weights.same_finger_other_key));
  EXPECT_DOUBLE_EQ(paper->weights.finger_use[0], 0.1);
  EXPECT_DOUBLE_EQ(paper->weights.black_key[0], 1.5);
  auto defaults = load_fingering_model("default");
  ASSERT_TRUE(defaults.ok()) << defaults.error().message;
  EXPECT_GT(defaults->weights.spacing_stretch, 0.0);
}

TEST(CostWeights, UnknownKeyIsAnErrorWithItsJsonPath) {
  const nlohmann::json doc = {{"crossing", {{"thumb", 1.0}, {"thumb_bogus", 2.0}}}};
  auto weights = cost_weights_from_json(doc, "default.json");
  ASSERT_FALSE(weights.ok());
  EXPECT_EQ(weights.error().message, "default.json: /crossing/thumb_bogus: unknown key");
  const nlohmann::json wrong = {{"fingers", {{"use", {1, 2, 3}}}}};
  auto bad = cost_weights_from_json(wrong, "x.json");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("x.json: /fingers/use: expected 5 numbers"),
            std::string::npos);
  auto missing = load_fingering_model("no_such_preset");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().message.find("no_such_preset.json"), std::string::npos);
}

}  // namespace
}  // namespace tutti::piano
