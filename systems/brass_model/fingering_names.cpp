// SPDX-License-Identifier: MIT
#include <tutti/brass_model/fingering_names.hpp>

#include <cctype>

namespace tutti::brass_model {
namespace {

bool valve_is_down(std::uint8_t mask, std::size_t valve) { return (mask & (1u << valve)) != 0; }

std::string joined(std::span<const ValveSpec> valves, std::uint8_t mask) {
  std::string name;
  for (const bool side_first : {true, false}) {
    for (std::size_t i = 0; i < valves.size(); ++i) {
      if (!valve_is_down(mask, i) || valves[i].switches_side != side_first) continue;
      name += (name.empty() ? "" : "-") + valves[i].name;
    }
  }
  return name;
}

}  // namespace

std::string combination_name(std::span<const ValveSpec> valves, std::uint8_t mask) {
  std::string name = joined(valves, mask);
  return name.empty() ? "open" : name;
}

std::optional<std::uint8_t> parse_combination(std::span<const ValveSpec> valves,
                                              std::string_view text) {
  if (text.empty() || text == "open") return std::uint8_t{0};
  std::uint8_t mask = 0;
  while (true) {
    const std::size_t dash = text.find('-');
    const std::string_view token = text.substr(0, dash);
    bool found = false;
    for (std::size_t i = 0; i < valves.size() && !found; ++i) {
      if (valves[i].name != token) continue;
      if (valve_is_down(mask, i)) return std::nullopt;  // "1-1"
      mask = static_cast<std::uint8_t>(mask | (1u << i));
      found = true;
    }
    if (!found) return std::nullopt;
    if (dash == std::string_view::npos) return mask;
    text.remove_prefix(dash + 1);
  }
}

std::string slide_fingering_name(std::span<const ValveSpec> triggers, std::uint8_t mask,
                                 int position) {
  return joined(triggers, mask) + std::to_string(position);
}

std::optional<SlideFingering> parse_slide_fingering(std::span<const ValveSpec> triggers,
                                                    std::string_view text) {
  std::size_t digits = text.size();
  while (digits > 0 && std::isdigit(static_cast<unsigned char>(text[digits - 1])) != 0) --digits;
  if (digits == text.size() || text.size() - digits > 2) return std::nullopt;
  SlideFingering f;
  f.position = std::stoi(std::string(text.substr(digits)));
  const std::string_view prefix = text.substr(0, digits);
  if (prefix == "open") return std::nullopt;
  auto mask = parse_combination(triggers, prefix);
  if (!mask) return std::nullopt;
  f.valves = *mask;
  return f;
}

}  // namespace tutti::brass_model
