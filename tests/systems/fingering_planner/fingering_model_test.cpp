// SPDX-License-Identifier: MIT
#include <tutti/fingering_planner/fingering_model.hpp>

#include <gtest/gtest.h>

#include <tutti/piano_model/keyboard_instruments.hpp>

namespace tutti::fingering_planner {
namespace {

// Each keyboard's own key sizes, one hand: on the harpsichord's narrower keys (a 152.4 mm
// octave) the hand is as wide in millimetres as on the piano, so it spans more keys.
TEST(FingeringModel, EachInstrumentsKeysTheSameHand) {
  auto instruments = piano_model::KeyboardInstruments::load(
      piano_model::keyboard_instruments_path(default_content_dir()));
  ASSERT_TRUE(instruments) << instruments.error().message;
  auto piano = load_fingering_model("default", "", default_content_dir(), instruments->find("piano"));
  auto harpsichord =
      load_fingering_model("default", "", default_content_dir(), instruments->find("harpsichord"));
  ASSERT_TRUE(piano) << piano.error().message;
  ASSERT_TRUE(harpsichord) << harpsichord.error().message;
  EXPECT_NEAR(piano->keyboard.x_mm(72) - piano->keyboard.x_mm(60), 164.5, 1e-9);
  EXPECT_NEAR(harpsichord->keyboard.x_mm(72) - harpsichord->keyboard.x_mm(60), 152.4, 1e-9);
  // A black key keeps its place in the octave, scaled: C# at 20.5625 of 164.5 mm.
  EXPECT_NEAR(harpsichord->keyboard.x_mm(61) - harpsichord->keyboard.x_mm(60),
              (20.5625 - 11.75) * 152.4 / 164.5, 1e-9);
  EXPECT_DOUBLE_EQ(harpsichord->hand.reach_mm(), piano->hand.reach_mm());
  EXPECT_GT(harpsichord->hand.reach_mm() / harpsichord->keyboard.white_key_width_mm(),
            piano->hand.reach_mm() / piano->keyboard.white_key_width_mm());
}

}  // namespace
}  // namespace tutti::fingering_planner
