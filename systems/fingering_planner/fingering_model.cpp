// SPDX-License-Identifier: MIT
#include <tutti/fingering_planner/fingering_model.hpp>

namespace tutti::piano {

Result<FingeringModel> load_fingering_model(std::string_view weights, std::string_view hand_preset,
                                            const std::filesystem::path& content_dir,
                                            const KeyboardInstrument* instrument) {
  const std::filesystem::path piano = content_dir / "piano";
  auto keyboard = instrument == nullptr
                      ? Keyboard::load(piano / "keyboard.json")
                      : Keyboard::load(piano / "keyboard.json", instrument->lowest_key,
                                       instrument->highest_key);
  if (!keyboard) return keyboard.error();
  auto hand = HandModel::load(piano / "hands.json", hand_preset, keyboard->white_key_width_mm());
  if (!hand) return hand.error();
  auto cost = load_cost_weights(piano / "fingering" / (std::string(weights) + ".json"));
  if (!cost) return cost.error();
  return FingeringModel{std::move(*keyboard), std::move(*hand), std::move(*cost)};
}

}  // namespace tutti::piano
