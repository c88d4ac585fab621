// SPDX-License-Identifier: MIT
// The acoustics behind the charts: the harmonic series' tuning, how valve combinations add tube
// (and come out sharp), a double horn's side switch, and where a slide must be.
#include <tutti/brass_model/brass_physics.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tutti::brass_model {
namespace {

const std::vector<ValveSpec> kThreeValves = {{"1", 2.0}, {"2", 1.0}, {"3", 3.0}};

std::uint8_t mask_of(std::initializer_list<int> valves) {
  std::uint8_t mask = 0;
  for (int v : valves) mask = static_cast<std::uint8_t>(mask | (1u << (v - 1)));
  return mask;
}

TEST(BrassPhysics, HarmonicSeriesTuningAgainstEqualTemperament) {
  // Textbook deviations of the natural harmonics from equal temperament, in cents.
  EXPECT_NEAR(partial_cents(2), 0.0, 1e-9);
  EXPECT_NEAR(partial_cents(3), 2.0, 0.1);
  EXPECT_NEAR(partial_cents(5), -13.7, 0.1);
  EXPECT_NEAR(partial_cents(7), -31.2, 0.1);
  EXPECT_NEAR(partial_cents(9), 3.9, 0.1);
  EXPECT_NEAR(partial_cents(11), -48.7, 0.1);
  EXPECT_EQ(partial_nominal_semitones(4), 24);
  EXPECT_EQ(partial_nominal_semitones(5), 28);  // a major third above the 4th
  EXPECT_EQ(partial_nominal_semitones(7), 34);  // named as the minor seventh, 31 cents flat
  EXPECT_EQ(partial_nominal_semitones(16), 48);
}

TEST(BrassPhysics, ValveCombinationsLowerZeroToSixSemitonesAndComeOutSharp) {
  // The order: 0, 2, 1, 1+2, 2+3, 1+3, 1+2+3 lower by 0..6 semitones.
  const std::vector<std::vector<int>> order = {{}, {2}, {1}, {1, 2}, {2, 3}, {1, 3}, {1, 2, 3}};
  double previous = -1.0;
  for (std::size_t s = 0; s < order.size(); ++s) {
    std::uint8_t mask = 0;
    for (int v : order[s]) mask = static_cast<std::uint8_t>(mask | (1u << (v - 1)));
    EXPECT_EQ(combination_nominal_semitones(kThreeValves, mask), int(s));
    const double lowering = combination_lowering_semitones(kThreeValves, mask);
    EXPECT_GT(lowering, previous);
    previous = lowering;
    // Tube lengths add: never flat, and single valves exact.
    EXPECT_LE(lowering, double(s) + 1e-9);
    if (order[s].size() <= 1) {
      EXPECT_NEAR(lowering, double(s), 1e-9);
    }
  }
  // How sharp, in cents, from the lengths (L·(2^(2/12)-1) + L·(2^(3/12)-1) added to L, ...).
  auto sharp = [](std::initializer_list<int> v) {
    return 100.0 * (combination_nominal_semitones(kThreeValves, mask_of(v)) -
                    combination_lowering_semitones(kThreeValves, mask_of(v)));
  };
  EXPECT_NEAR(sharp({1, 2}), 10.7, 0.5);
  EXPECT_NEAR(sharp({2, 3}), 15.4, 0.5);
  EXPECT_NEAR(sharp({1, 3}), 30.2, 0.5);
  EXPECT_NEAR(sharp({1, 2, 3}), 53.2, 0.5);
  EXPECT_NEAR(sharp({3}), 0.0, 1e-9);  // why 3 alone is the in-tune alternate to 1-2
}

TEST(BrassPhysics, ThumbValveSwitchesSideWithItsOwnLoops) {
  std::vector<ValveSpec> horn = kThreeValves;
  horn.push_back({"T", -5.0, true});
  const auto thumb = mask_of({4});
  EXPECT_NEAR(combination_lowering_semitones(horn, thumb), -5.0, 1e-9);
  // Each side's loops are tuned for that side: T-1-3 is as sharp as 1-3.
  EXPECT_NEAR(combination_lowering_semitones(horn, mask_of({1, 3, 4})),
              combination_lowering_semitones(horn, mask_of({1, 3})) - 5.0, 1e-9);
  EXPECT_EQ(combination_nominal_semitones(horn, mask_of({1, 2, 4})), -2);
  // A trigger is a plain loop: on a trombone's F attachment the trigger lowers by 5 exactly.
  const std::vector<ValveSpec> trigger = {{"T", 5.0}};
  EXPECT_NEAR(combination_lowering_semitones(trigger, 1), 5.0, 1e-9);
}

TEST(BrassPhysics, SlideExtensionFromTubeLength) {
  // B♭ tenor trombone: pedal B♭1 = 58.27 Hz, half a wavelength at 343 m/s.
  const double tube = acoustic_length_mm(34);
  EXPECT_NEAR(tube, 343000.0 / (2.0 * 58.2705), 1.0);
  // A U-slide adds twice its extension: 2nd position lowers by one semitone.
  const double second = slide_extension_mm(tube, 1.0);
  EXPECT_NEAR(2.0 * second / tube, std::exp2(1.0 / 12.0) - 1.0, 1e-12);
  EXPECT_NEAR(second, 87.5, 1.0);                          // ~8.5-9 cm on real slides
  EXPECT_NEAR(slide_extension_mm(tube, 6.0), 609.5, 1.0);  // 7th position
  // Positions get further apart down the slide, and the inverse holds.
  double last_gap = 0.0;
  for (int p = 1; p < 7; ++p) {
    const double gap = slide_extension_mm(tube, p) - slide_extension_mm(tube, p - 1);
    EXPECT_GT(gap, last_gap);
    last_gap = gap;
    EXPECT_NEAR(slide_semitones(tube, slide_extension_mm(tube, p)), double(p), 1e-9);
  }
  EXPECT_LT(slide_extension_mm(tube, -0.3), 0.0);
}

}  // namespace
}  // namespace tutti::brass_model
