// SPDX-License-Identifier: MIT
#include <tutti/cli/stream_report_command.hpp>

#include <cstdio>
#include <ostream>

#include <tutti/core/exit_codes.hpp>
#include <tutti/fingering_planner/fingering_model.hpp>
#include <tutti/fingering_planner/streaming_report.hpp>
#include <tutti/music/load_score.hpp>

namespace tutti::cli {
namespace {

std::string percent(int part, int whole) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f %%", whole > 0 ? 100.0 * part / whole : 100.0);
  return text;
}

std::string row(const std::string& name, const fingering_planner::StreamingAgreement& a) {
  const double exact = a.right.exact_cost + a.left.exact_cost;
  char ratio[32], split_ratio[32];
  std::snprintf(ratio, sizeof ratio, "%.3f", a.cost_ratio());
  std::snprintf(split_ratio, sizeof split_ratio, "%.3f", exact > 0 ? a.split_cost / exact : 1.0);
  return "| " + name + " | " + std::to_string(a.lookahead) + " | " + std::to_string(a.notes) +
         " | " + percent(a.right.same_finger, a.right.notes) + " | " +
         percent(a.left.same_finger, a.left.notes) + " | " + percent(a.same_finger(), a.notes) +
         " | " + ratio + " | " + percent(a.same_as_lookahead_planner, a.notes) + " | " +
         percent(a.split_same_hand, a.notes) + " | " + percent(a.split_same_finger, a.notes) +
         " | " + split_ratio + " |\n";
}

void add(fingering_planner::StreamingAgreement& total,
         const fingering_planner::StreamingAgreement& a) {
  total.notes += a.notes;
  for (auto [to, from] : {std::pair{&total.right, &a.right}, std::pair{&total.left, &a.left}}) {
    to->notes += from->notes;
    to->same_finger += from->same_finger;
    to->streaming_cost += from->streaming_cost;
    to->exact_cost += from->exact_cost;
  }
  total.split_same_hand += a.split_same_hand;
  total.split_same_finger += a.split_same_finger;
  total.split_cost += a.split_cost;
  total.same_as_lookahead_planner += a.same_as_lookahead_planner;
}

}  // namespace

int run_stream_report(const StreamReportOptions& o, std::ostream& out, std::ostream& err) {
  const Fail fail{err};
  if (o.inputs.empty()) return fail("no input files");
  for (int l : o.lookaheads) {
    if (l < 0) return fail("--lookahead " + std::to_string(l) + ": must be >= 0");
  }
  auto model = fingering_planner::load_fingering_model(o.weights);
  if (!model) return fail(model.error());
  std::vector<music::Score> scores;
  for (const auto& input : o.inputs) {
    auto score = music::load_score(input);
    if (!score) return fail(score.error());
    for (music::Note& n : score->notes) n.finger = 0;  // plan from scratch on both sides
    scores.push_back(std::move(*score));
  }
  out << "| piece | L | notes | right = exact | left = exact | all = exact | cost / exact | = "
         "lookahead planner (L+1) | live split: hand = exact | hand and finger = exact | cost / "
         "exact |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  std::vector<fingering_planner::StreamingAgreement> totals;
  for (int l : o.lookaheads) {
    fingering_planner::StreamingAgreement total;
    total.lookahead = l;
    for (std::size_t i = 0; i < scores.size(); ++i) {
      auto a = fingering_planner::measure_streaming_agreement(scores[i], *model, l);
      if (!a) return fail(o.inputs[i].string() + ": " + a.error().message);
      out << row(o.inputs[i].filename().string(), *a);
      add(total, *a);
    }
    totals.push_back(total);
  }
  for (const auto& total : totals) out << row("**all**", total);
  return kExitOk;
}

}  // namespace tutti::cli
