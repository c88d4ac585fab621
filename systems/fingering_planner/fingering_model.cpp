// SPDX-License-Identifier: MIT
#include <tutti/fingering_planner/fingering_model.hpp>

#include <utility>

namespace tutti::fingering_planner {

// The piano model's names this planner uses (systems/piano_model).
using piano_model::HandModel;
using piano_model::Keyboard;
using piano_model::KeyboardInstrument;

Result<FingeringModel> load_fingering_model(std::string_view weights, std::string_view hand_preset,
                                            const std::filesystem::path& content_dir,
                                            const KeyboardInstrument* instrument) {
  const std::filesystem::path piano = content_dir / "piano";
  auto piano_keys = Keyboard::load(piano / "keyboard.json");
  if (!piano_keys) return piano_keys.error();
  // The hand's reach is in the piano's white keys (hands.json): the same hand in millimetres on
  // every instrument, so it spans more of a narrower keyboard's keys.
  const double hand_unit_mm = piano_keys->white_key_width_mm();
  auto keyboard = instrument == nullptr
                      ? std::move(piano_keys)
                      : Keyboard::load(piano / "keyboard.json", instrument->lowest_key,
                                       instrument->highest_key, instrument->octave_span_mm);
  if (!keyboard) return keyboard.error();
  auto hand = HandModel::load(piano / "hands.json", hand_preset, hand_unit_mm);
  if (!hand) return hand.error();
  auto cost = load_cost_weights(piano / "fingering" / (std::string(weights) + ".json"));
  if (!cost) return cost.error();
  return FingeringModel{std::move(*keyboard), std::move(*hand), std::move(*cost)};
}

}  // namespace tutti::fingering_planner
