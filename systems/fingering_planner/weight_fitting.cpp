// SPDX-License-Identifier: MIT
#include <tutti/fingering_planner/weight_fitting.hpp>

#include <cmath>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

namespace tutti::fingering_planner {
namespace {

struct Tunable {
  std::string name;
  std::function<double&(CostWeights&)> field;
};

// Every finite weight that shapes the choice of fingers (not the event grouping, the
// unreachable/impossible penalties, the natural spacing unit, or the physical limits of a shift:
// its time and the hand speed limit, which come from measurements, not from marks).
const std::vector<Tunable>& tunables() {
  static const std::vector<Tunable> list = [] {
    std::vector<Tunable> t;
    auto add = [&](std::string name, std::function<double&(CostWeights&)> f) {
      t.push_back({std::move(name), std::move(f)});
    };
    add("hand_area/overlap", [](CostWeights& w) -> double& { return w.area_overlap; });
    add("hand_area/gap_base", [](CostWeights& w) -> double& { return w.gap_base; });
    add("hand_area/gap_speed_per_white_key_per_s",
        [](CostWeights& w) -> double& { return w.gap_speed; });
    for (std::size_t i = 0; i < 5; ++i) {
      add("fingers/use/" + std::to_string(i),
          [i](CostWeights& w) -> double& { return w.finger_use[i]; });
    }
    for (std::size_t i = 0; i < 5; ++i) {
      add("fingers/black_key/" + std::to_string(i),
          [i](CostWeights& w) -> double& { return w.black_key[i]; });
    }
    add("fingers/thumb_on_tonic", [](CostWeights& w) -> double& { return w.thumb_on_tonic; });
    add("fingers/thumb_on_fourth", [](CostWeights& w) -> double& { return w.thumb_on_fourth; });
    add("same_finger/other_key", [](CostWeights& w) -> double& { return w.same_finger_other_key; });
    add("same_finger/speed_per_white_key_per_s",
        [](CostWeights& w) -> double& { return w.same_finger_speed; });
    add("same_finger/same_key", [](CostWeights& w) -> double& { return w.same_finger_same_key; });
    add("same_finger/repeat_finger_change",
        [](CostWeights& w) -> double& { return w.repeat_finger_change; });
    add("spacing/stretch", [](CostWeights& w) -> double& { return w.spacing_stretch; });
    add("spacing/compress", [](CostWeights& w) -> double& { return w.spacing_compress; });
    add("spacing/thumb_factor", [](CostWeights& w) -> double& { return w.spacing_thumb_factor; });
    add("crossing/thumb", [](CostWeights& w) -> double& { return w.cross_thumb; });
    for (std::size_t i = 1; i < 4; ++i) {
      add("crossing/thumb_by_finger/" + std::to_string(i),
          [i](CostWeights& w) -> double& { return w.cross_thumb_finger[i]; });
    }
    add("crossing/thumb_distance",
        [](CostWeights& w) -> double& { return w.cross_thumb_distance; });
    add("crossing/thumb_on_black", [](CostWeights& w) -> double& { return w.cross_thumb_black; });
    add("crossing/thumb_little", [](CostWeights& w) -> double& { return w.cross_little; });
    add("crossing/other", [](CostWeights& w) -> double& { return w.cross_other; });
    return t;
  }();
  return list;
}

std::vector<music::Score> stripped(const std::vector<music::Score>& scores) {
  std::vector<music::Score> out = scores;
  for (music::Score& s : out) {
    for (music::Note& n : s.notes) n.finger = 0, n.finger_substitute = 0;
  }
  return out;
}

Result<MatchStats> evaluate(const std::vector<music::Score>& annotated,
                            const std::vector<music::Score>& unmarked, const FingeringModel& model,
                            const PlanOptions& options) {
  MatchStats total;
  for (std::size_t i = 0; i < annotated.size(); ++i) {
    auto plan = plan_score(unmarked[i], model, options);
    if (!plan) return plan.error();
    total += match_rate(annotated[i], *plan);
  }
  return total;
}

nlohmann::json number_json(double value) {
  if (std::isinf(value)) return "inf";
  return value;
}

nlohmann::json five_json(const std::array<double, 5>& values) {
  nlohmann::json array = nlohmann::json::array();
  for (double v : values) array.push_back(v);
  return array;
}

}  // namespace

MatchStats& MatchStats::operator+=(const MatchStats& other) {
  right_marked += other.right_marked;
  right_matched += other.right_matched;
  left_marked += other.left_marked;
  left_matched += other.left_matched;
  return *this;
}

MatchStats match_rate(const music::Score& score_with_marks, const ScorePlan& plan) {
  MatchStats stats;
  const std::size_t n = std::min(score_with_marks.notes.size(), plan.fingers.size());
  for (std::size_t i = 0; i < n; ++i) {
    const int mark = score_with_marks.notes[i].finger;
    if (mark < 1 || mark > 5) continue;
    const bool match = plan.fingers[i] == mark;
    const bool left = i < plan.hands.size() && plan.hands[i] == music::Hand::left;
    (left ? stats.left_marked : stats.right_marked) += 1;
    (left ? stats.left_matched : stats.right_matched) += match ? 1 : 0;
  }
  return stats;
}

Result<MatchStats> evaluate_match(const std::vector<music::Score>& annotated,
                                  const FingeringModel& model, const PlanOptions& options) {
  PlanOptions o = options;
  o.pins_from_marks = false;
  return evaluate(annotated, stripped(annotated), model, o);
}

std::vector<std::string> tunable_weight_names() {
  std::vector<std::string> names;
  for (const Tunable& t : tunables()) names.push_back(t.name);
  return names;
}

Result<FitResult> fit_weights(const std::vector<music::Score>& annotated, const CostWeights& start,
                              const FitOptions& options) {
  auto loaded = load_fingering_model("paper", options.hand_preset, options.content_dir);
  if (!loaded) return loaded.error();
  FingeringModel model = std::move(*loaded);
  model.weights = start;
  const std::vector<music::Score> unmarked = stripped(annotated);
  PlanOptions plan_options;
  plan_options.pins_from_marks = false;

  FitResult result;
  auto score_of = [&](const CostWeights& w) -> Result<int> {
    model.weights = w;
    ++result.evaluations;
    auto stats = evaluate(annotated, unmarked, model, plan_options);
    if (!stats) return stats.error();
    return stats->matched();
  };
  auto first = evaluate(annotated, unmarked, model, plan_options);
  if (!first) return first.error();
  ++result.evaluations;
  const int marked = first->marked();
  if (marked == 0) return Error{"fit_weights: no marked notes (Note::finger 1..5) to fit"};
  int best = first->matched();
  result.match_before = double(best) / marked;

  std::vector<const Tunable*> chosen;
  for (const Tunable& t : tunables()) {
    if (options.only.empty()) {
      chosen.push_back(&t);
      continue;
    }
    for (const std::string& name : options.only) {
      if (name == t.name) chosen.push_back(&t);
    }
  }
  if (!options.only.empty() && chosen.size() != options.only.size()) {
    return Error{"fit_weights: unknown weight name in FitOptions::only"};
  }

  CostWeights current = start;
  for (int round = 0; round < options.max_rounds; ++round) {
    ++result.iterations;
    bool changed = false;
    for (const Tunable* t : chosen) {
      const double value = t->field(current);
      if (!std::isfinite(value)) continue;
      std::vector<double> trials;
      if (value == 0.0) {
        for (double s : options.zero_steps) trials.push_back(s), trials.push_back(-s);
      } else {
        for (double f : options.factors) trials.push_back(value * f);
      }
      double best_value = value;
      for (double trial : trials) {
        CostWeights w = current;
        t->field(w) = trial;
        auto score = score_of(w);
        if (!score) return score.error();
        if (*score > best) best = *score, best_value = trial;
      }
      if (best_value != value) {
        t->field(current) = best_value;
        changed = true;
      }
    }
    if (!changed) break;
  }
  result.weights = current;
  result.match_after = double(best) / marked;
  return result;
}

nlohmann::json cost_weights_to_json(const CostWeights& w, const std::string& description) {
  nlohmann::json doc;
  doc["name"] = w.name;
  if (!description.empty()) doc["description"] = description;
  doc["hand_area"] = {{"overlap", w.area_overlap},
                      {"gap_base", w.gap_base},
                      {"gap_speed_per_white_key_per_s", w.gap_speed},
                      {"release_fraction", w.release_fraction},
                      {"shift_time_s", w.shift_time_s},
                      {"shift_hold_fraction", w.shift_hold_fraction},
                      {"speed_limit_white_keys_per_s", number_json(w.speed_limit)},
                      {"over_speed_per_white_key_per_s", w.over_speed}};
  doc["fingers"] = {{"use", five_json(w.finger_use)},
                    {"black_key", five_json(w.black_key)},
                    {"thumb_on_tonic", w.thumb_on_tonic},
                    {"thumb_on_fourth", w.thumb_on_fourth}};
  doc["same_finger"] = {{"other_key", number_json(w.same_finger_other_key)},
                        {"speed_per_white_key_per_s", w.same_finger_speed},
                        {"same_key", w.same_finger_same_key},
                        {"repeat_finger_change", w.repeat_finger_change}};
  doc["spacing"] = {{"per_finger", w.spacing_per_finger},
                    {"stretch", w.spacing_stretch},
                    {"compress", w.spacing_compress},
                    {"thumb_factor", w.spacing_thumb_factor},
                    {"max_distance", w.spacing_max_distance}};
  doc["crossing"] = {{"thumb", w.cross_thumb},
                     {"thumb_by_finger", five_json(w.cross_thumb_finger)},
                     {"thumb_distance", w.cross_thumb_distance},
                     {"thumb_on_black", w.cross_thumb_black},
                     {"thumb_little", w.cross_little},
                     {"other", w.cross_other}};
  doc["other_hand"] = {{"separation_white_keys", w.other_hand_separation},
                       {"per_white_key", w.other_hand_per_white_key},
                       {"lead_s", w.other_hand_lead_s}};
  doc["events"] = {{"chord_tolerance_s", w.chord_tolerance_s},
                   {"unreachable_per_white_key", w.unreachable},
                   {"impossible", w.impossible}};
  return doc;
}

Status save_cost_weights(const CostWeights& weights, const std::filesystem::path& path,
                         const std::string& description) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) return Error{path.string() + ": cannot open for writing"};
  out << cost_weights_to_json(weights, description).dump(2) << '\n';
  out.close();
  if (!out) return Error{path.string() + ": write failed"};
  return Status::success();
}

}  // namespace tutti::fingering_planner
