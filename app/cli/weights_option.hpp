// SPDX-License-Identifier: MIT
#pragma once
// The `--weights` option shared by `tutti fingering` and `tutti fit-fingering`: a preset name
// from content/piano/fingering/ ("default", "paper") or a path to a weights .json file (it
// contains a '/' or ends in .json).

#include <filesystem>
#include <string>

#include <tutti/core/result.hpp>
#include <tutti/fingering_planner/fingering_model.hpp>

namespace tutti::cli {

// content_dir empty = piano_model::default_content_dir(); hand_size empty = hands.json's default.
Result<fingering_planner::FingeringModel> load_model_with_weights(
    const std::string& weights, const std::string& hand_size,
    const std::filesystem::path& content_dir);

}  // namespace tutti::cli
