// SPDX-License-Identifier: MIT
#include <tutti/brass_motion/plan_brass_motion.hpp>

#include <algorithm>
#include <cmath>

namespace tutti::brass_motion {

// The brass model's names used here (systems/brass_model).
using brass_model::BrassLine;
using brass_model::change_window_start_s;
using brass_model::ChangeWindow;
using brass_model::Fingering;
using brass_model::Instrument;
using brass_model::kMaxValves;
using brass_model::LineNote;
using brass_model::Mechanism;

namespace {

struct PlayedFingering {
  const LineNote* note;
  const Fingering* fingering;
};

std::vector<PlayedFingering> played_notes(const BrassLine& line) {
  std::vector<PlayedFingering> out;
  out.reserve(line.notes.size());
  for (const LineNote& n : line.notes) {
    if (!n.playable || n.fingering < 0) continue;
    const auto index = static_cast<std::size_t>(n.fingering);
    if (index >= line.instrument->chart.size()) continue;
    out.push_back({&n, &line.instrument->chart[index]});
  }
  return out;
}

void plan_valves(const std::vector<PlayedFingering>& played, const BrassMotionParams& p,
                 const ChangeWindow& window, BrassMotionPlan& plan) {
  for (int v = 0; v < plan.valve_count; ++v) {
    const auto bit = static_cast<std::uint8_t>(1u << v);
    auto& strokes = plan.valves[static_cast<std::size_t>(v)];
    double free_from = -1e300;  // the valve is up (again) from here
    for (std::size_t k = 0; k < played.size();) {
      if ((played[k].fingering->valves & bit) == 0) {
        ++k;
        continue;
      }
      // A run of notes needing the valve, bridging short rests.
      std::size_t last = k;
      while (last + 1 < played.size() && (played[last + 1].fingering->valves & bit) != 0 &&
             played[last + 1].note->onset_s - played[last].note->offset_s < p.valve_hold_rest_s) {
        ++last;
      }
      const LineNote& first_note = *played[k].note;
      const LineNote& last_note = *played[last].note;
      ValveStroke s;
      s.down_s = first_note.onset_s;
      double lead = p.valve_lead_s;
      if (k > 0) lead = std::min(lead, 0.5 * (first_note.onset_s - played[k - 1].note->onset_s));
      s.press_s = std::max(s.down_s - lead, free_from);
      s.press_s = std::min(s.press_s, s.down_s);
      const bool followed = last + 1 < played.size();
      const LineNote* next = followed ? played[last + 1].note : nullptr;
      if (next != nullptr && next->onset_s - last_note.offset_s < p.valve_hold_rest_s) {
        // Rises while changing to the next note, up by its onset.
        s.up_s = next->onset_s;
        s.release_s =
            std::max(change_window_start_s(last_note, *next, window), s.up_s - p.valve_release_s);
      } else {
        s.release_s = last_note.offset_s;
        s.up_s = last_note.offset_s + p.valve_release_s;
        if (next != nullptr) s.up_s = std::min(s.up_s, next->onset_s);
      }
      s.release_s = std::max(s.release_s, s.down_s);
      s.up_s = std::max(s.up_s, s.release_s);
      strokes.push_back(s);
      free_from = s.up_s;
      k = last + 1;
    }
  }
}

void plan_slide(const std::vector<PlayedFingering>& played, const Instrument& instrument,
                const BrassMotionParams& p, const ChangeWindow& window, BrassMotionPlan& plan) {
  plan.has_slide = instrument.mechanism == Mechanism::slide;
  if (!plan.has_slide || played.empty()) return;
  plan.slide_start_mm = played.front().fingering->slide_mm;
  plan.slide_start_position = played.front().fingering->position;
  double free_from = -1e300;  // previous move's end
  for (std::size_t k = 1; k < played.size(); ++k) {
    const Fingering& from = *played[k - 1].fingering;
    const Fingering& to = *played[k].fingering;
    const double distance = std::abs(double(to.slide_mm) - double(from.slide_mm));
    if (distance <= 0.0) continue;
    const LineNote& before = *played[k - 1].note;
    const LineNote& note = *played[k].note;
    const double needed =
        std::max(p.slide_min_move_s, 1.875 * distance / instrument.max_slide_speed_mm_per_s);
    const double earliest = std::max(change_window_start_s(before, note, window), free_from);
    const double available = note.onset_s - earliest;
    const double duration = std::max(needed, std::min(p.slide_comfortable_s, available));
    SlideMove m;
    m.start_s = std::max(earliest, note.onset_s - duration);
    m.end_s = m.start_s + duration;
    if (m.end_s > note.onset_s + 1e-9) ++plan.late_slide_moves;
    m.from_mm = from.slide_mm;
    m.to_mm = to.slide_mm;
    m.from_position = from.position;
    m.to_position = to.position;
    plan.slide.push_back(m);
    free_from = m.end_s;
  }
}

// The slide's extension as the body sets itself for it (plateau_envelope.hpp): at least as far as
// the slide is out at every moment (each hold from the move that brings it there to the move that
// leaves, each move at its farther end), eased in before and out after over slide_reach_ramp_s.
// The trombonist turns the chest and dips the slide for the far positions by this, not by the
// slide's own extension, so a quick move between far positions does not swing the body with it.
void plan_slide_reach(const std::vector<PlayedFingering>& played, const BrassMotionParams& p,
                      BrassMotionPlan& plan) {
  if (!plan.has_slide || played.empty()) return;
  // Before the first move and after the last, the slide stays out while the phrase's notes last
  // and the instrument comes down (raised over about 2.6 s before, lowered over 1.6 s after).
  constexpr double kBeforeFirstS = 3.0, kAfterLastS = 2.0;
  std::vector<tutti::spline_motion::EnvelopeNeed> needs;
  needs.reserve(2 * plan.slide.size() + 1);
  double held_from = played.front().note->onset_s - kBeforeFirstS;
  double held_mm = plan.slide_start_mm;
  for (const SlideMove& m : plan.slide) {
    needs.push_back({held_from, m.start_s, held_mm});
    needs.push_back({m.start_s, m.end_s, std::max<double>(m.from_mm, m.to_mm)});
    held_from = m.end_s;
    held_mm = m.to_mm;
  }
  double last_offset = held_from;
  for (const PlayedFingering& n : played) last_offset = std::max(last_offset, n.note->offset_s);
  needs.push_back({held_from, last_offset + kAfterLastS, held_mm});
  plan.slide_reach = tutti::spline_motion::plan_plateau_envelope(std::move(needs), p.slide_reach_ramp_s,
                                                          p.slide_reach_bridge_s);
}

void plan_mouth(const std::vector<PlayedFingering>& played, const Instrument& instrument,
                const BrassMotionParams& p, BrassMotionPlan& plan) {
  plan.rest_tension = static_cast<float>(p.mouth_rest_tension);
  plan.corner_pull_from = static_cast<float>(p.corner_pull_from);
  float current = plan.rest_tension;
  double free_from = -1e300;
  for (std::size_t k = 0; k < played.size(); ++k) {
    const LineNote& note = *played[k].note;
    const auto target = static_cast<float>(embouchure_tension(instrument, note.written, p));
    double ramp = p.mouth_ramp_s;
    if (k > 0) ramp = std::min(ramp, 0.5 * (note.onset_s - played[k - 1].note->onset_s));
    const double start = std::max(note.onset_s - ramp, free_from);
    if (target != current) {
      plan.tension.push_back({start, std::max(start, note.onset_s), current, target});
      current = target;
    }
    free_from = note.onset_s;
    const bool rest_follows = k + 1 == played.size() ||
                              played[k + 1].note->onset_s - note.offset_s > p.mouth_relax_after_s;
    if (rest_follows && current != plan.rest_tension) {
      const double relax_end = note.offset_s + p.mouth_ramp_s * 3.0;
      plan.tension.push_back({note.offset_s, relax_end, current, plan.rest_tension});
      current = plan.rest_tension;
      free_from = relax_end;
    }
    plan.sounding.push_back({note.onset_s, note.offset_s});
  }
}

}  // namespace

double embouchure_tension(const Instrument& instrument, int written,
                          const BrassMotionParams& params) {
  const int span = std::max(1, instrument.highest_written - instrument.lowest_written);
  const double place =
      std::clamp(double(written - instrument.lowest_written) / double(span), 0.0, 1.0);
  return params.mouth_low_tension +
         (1.0 - params.mouth_low_tension) * std::pow(place, params.mouth_tension_exponent);
}

BrassMotionPlan plan_brass_motion(const BrassLine& line, const BrassMotionParams& params,
                                  const ChangeWindow& window) {
  BrassMotionPlan plan;
  if (line.instrument == nullptr) return plan;
  const Instrument& instrument = *line.instrument;
  plan.valve_count = std::min<int>(static_cast<int>(instrument.valves.size()), kMaxValves);
  const std::vector<PlayedFingering> played = played_notes(line);
  plan_valves(played, params, window, plan);
  plan_slide(played, instrument, params, window, plan);
  plan_slide_reach(played, params, plan);
  plan_mouth(played, instrument, params, plan);
  return plan;
}

}  // namespace tutti::brass_motion
