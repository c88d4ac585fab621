// SPDX-License-Identifier: MIT
#include <tutti/fingering_planner/streaming_report.hpp>

#include <algorithm>
#include <limits>
#include <numeric>

#include <tutti/fingering_planner/exact_planner.hpp>
#include <tutti/fingering_planner/lookahead_planner.hpp>
#include <tutti/fingering_planner/plan_score.hpp>
#include <tutti/fingering_planner/streaming_piano.hpp>

namespace tutti::fingering_planner {
namespace {

PlanNote plan_note(const music::Score& score, const FingeringModel& model,
                   const std::vector<int>& tonics, int index) {
  const music::Note& n = score.notes[static_cast<std::size_t>(index)];
  PlanNote p;
  p.key = std::clamp(n.pitch, model.keyboard.lowest_key(), model.keyboard.highest_key());
  p.onset_s = n.onset_s;
  p.offset_s = std::max(n.offset_s, n.onset_s);
  p.tonic = tonics[static_cast<std::size_t>(index)];
  return p;
}

// The cost model's total for these fingers (pinned), impossible moves priced as the DP does.
double fingering_cost(std::vector<PlanNote> notes, const std::vector<int>& fingers,
                      music::Hand side, const FingeringModel& model) {
  for (std::size_t i = 0; i < notes.size(); ++i) notes[i].pin = fingers[i];
  auto plan = plan_hand_exact(notes, side, model);
  if (!plan) return 0.0;
  return plan->total_cost + model.weights.impossible * plan->impossible_transitions;
}

// Notes in the order they arrive: by onset, then key (the planners' own order).
std::vector<int> arrival_order(const music::Score& score, std::vector<int> indices) {
  std::stable_sort(indices.begin(), indices.end(), [&](int a, int b) {
    const music::Note& x = score.notes[static_cast<std::size_t>(a)];
    const music::Note& y = score.notes[static_cast<std::size_t>(b)];
    return x.onset_s != y.onset_s ? x.onset_s < y.onset_s : x.pitch < y.pitch;
  });
  return indices;
}

// Feeds `order` (Score::notes indices) as they would arrive: time moves to each new onset
// (decisions due by then are made), then the notes starting there are pushed. Returns the
// finger and hand per Score::notes index (0 / unknown where not fed).
Status feed(const music::Score& score, const FingeringModel& model, const std::vector<int>& tonics,
            const std::vector<int>& order, const std::vector<music::Hand>* hands, int lookahead,
            std::vector<int>& fingers, std::vector<music::Hand>& fed_hands) {
  StreamingOptions options;
  options.lookahead = lookahead;
  auto planner = StreamingPianoPlanner::create(model, options);
  if (!planner) return planner.error();
  std::vector<StreamedFinger> decided;
  double last_onset = -std::numeric_limits<double>::infinity();
  for (int index : order) {
    const PlanNote p = plan_note(score, model, tonics, index);
    // A chord's notes arrive together: time moves on only at a new onset.
    if (p.onset_s > last_onset) planner->advance(p.onset_s, decided);
    last_onset = p.onset_s;
    const music::Hand hand =
        hands != nullptr ? (*hands)[static_cast<std::size_t>(index)] : music::Hand::unknown;
    auto side = planner->push(index, p, p.offset_s, hand);
    if (!side) return side.error();
    fed_hands[static_cast<std::size_t>(index)] = *side;
  }
  planner->flush(score.notes.empty() ? 0.0 : score.notes.back().offset_s, decided);
  for (const StreamedFinger& d : decided) fingers[static_cast<std::size_t>(d.id)] = d.finger;
  return {};
}

}  // namespace

Result<StreamingAgreement> measure_streaming_agreement(const music::Score& score,
                                                       const FingeringModel& model, int lookahead) {
  if (lookahead < 0) return Error{"lookahead must be >= 0"};
  PlanOptions exact_options;
  exact_options.pins_from_marks = false;
  // The streaming planner plans each hand alone; so does the reference it is measured against
  // (the other hand's room, other_hand_cost.hpp, is not part of this comparison).
  FingeringModel alone = model;
  alone.weights.other_hand_per_white_key = 0.0;
  auto exact = plan_score(score, alone, exact_options);
  if (!exact) return exact.error();
  const std::vector<int> tonics = note_tonics(score);
  std::vector<int> planned;
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    if (exact->hands[i] == music::Hand::left || exact->hands[i] == music::Hand::right)
      planned.push_back(static_cast<int>(i));
  }
  const std::vector<int> order = arrival_order(score, planned);

  StreamingAgreement out;
  out.lookahead = lookahead;
  out.notes = static_cast<int>(planned.size());
  const std::size_t count = score.notes.size();

  // The exact plan's hands.
  std::vector<int> fingers(count, 0);
  std::vector<music::Hand> fed(count, music::Hand::unknown);
  if (Status s = feed(score, model, tonics, order, &exact->hands, lookahead, fingers, fed); !s)
    return s.error();
  for (music::Hand side : {music::Hand::right, music::Hand::left}) {
    const std::vector<int>& indices =
        side == music::Hand::right ? exact->right_notes : exact->left_notes;
    const HandPlan& plan = side == music::Hand::right ? exact->right : exact->left;
    HandAgreement& a = side == music::Hand::right ? out.right : out.left;
    std::vector<PlanNote> notes;
    std::vector<int> streamed;
    for (int index : indices) {
      notes.push_back(plan_note(score, model, tonics, index));
      streamed.push_back(fingers[static_cast<std::size_t>(index)]);
    }
    a.notes = static_cast<int>(indices.size());
    for (std::size_t k = 0; k < indices.size(); ++k) {
      a.same_finger += streamed[k] == plan.fingers[k] ? 1 : 0;
    }
    a.streaming_cost = fingering_cost(notes, streamed, side, model);
    a.exact_cost = fingering_cost(notes, plan.fingers, side, model);
    auto paper = plan_hand_lookahead(notes, side, model, lookahead + 1);
    if (!paper) return paper.error();
    for (std::size_t k = 0; k < indices.size(); ++k) {
      out.same_as_lookahead_planner += streamed[k] == paper->fingers[k] ? 1 : 0;
    }
  }

  // The live split.
  std::fill(fingers.begin(), fingers.end(), 0);
  std::fill(fed.begin(), fed.end(), music::Hand::unknown);
  if (Status s = feed(score, model, tonics, order, nullptr, lookahead, fingers, fed); !s)
    return s.error();
  for (int index : planned) {
    const auto i = static_cast<std::size_t>(index);
    const bool same_hand = fed[i] == exact->hands[i];
    out.split_same_hand += same_hand ? 1 : 0;
    out.split_same_finger += same_hand && fingers[i] == exact->fingers[i] ? 1 : 0;
  }
  for (music::Hand side : {music::Hand::right, music::Hand::left}) {
    std::vector<PlanNote> notes;
    std::vector<int> streamed;
    for (int index : order) {
      if (fed[static_cast<std::size_t>(index)] != side) continue;
      notes.push_back(plan_note(score, model, tonics, index));
      streamed.push_back(fingers[static_cast<std::size_t>(index)]);
    }
    out.split_cost += fingering_cost(notes, streamed, side, model);
  }
  return out;
}

}  // namespace tutti::fingering_planner
