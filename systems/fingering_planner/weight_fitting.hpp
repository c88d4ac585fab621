// SPDX-License-Identifier: MIT
#pragma once
// Fitting the cost weights to annotated fingerings (Note::finger marks), and saving weights.
//
// fit_weights: deterministic coordinate descent on the exact planner's agreement with the marks.
// Each round tries, for every tunable weight in a fixed order, a few multiplicative steps
// (a zero weight tries small absolute values instead) and keeps the best strict improvement of
// the match rate; rounds repeat until one changes nothing (or max_rounds). The objective is the
// fraction of marked notes whose planned finger equals the mark (marks are stripped before
// planning, so they are never pins). Ties keep the current value: the result only depends on the
// inputs.
//
// save_cost_weights writes the same JSON schema as content/piano/fingering/*.json
// (load_cost_weights reads it back to the same values).

#include <filesystem>
#include <string>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/fingering_planner/cost_weights.hpp>
#include <tutti/fingering_planner/fingering_model.hpp>
#include <tutti/fingering_planner/plan_score.hpp>
#include <tutti/music/score.hpp>

namespace tutti::fingering_planner {

// The piano model's names this planner uses (systems/piano_model).
using piano_model::default_content_dir;

// Agreement of a plan with a score's marks (notes with Note::finger 1..5), per hand.
struct MatchStats {
  int right_marked = 0;
  int right_matched = 0;
  int left_marked = 0;
  int left_matched = 0;

  int marked() const { return right_marked + left_marked; }
  int matched() const { return right_matched + left_matched; }
  // Fractions in 0..1; 0 when nothing is marked.
  double rate() const { return marked() ? double(matched()) / marked() : 0.0; }
  double right_rate() const { return right_marked ? double(right_matched) / right_marked : 0.0; }
  double left_rate() const { return left_marked ? double(left_matched) / left_marked : 0.0; }
  MatchStats& operator+=(const MatchStats& other);
};

// `score_with_marks` is the score as annotated; `plan` = plan_score of it (normally planned with
// the marks stripped). The hand of a note is the plan's.
MatchStats match_rate(const music::Score& score_with_marks, const ScorePlan& plan);

// Plans every score with marks stripped and sums the agreement.
Result<MatchStats> evaluate_match(const std::vector<music::Score>& annotated,
                                  const FingeringModel& model, const PlanOptions& options = {});

struct FitOptions {
  std::vector<double> factors{0.5, 0.8, 1.25, 2.0};  // multiplicative steps per weight
  std::vector<double> zero_steps{0.1, 0.5};          // tried (±) for a weight that is 0
  int max_rounds = 8;
  // Names of the weights to tune (see tunable_weight_names()); empty = all of them.
  std::vector<std::string> only;
  // Keyboard and hand geometry used while fitting (the weights are replaced).
  std::string hand_preset;  // empty = hands.json default
  std::filesystem::path content_dir = default_content_dir();
};

struct FitResult {
  CostWeights weights;
  double match_before = 0.0;  // 0..1 on the annotated notes
  double match_after = 0.0;
  int iterations = 0;   // rounds of coordinate descent run
  int evaluations = 0;  // planner runs over the whole set
};

// Error when nothing is marked, or a score cannot be planned.
Result<FitResult> fit_weights(const std::vector<music::Score>& annotated, const CostWeights& start,
                              const FitOptions& options = {});

// The weights fit_weights may change, as "section/key" or "section/key/i" for arrays.
std::vector<std::string> tunable_weight_names();

// JSON in the schema of content/piano/fingering/*.json (infinity written as "inf").
nlohmann::json cost_weights_to_json(const CostWeights& weights,
                                    const std::string& description = "");
Status save_cost_weights(const CostWeights& weights, const std::filesystem::path& path,
                         const std::string& description = "");

}  // namespace tutti::fingering_planner
