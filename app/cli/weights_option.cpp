// SPDX-License-Identifier: MIT
#include <tutti/cli/weights_option.hpp>

#include <tutti/fingering_planner/cost_weights.hpp>
#include <tutti/piano_model/content_dir.hpp>

namespace tutti::cli {

namespace fs = std::filesystem;

Result<fingering_planner::FingeringModel> load_model_with_weights(const std::string& weights,
                                                                  const std::string& hand_size,
                                                                  const fs::path& content_dir) {
  const fs::path content = content_dir.empty() ? piano_model::default_content_dir() : content_dir;
  const bool is_file =
      weights.find('/') != std::string::npos || fs::path(weights).extension() == ".json";
  auto model =
      fingering_planner::load_fingering_model(is_file ? "default" : weights, hand_size, content);
  if (!model) return model.error();
  if (is_file) {
    auto loaded = fingering_planner::load_cost_weights(weights);
    if (!loaded) return loaded.error();
    model->weights = std::move(*loaded);
  }
  return model;
}

}  // namespace tutti::cli
