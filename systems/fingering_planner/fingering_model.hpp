// SPDX-License-Identifier: MIT
#pragma once
// Everything the planners need, loaded once: keyboard geometry, hand reach, cost weights.
// Files: <content>/piano/keyboard.json, <content>/piano/hands.json,
//        <content>/piano/fingering/<weights>.json (weights = "default" or "paper").

#include <filesystem>
#include <string_view>

#include <tutti/core/result.hpp>
#include <tutti/fingering_planner/cost_weights.hpp>
#include <tutti/piano_model/content_dir.hpp>
#include <tutti/piano_model/hand_model.hpp>
#include <tutti/piano_model/keyboard.hpp>
#include <tutti/piano_model/keyboard_instruments.hpp>

namespace tutti::fingering_planner {

// The piano model's names this planner uses (systems/piano_model).
using piano_model::default_content_dir;
using piano_model::HandModel;
using piano_model::Keyboard;
using piano_model::KeyboardInstrument;

struct FingeringModel {
  Keyboard keyboard;
  HandModel hand;
  CostWeights weights;
};

// `hand_preset` empty = hands.json's default_preset; `instrument` null = keyboard.json's compass
// (the piano's), else that instrument's. Errors are the loaders' (file + JSON path).
Result<FingeringModel> load_fingering_model(
    std::string_view weights = "default", std::string_view hand_preset = "",
    const std::filesystem::path& content_dir = default_content_dir(),
    const KeyboardInstrument* instrument = nullptr);

}  // namespace tutti::fingering_planner
