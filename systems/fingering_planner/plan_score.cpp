// SPDX-License-Identifier: MIT
#include <tutti/fingering_planner/plan_score.hpp>

#include <algorithm>
#include <array>
#include <cmath>

#include <tutti/fingering_planner/exact_planner.hpp>
#include <tutti/fingering_planner/local_replan.hpp>
#include <tutti/fingering_planner/lookahead_planner.hpp>
#include <tutti/music/meter.hpp>
#include <tutti/music/pitch.hpp>

namespace tutti::fingering_planner {

// The piano model's names this planner uses (systems/piano_model).
using piano_model::HandCorridor;

Result<HandPlan> plan_hand(std::span<const PlanNote> notes, music::Hand side,
                           const FingeringModel& model, const PlanOptions& options,
                           std::span<const HandCorridor> other_hand) {
  if (options.mode == PlannerMode::lookahead) {
    return plan_hand_lookahead(notes, side, model, options.lookahead, other_hand);
  }
  return plan_hand_exact(notes, side, model, other_hand);
}

std::vector<int> note_tonics(const music::Score& score) {
  std::vector<int> out(score.notes.size(), -1);
  if (score.notes.empty()) return out;
  if (!score.key_signatures.empty()) {
    for (std::size_t i = 0; i < score.notes.size(); ++i) {
      const music::KeySignature* in_force = &score.key_signatures.front();
      for (const music::KeySignature& k : score.key_signatures) {
        if (k.tick > score.notes[i].onset_ticks) break;
        in_force = &k;
      }
      const int major = ((in_force->fifths * 7) % 12 + 12) % 12;
      out[i] = in_force->minor ? (major + 9) % 12 : major;
    }
    return out;
  }
  std::array<double, 12> weight{};
  int first_low = score.notes.front().pitch;
  const std::int64_t first_tick = score.notes.front().onset_ticks;
  for (const music::Note& n : score.notes) {
    weight[static_cast<std::size_t>(((n.pitch % 12) + 12) % 12)] +=
        std::max(n.offset_s - n.onset_s, 0.0) + 1e-3;
    if (n.onset_ticks == first_tick) first_low = std::min(first_low, n.pitch);
  }
  static constexpr std::array<std::array<int, 7>, 2> kScales = {
      {{0, 2, 4, 5, 7, 9, 11}, {0, 2, 3, 5, 7, 8, 11}}};  // major, harmonic minor
  int best_tonic = -1;
  double best = -1.0;
  for (const auto& scale : kScales) {
    for (int t = 0; t < 12; ++t) {
      double sum = 0.0;
      for (int s : scale) sum += weight[static_cast<std::size_t>((t + s) % 12)];
      const bool better =
          sum > best + 1e-9 || (std::abs(sum - best) <= 1e-9 && t == ((first_low % 12) + 12) % 12 &&
                                best_tonic != ((first_low % 12) + 12) % 12);
      if (better) best = sum, best_tonic = t;
    }
  }
  std::fill(out.begin(), out.end(), best_tonic);
  return out;
}

namespace {

// One hand's planner input: the notes `indices` of the score (clamped to the keyboard, each
// clamp reported in `clamped`), with their tonics and pins.
std::vector<PlanNote> hand_input(const music::Score& score, const FingeringModel& model,
                                 const PlanOptions& options, std::span<const int> indices,
                                 std::span<const int> tonics, std::vector<Diagnostic>& clamped) {
  std::vector<PlanNote> notes;
  notes.reserve(indices.size());
  for (int index : indices) {
    const auto i = static_cast<std::size_t>(index);
    const music::Note& n = score.notes[i];
    PlanNote p;
    p.key = std::clamp(n.pitch, model.keyboard.lowest_key(), model.keyboard.highest_key());
    if (p.key != n.pitch) {
      Diagnostic d;
      d.kind = DiagnosticKind::unreachable_span;
      d.time_s = n.onset_s;
      d.bar = music::bar_at_beats(score, n.onset_beats);
      d.notes = {index};
      d.message = score.source + ": bar " + std::to_string(d.bar) + ": " +
                  music::pitch_name(n.pitch) + " is off the keyboard; planned as " +
                  music::pitch_name(p.key);
      clamped.push_back(std::move(d));
    }
    p.onset_s = n.onset_s;
    p.offset_s = std::max(n.offset_s, n.onset_s);
    p.tonic = tonics[i];
    p.pin = options.pins_from_marks && n.finger >= 1 && n.finger <= 5 ? n.finger : 0;
    notes.push_back(p);
  }
  return notes;
}

// Hand-local note indices in `plan` become Score::notes indices, messages name file and bar.
// Only the first `count` diagnostics are converted (the rest already are, from an earlier plan).
void to_score_terms(const music::Score& score, music::Hand side, std::span<const int> indices,
                    HandPlan& plan, std::size_t count) {
  for (std::size_t k = 0; k < count; ++k) {
    Diagnostic& d = plan.diagnostics[k];
    for (int& note : d.notes) note = indices[static_cast<std::size_t>(note)];
    if (!d.notes.empty()) {
      d.bar = music::bar_at_beats(
          score, score.notes[static_cast<std::size_t>(d.notes.front())].onset_beats);
    }
    d.message = score.source + ": bar " + std::to_string(d.bar) + " (" +
                (side == music::Hand::right ? "right" : "left") + " hand) " + d.message;
  }
}

void add_clamped(ScorePlan& out, std::vector<Diagnostic>& clamped) {
  for (Diagnostic& d : clamped) {
    HandPlan& target = out.hands[static_cast<std::size_t>(d.notes.front())] == music::Hand::left
                           ? out.left
                           : out.right;
    target.diagnostics.push_back(std::move(d));
  }
}

}  // namespace

Result<ScorePlan> plan_score(const music::Score& score, const FingeringModel& model,
                             const PlanOptions& options) {
  ScorePlan out;
  const HandAssignment assignment = assign_hands(score, model);
  out.hands = assignment.hand;
  out.fingers.assign(score.notes.size(), 0);
  std::vector<Diagnostic> clamped;
  const std::vector<int> tonics =
      options.tonic_from_key ? note_tonics(score) : std::vector<int>(score.notes.size(), -1);
  std::vector<PlanNote> right_input, left_input;  // read once, planned up to twice
  for (music::Hand side : {music::Hand::right, music::Hand::left}) {
    std::vector<int>& indices = side == music::Hand::right ? out.right_notes : out.left_notes;
    for (std::size_t i = 0; i < score.notes.size(); ++i) {
      if (assignment.hand[i] == side) indices.push_back(static_cast<int>(i));
    }
    (side == music::Hand::right ? right_input : left_input) =
        hand_input(score, model, options, indices, tonics, clamped);
  }
  // Plans one hand beside the other hand's corridors (other_hand_cost.hpp; empty = alone).
  auto plan_side = [&](music::Hand side, std::span<const HandCorridor> other) -> Status {
    const bool right = side == music::Hand::right;
    const std::vector<int>& indices = right ? out.right_notes : out.left_notes;
    auto plan = plan_hand(right ? right_input : left_input, side, model, options, other);
    if (!plan) return Error{score.source + ": " + plan.error().message};
    for (std::size_t k = 0; k < indices.size(); ++k) {
      out.fingers[static_cast<std::size_t>(indices[k])] = plan->fingers[k];
    }
    to_score_terms(score, side, indices, *plan, plan->diagnostics.size());
    (right ? out.right : out.left) = std::move(*plan);
    return Status::success();
  };
  // The right hand first, alone; the left hand beside it. Then the right hand again beside the
  // left (a right hand that would reach past the left thumb takes another fingering) and the
  // left once more beside where the right hand now is, so each hand's plan and cost are the
  // ones beside the other's final plan.
  if (Status s = plan_side(music::Hand::right, {}); !s) return s.error();
  if (Status s = plan_side(music::Hand::left, out.right.corridors); !s) return s.error();
  if (model.weights.other_hand_per_white_key > 0.0 && !out.left.corridors.empty() &&
      !out.right_notes.empty()) {
    if (Status s = plan_side(music::Hand::right, out.left.corridors); !s) return s.error();
    if (Status s = plan_side(music::Hand::left, out.right.corridors); !s) return s.error();
  }
  add_clamped(out, clamped);
  return out;
}

Result<ScorePlan> replan_score_locally(const music::Score& score, const FingeringModel& model,
                                       const PlanOptions& options, const ScorePlan& previous,
                                       std::span<const int> edited, ScoreReplanSpan* span) {
  if (previous.fingers.size() != score.notes.size() ||
      previous.hands.size() != score.notes.size()) {
    return Error{score.source + ": re-plan: the previous plan is for " +
                 std::to_string(previous.fingers.size()) + " notes, the score has " +
                 std::to_string(score.notes.size())};
  }
  ScorePlan out = previous;
  ScoreReplanSpan summary;
  int right_changed_notes = 0;
  double right_changed_first_s = 0.0, right_changed_last_s = 0.0;
  std::vector<Diagnostic> clamped;
  const std::vector<int> tonics =
      options.tonic_from_key ? note_tonics(score) : std::vector<int>(score.notes.size(), -1);
  for (music::Hand side : {music::Hand::right, music::Hand::left}) {
    const std::vector<int>& indices =
        side == music::Hand::right ? previous.right_notes : previous.left_notes;
    std::vector<int> local_edits;
    for (std::size_t k = 0; k < indices.size(); ++k) {
      const music::Note& note = score.notes[static_cast<std::size_t>(indices[k])];
      // The left hand keeps out of the right hand's way: where the right hand's fingering
      // changed, the left hand's is searched again too.
      const double lead = model.weights.other_hand_lead_s;
      const bool beside_changed_right =
          side == music::Hand::left && right_changed_notes > 0 &&
          note.offset_s >= right_changed_first_s - lead && note.onset_s <= right_changed_last_s + lead;
      if (beside_changed_right ||
          std::find(edited.begin(), edited.end(), indices[k]) != edited.end()) {
        local_edits.push_back(static_cast<int>(k));
      }
    }
    if (local_edits.empty()) continue;
    const std::vector<PlanNote> notes = hand_input(score, model, options, indices, tonics, clamped);
    HandPlan before = side == music::Hand::right ? previous.right : previous.left;
    before.fingers.resize(indices.size());
    for (std::size_t k = 0; k < indices.size(); ++k) {
      before.fingers[k] = previous.fingers[static_cast<std::size_t>(indices[k])];
    }
    // The previous plan's diagnostics are in score terms; the hand-level re-plan keeps the
    // ones outside its window as they are.
    // Each hand beside the other, as plan_score leaves them.
    auto replan = replan_hand_locally(
        notes, side, model, before, local_edits,
        side == music::Hand::left ? out.right.corridors : out.left.corridors);
    if (!replan) return Error{score.source + ": " + replan.error().message};
    HandPlan& target = side == music::Hand::right ? out.right : out.left;
    target = std::move(replan->plan);
    to_score_terms(score, side, indices, target,
                   target.diagnostics.size() - static_cast<std::size_t>(replan->kept_diagnostics));
    for (std::size_t k = 0; k < indices.size(); ++k) {
      out.fingers[static_cast<std::size_t>(indices[k])] = target.fingers[k];
    }
    if (side == music::Hand::right) {
      right_changed_notes = replan->changed_notes;
      right_changed_first_s = replan->first_changed_s;
      right_changed_last_s = replan->last_changed_s;
    }
    summary.changed_notes += replan->changed_notes;
    summary.searched_events += replan->searched_last_event - replan->searched_first_event + 1;
    summary.event_count += replan->event_count;
    if (replan->changed_notes > 0) {
      summary.first_changed_s = summary.changed_notes == replan->changed_notes
                                    ? replan->first_changed_s
                                    : std::min(summary.first_changed_s, replan->first_changed_s);
      summary.last_changed_s = std::max(summary.last_changed_s, replan->last_changed_s);
    }
  }
  add_clamped(out, clamped);  // only re-planned hands were read again
  if (span != nullptr) *span = summary;
  return out;
}

}  // namespace tutti::fingering_planner
