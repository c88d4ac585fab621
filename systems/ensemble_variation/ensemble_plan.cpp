// SPDX-License-Identifier: MIT
#include <tutti/ensemble_variation/ensemble_plan.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <tutti/music/meter.hpp>

namespace tutti::ensemble_variation {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kBreathRelease_s = 0.35;

// Bar lines (quarter notes from the start) up to `end_beats`: a time signature change starts a
// bar; without time signatures, 4/4.
std::vector<double> bar_lines(const music::Score& score, double end_beats) {
  std::vector<double> bars;
  std::vector<std::pair<double, double>> meters;  // (start beats, bar length in quarters)
  for (const music::TimeSignature& ts : score.time_signatures) {
    const double length =
        ts.denominator > 0 && ts.numerator > 0 ? 4.0 * ts.numerator / ts.denominator : 4.0;
    meters.emplace_back(score.tempo_map.beats_at(static_cast<double>(ts.tick)), length);
  }
  if (meters.empty() || meters.front().first > 0.0) meters.insert(meters.begin(), {0.0, 4.0});
  for (std::size_t m = 0; m < meters.size(); ++m) {
    const double until = m + 1 < meters.size() ? meters[m + 1].first : end_beats;
    for (double b = meters[m].first; b < until - 1e-9 && bars.size() < 100000;
         b += meters[m].second) {
      bars.push_back(b);
    }
  }
  return bars;
}

// The spans sorted, cleaned and made disjoint (PerformerInput::expressions).
std::vector<ExpressionSpan> clean_expressions(const std::vector<ExpressionSpan>& spans) {
  std::vector<ExpressionSpan> sorted;
  for (ExpressionSpan span : spans) {
    if (!std::isfinite(span.start_s) || !std::isfinite(span.end_s) ||
        !(span.end_s > span.start_s)) {
      continue;
    }
    span.amount = std::isfinite(span.amount) ? std::clamp(span.amount, 0.0, 1.0) : 0.0;
    sorted.push_back(span);
  }
  // Stable on ties, so the editor's order decides between spans starting together.
  std::stable_sort(
      sorted.begin(), sorted.end(),
      [](const ExpressionSpan& a, const ExpressionSpan& b) { return a.start_s < b.start_s; });
  std::vector<ExpressionSpan> out;
  for (ExpressionSpan span : sorted) {
    if (!out.empty()) span.start_s = std::max(span.start_s, out.back().end_s);
    if (span.end_s > span.start_s) out.push_back(span);
  }
  return out;
}

}  // namespace

Result<EnsemblePlan> plan_ensemble(const std::vector<PerformerInput>& inputs,
                                   const EnsembleOptions& options) {
  EnsemblePlan plan;
  bool any = false;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    if (inputs[i].score == nullptr) return Error{"ensemble: a performer has no score"};
    if (inputs[i].lead && plan.lead < 0) plan.lead = static_cast<int>(i);
    if (!any || inputs[i].first_onset_s < plan.entrance_s)
      plan.entrance_s = inputs[i].first_onset_s;
    any = true;
  }

  for (const PerformerInput& in : inputs) {
    const music::Score& score = *in.score;
    const VariationParams& v = in.params;
    PerformerMotionPlan p;
    p.params = v;
    p.tempo = score.tempo_map;
    p.sway_amplitude_rad = static_cast<float>((0.5 + 3.5 * v.sway_amount) * kDeg);
    p.sway_period_beats = 2.0 + 6.0 * v.sway_period;
    p.head_amplitude_rad = static_cast<float>((1.0 + 3.0 * v.head_motion) * kDeg);
    p.active_start_s = in.first_onset_s;
    p.active_end_s = in.last_offset_s;
    p.expressions = clean_expressions(in.expressions);

    for (const BreathInput& e : in.breaths) {
      BreathMotion b;
      b.rise_start_s = std::min(e.prepare_start_s, e.start_s);
      b.peak_s = e.end_s;
      b.release_end_s = e.end_s + kBreathRelease_s;
      b.size = static_cast<float>(std::clamp(e.depth, 0.0, 1.0) * (0.4 + 0.6 * v.breath_depth));
      p.breaths.push_back(b);
      p.active_start_s = std::min(p.active_start_s, b.rise_start_s);
    }

    // Weight shifts on every n-th bar line while the player is on stage, and at every phrase
    // boundary (a breath taken in a rest: the player settles onto the other foot while
    // breathing in, over one beat); a bar line's shift gives way to a phrase's near it.
    const int every = 1 + static_cast<int>(std::lround(7.0 * (1.0 - v.weight_shift_rate)));
    const float width = static_cast<float>(0.012 + 0.010 * v.sway_amount);
    p.initial_shift_m = unit_from_seed(in.seed, 20) < 0.5 ? width : -width;
    std::vector<WeightShift> phrases;
    for (const BreathInput& e : in.breaths) {
      if (!e.phrase) continue;
      const double beat_s =
          score.tempo_map.seconds_at_beats(
              score.tempo_map.beats_at_seconds(e.start_s) +
              music::beat_length_at(score, score.tempo_map.beats_at_seconds(e.start_s))) -
          e.start_s;
      WeightShift shift;
      shift.start_s = e.start_s;
      shift.end_s = std::max(e.start_s + 1e-3, std::min(e.end_s, e.start_s + beat_s));
      phrases.push_back(shift);
    }
    std::vector<WeightShift> shifts = phrases;
    const double end_beats = score.tempo_map.beats_at_seconds(p.active_end_s + 2.0);
    const std::vector<double> bars = bar_lines(score, end_beats);
    for (std::size_t b = static_cast<std::size_t>(every); b < bars.size();
         b += static_cast<std::size_t>(every)) {
      const double start_beats = bars[b];
      const double beat = music::beat_length_at(score, start_beats);
      WeightShift shift;
      shift.start_s = score.tempo_map.seconds_at_beats(start_beats);
      shift.end_s = score.tempo_map.seconds_at_beats(start_beats + beat);
      const double margin = 0.5 * (shift.end_s - shift.start_s);
      const bool near_a_phrase =
          std::any_of(phrases.begin(), phrases.end(), [&](const WeightShift& q) {
            return shift.start_s < q.end_s + margin && q.start_s < shift.end_s + margin;
          });
      if (!near_a_phrase) shifts.push_back(shift);
    }
    std::sort(shifts.begin(), shifts.end(),
              [](const WeightShift& a, const WeightShift& b) { return a.start_s < b.start_s; });
    float side = p.initial_shift_m;
    for (WeightShift& shift : shifts) {
      shift.from_m = side;
      shift.to_m = -side;
      side = -side;
      p.weight_shifts.push_back(shift);
    }
    plan.performers.push_back(std::move(p));
  }

  if (plan.lead >= 0) {
    const PerformerInput& lead = inputs[static_cast<std::size_t>(plan.lead)];
    const music::Score& score = *lead.score;
    std::vector<double> entrances;
    if (!options.cues_s) {
      if (any) entrances.push_back(plan.entrance_s);
    } else {
      for (double e : *options.cues_s) {
        if (std::isfinite(e)) {
          entrances.push_back(e);
        } else {
          ++plan.dropped_cues;
        }
      }
      std::sort(entrances.begin(), entrances.end());
    }
    // One beat of the lead's tempo before each E; a cue whose lift would start before the
    // previous cue has settled is dropped (two gestures cannot share the bell). Followers'
    // answers are the same gestures shifted by their delay, so they cannot overlap either.
    std::vector<double> beats;
    double settled_s = -std::numeric_limits<double>::infinity();
    for (double e : entrances) {
      const double e_beats = score.tempo_map.beats_at_seconds(e);
      const double beat_s =
          e - score.tempo_map.seconds_at_beats(e_beats - music::beat_length_at(score, e_beats));
      if (e - beat_s < settled_s) {
        ++plan.dropped_cues;
        continue;
      }
      plan.cue_entrances_s.push_back(e);
      beats.push_back(beat_s);
      settled_s = e + 0.5 * beat_s;
    }
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      const VariationParams& v = inputs[i].params;
      const bool is_lead = static_cast<int>(i) == plan.lead;
      const double delay = is_lead ? 0.0 : 0.06 + 0.08 * v.reaction;
      for (std::size_t c = 0; c < plan.cue_entrances_s.size(); ++c) {
        const double e = plan.cue_entrances_s[c];
        const double beat_s = beats[c];
        CueMotion cue;
        cue.start_s = e - beat_s + delay;
        cue.lift_s = e - 0.5 * beat_s + delay;
        cue.dip_s = e + delay;
        cue.end_s = e + 0.5 * beat_s + delay;
        cue.strength =
            static_cast<float>((0.3 + 0.7 * v.cue_strength) * (is_lead ? 1.0 : 1.0 / 3.0));
        plan.performers[i].cues.push_back(cue);
      }
    }
  }
  return plan;
}

}  // namespace tutti::ensemble_variation
