// SPDX-License-Identifier: MIT
#include <tutti/brass_motion/breath_params.hpp>

#include <nlohmann/json.hpp>

#include <tutti/content/content_dir.hpp>
#include <tutti/content/json_reader.hpp>

namespace tutti::brass_motion {
std::filesystem::path breath_params_path() {
  return content::default_content_dir() / "brass" / "breath.json";
}

Result<BreathParams> load_breath_params() { return load_breath_params(breath_params_path()); }

Result<BreathParams> load_breath_params(const std::filesystem::path& file) {
  auto document = content::read_json_file(file);
  if (!document) return document.error();
  return breath_params_from_json(*document, file.string());
}

Result<BreathParams> breath_params_from_json(const nlohmann::json& document,
                                             const std::string& file_name) {
  const content::JsonReader reader(file_name);
  BreathParams p;
  const content::NumberField fields[] = {
      {"inhale_min_s", &p.inhale_min_s, 0.01, 5.0},
      {"inhale_max_s", &p.inhale_max_s, 0.05, 10.0},
      {"refill_per_s", &p.refill_per_s, 0.05, 20.0},
      {"prepare_s", &p.prepare_s, 0.0, 10.0},
      {"resting_air", &p.resting_air, 0.0, 1.0},
      {"capacity_s", &p.capacity_s, 0.5, 120.0},
      {"mf_velocity", &p.mf_velocity, 2.0, 126.0},
      {"drain_soft", &p.drain_soft, 0.01, 1.0},
      {"drain_loud", &p.drain_loud, 1.0, 20.0},
      {"drain_low", &p.drain_low, 0.01, 20.0},
      {"drain_high", &p.drain_high, 0.01, 20.0},
      {"strain_from_air", &p.strain_from_air, 0.01, 1.0},
      {"catch_reserve_air", &p.catch_reserve_air, 0.0, 0.9},
      {"catch_inhale_s", &p.catch_inhale_s, 0.01, 5.0},
      {"catch_min_s", &p.catch_min_s, 0.01, 5.0},
      {"catch_max_cut", &p.catch_max_cut, 0.0, 0.9},
      {"catch_below_air", &p.catch_below_air, 0.0, 1.0},
      {"catch_strong_beat_bonus", &p.catch_strong_beat_bonus, 0.0, 10.0},
  };
  if (auto ok = reader.read_number_fields(document, "", fields, /*required=*/true); !ok) {
    return ok.error();
  }
  if (p.inhale_min_s > p.inhale_max_s) return reader.error("/inhale_min_s", "above inhale_max_s");
  if (p.catch_min_s > p.catch_inhale_s) {
    return reader.error("/catch_min_s", "above catch_inhale_s");
  }
  return p;
}

}  // namespace tutti::brass_motion
