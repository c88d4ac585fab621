// SPDX-License-Identifier: MIT
#include <tutti/brass_motion/breath_plan.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include <tutti/music/meter.hpp>

namespace tutti::brass_motion {

// The brass model's names used here (systems/brass_model).
using brass_model::BrassLine;
using brass_model::LineNote;

namespace {

constexpr double kBeatTolerance = 1e-6;  // quarter notes: rests of exactly 0.5, 1, 2 beats
constexpr double kTimeTolerance = 1e-9;  // seconds
constexpr double kPi = 3.14159265358979323846;

// The score's meter as spans of one time signature each. As in music/meter.hpp a change starts
// a new bar, so every span starts on a downbeat; before the first signature: 4/4.
class Meter {
 public:
  explicit Meter(const music::Score& score) {
    spans_.push_back({0.0, 4.0, 1.0});
    for (const music::TimeSignature& ts : score.time_signatures) {
      const double at = std::max(0.0, score.tempo_map.beats_at(static_cast<double>(ts.tick)));
      const double bar =
          ts.numerator > 0 && ts.denominator > 0 ? 4.0 * ts.numerator / ts.denominator : 4.0;
      const Span span{at, bar, music::beat_length_at(score, at)};
      if (at <= spans_.back().start_q + kBeatTolerance) {
        spans_.back() = {spans_.back().start_q, span.bar_q, span.beat_q};
      } else {
        spans_.push_back(span);
      }
    }
  }

  // Beats of the meter in [q0, q1] (quarter notes, q0 <= q1).
  double beats_between(double q0, double q1) const {
    double beats = 0.0;
    for (std::size_t i = span_at(q0); i < spans_.size(); ++i) {
      const double from = std::max(q0, i == 0 ? q0 : spans_[i].start_q);
      const double to = i + 1 < spans_.size() ? std::min(q1, spans_[i + 1].start_q) : q1;
      if (to > from) beats += (to - from) / spans_[i].beat_q;
      if (i + 1 < spans_.size() && spans_[i + 1].start_q >= q1) break;
    }
    return beats;
  }

  // The point `beats` beats of the meter before q_end; before 0 the first meter goes on.
  double back(double q_end, double beats) const {
    std::size_t i = span_at(q_end - kBeatTolerance);
    double q = q_end;
    double remaining = beats;
    for (;;) {
      const Span& s = spans_[i];
      const double available =
          i == 0 ? std::numeric_limits<double>::infinity() : (q - s.start_q) / s.beat_q;
      if (available >= remaining) return q - remaining * s.beat_q;
      remaining -= available;
      q = s.start_q;
      --i;
    }
  }

  double beat_at(double q) const { return spans_[span_at(q)].beat_q; }

  // 2 = a downbeat, 1 = another beat of the meter, 0 = between beats.
  int strength(double q) const {
    const Span& s = spans_[span_at(q + kBeatTolerance)];
    const auto on_grid = [](double offset, double step) {
      const double r = std::fmod(offset, step);
      return std::abs(r) < kBeatTolerance || std::abs(r - step) < kBeatTolerance ||
             std::abs(r + step) < kBeatTolerance;
    };
    const double offset = q - s.start_q;
    if (on_grid(offset, s.bar_q)) return 2;
    return on_grid(offset, s.beat_q) ? 1 : 0;
  }

 private:
  struct Span {
    double start_q = 0.0;
    double bar_q = 4.0;
    double beat_q = 1.0;
  };

  // The last span starting at or before q (the first for q before everything).
  std::size_t span_at(double q) const {
    const auto it = std::upper_bound(spans_.begin(), spans_.end(), q,
                                     [](double value, const Span& s) { return value < s.start_q; });
    return it == spans_.begin() ? 0 : static_cast<std::size_t>(it - spans_.begin()) - 1;
  }

  std::vector<Span> spans_;
};

// Seconds at a point in quarter notes; before 0 at the opening tempo.
double seconds_at_q(const music::TempoMap& map, double q) {
  if (q >= 0.0) return map.seconds_at_beats(q);
  return map.seconds_at_beats(0.0) + q * 60.0 / map.bpm_at(0.0);
}

// A played note, its end cut at the next played onset.
struct Played {
  int note = -1;
  double on_s = 0.0;
  double off_s = 0.0;
  double on_q = 0.0;
  double off_q = 0.0;
  double drain_per_s = 0.0;  // air per second while it sounds
};

double piecewise(double x, double x_mid, double at_lo, double at_hi, double x_lo, double x_hi) {
  if (x <= x_mid) return at_lo + (1.0 - at_lo) * (x - x_lo) / (x_mid - x_lo);
  return 1.0 + (at_hi - 1.0) * (x - x_mid) / (x_hi - x_mid);
}

double drain_per_s(const LineNote& n, int lowest, int highest, const BreathParams& p) {
  const double velocity = std::clamp(static_cast<double>(n.velocity), 1.0, 127.0);
  const double loudness =
      piecewise(velocity, p.mf_velocity, p.drain_soft, p.drain_loud, 1.0, 127.0);
  const double place =
      highest > lowest
          ? std::clamp(static_cast<double>(n.written - lowest) / (highest - lowest), 0.0, 1.0)
          : 0.5;
  const double reg = piecewise(place, 0.5, p.drain_low, p.drain_high, 0.0, 1.0);
  return loudness * reg / p.capacity_s;
}

std::vector<Played> played_notes(const BrassLine& line, const BreathParams& p) {
  int lowest = 0;
  int highest = 0;
  if (line.instrument != nullptr &&
      line.instrument->highest_written > line.instrument->lowest_written) {
    lowest = line.instrument->lowest_written;
    highest = line.instrument->highest_written;
  } else {
    bool any = false;
    for (const LineNote& n : line.notes) {
      if (!n.playable) continue;
      lowest = any ? std::min(lowest, n.written) : n.written;
      highest = any ? std::max(highest, n.written) : n.written;
      any = true;
    }
  }
  std::vector<Played> played;
  for (std::size_t i = 0; i < line.notes.size(); ++i) {
    const LineNote& n = line.notes[i];
    if (!n.playable) continue;
    played.push_back({static_cast<int>(i), n.onset_s, std::max(n.onset_s, n.offset_s),
                      n.onset_beats, std::max(n.onset_beats, n.offset_beats),
                      drain_per_s(n, lowest, highest, p)});
  }
  std::sort(played.begin(), played.end(), [](const Played& a, const Played& b) {
    return a.on_s < b.on_s || (a.on_s == b.on_s && a.note < b.note);
  });
  for (std::size_t k = 0; k + 1 < played.size(); ++k) {
    if (played[k].off_s > played[k + 1].on_s) {
      played[k].off_s = played[k + 1].on_s;
      played[k].off_q = std::max(played[k].on_q, played[k + 1].on_q);
    }
  }
  return played;
}

// The breath the rules give before played note k (k = 0: before the first entrance).
struct RuleBreath {
  bool breathe = false;
  bool skipped = false;  // long enough in beats, too short in seconds
  BreathEvent event;
};

RuleBreath rule_breath(const std::vector<Played>& played, std::size_t k, const Meter& meter,
                       const music::TempoMap& map, const BreathParams& p) {
  RuleBreath r;
  const Played& next = played[k];
  const bool first = k == 0;
  const double rest_q = first ? std::min(0.0, next.on_q) : played[k - 1].off_q;
  const double rest_s = first ? std::min(seconds_at_q(map, 0.0), next.on_s) : played[k - 1].off_s;
  const double beats = meter.beats_between(rest_q, next.on_q);
  BreathEvent& e = r.event;
  e.before_note = next.note;
  e.rest_beats = beats;
  e.end_s = next.on_s;
  if (first) {
    e.kind = BreathKind::before_entrance;
    e.window_start_s = std::min(seconds_at_q(map, meter.back(next.on_q, 2.0)), next.on_s);
  } else if (beats < 0.5 - kBeatTolerance) {
    return r;
  } else if (beats < 1.0 - kBeatTolerance) {
    e.kind = BreathKind::in_rest;
    e.window_start_s = rest_s;
  } else if (beats < 2.0 - kBeatTolerance) {
    e.kind = BreathKind::last_beat;
    e.window_start_s = seconds_at_q(map, meter.back(next.on_q, 1.0));
  } else {
    e.kind = BreathKind::prepared;
    e.window_start_s = seconds_at_q(map, meter.back(next.on_q, 2.0));
  }
  if (!first) e.window_start_s = std::clamp(e.window_start_s, rest_s, e.end_s);
  const double window = e.end_s - e.window_start_s;
  if (!first && window < p.inhale_min_s - kTimeTolerance) {
    r.skipped = true;
    return r;
  }
  // Before the first entrance there is always room: the player breathes before the music.
  e.start_s = e.end_s - std::clamp(window, p.inhale_min_s, p.inhale_max_s);
  e.prepare_start_s = e.start_s;
  if (e.kind == BreathKind::prepared) {
    e.prepare_start_s = std::max(rest_s, e.start_s - p.prepare_s);
  } else if (first) {
    e.prepare_start_s = e.start_s - p.prepare_s;
  }
  r.breathe = true;
  return r;
}

// A catch-breath after played note k: the note loses cut_s, the inhale runs to the next onset.
struct Catch {
  bool taken = false;
  double cut_s = 0.0;
  double gap_beats = 0.0;
};

double after_note(double air, const Played& n, double cut_s) {
  const double length = std::max(0.0, n.off_s - cut_s - n.on_s);
  return std::max(0.0, air - n.drain_per_s * length);
}

double refilled(double air, double inhale_s, const BreathParams& p) {
  return std::min(1.0, air + p.refill_per_s * std::max(0.0, inhale_s));
}

// Decides the catch-breaths of phrase [begin, end) (played positions between rule breaths),
// starting with `air`; returns the air at its end. No catch-breath goes before a played note k
// with removed[k] (a remove mark).
double plan_phrase(const std::vector<Played>& played, std::size_t begin, std::size_t end,
                   double air, const Meter& meter, const BreathParams& p,
                   const std::vector<char>& removed, std::vector<Catch>& catches, int& out_of_air) {
  std::size_t cur = begin;
  bool empty = false;  // the air has reached 0 (counted) and no breath since
  std::vector<double> before(end - begin, 0.0);
  while (cur < end) {
    // The first note during which the air would fall below the reserve.
    std::size_t low = end;
    double a = air;
    for (std::size_t k = cur; k < end; ++k) {
      before[k - begin] = a;
      const double length = played[k].off_s - played[k].on_s;
      if (length > 0.0 && played[k].drain_per_s > 0.0 &&
          a - played[k].drain_per_s * length < p.catch_reserve_air) {
        low = k;
        break;
      }
      a = after_note(a, played[k], 0.0);
    }
    if (low == end) return a;

    // The best boundary after a note j, cur <= j <= low, with a next note in the phrase:
    // among those where the air is below catch_below_air (and above 0), the best score; else
    // the latest where air is left; else the latest at all.
    std::size_t best = end;
    double best_score = -1.0;
    std::size_t latest_positive = end;
    std::size_t latest_any = end;
    for (std::size_t j = cur; j <= low && j + 1 < end; ++j) {
      if (removed[j + 1] != 0) continue;
      const Played& n = played[j];
      const double length = n.off_s - n.on_s;
      const double gap_s = played[j + 1].on_s - n.off_s;
      const double cut = std::clamp(p.catch_inhale_s - gap_s, 0.0, p.catch_max_cut * length);
      if (gap_s + cut < p.catch_min_s - kTimeTolerance) continue;
      const double air_at = after_note(before[j - begin], n, cut);
      latest_any = j;
      if (air_at <= 0.0) continue;
      latest_positive = j;
      if (air_at > p.catch_below_air) continue;
      const double beats = (n.off_q - n.on_q) / meter.beat_at(n.on_q);
      const double gap_beats = meter.beats_between(n.off_q, played[j + 1].on_q);
      const int strength = meter.strength(n.on_q);
      const double bonus = p.catch_strong_beat_bonus * (strength == 2 ? 1.0 : strength * 0.5);
      // A player breathes before the strain shows when the music allows it.
      const double score = (beats + 2.0 * gap_beats) * (1.0 + bonus) *
                           (1.0 - strain_at_air(air_at, p.strain_from_air));
      if (score >= best_score) {
        best_score = score;
        best = j;
      }
    }
    const std::size_t j = best != end              ? best
                          : latest_positive != end ? latest_positive
                                                   : latest_any;
    if (j == end) {  // nowhere to breathe up to note `low`: it plays on what is left
      air = after_note(before[low - begin], played[low], 0.0);
      if (air <= 0.0 && !empty) ++out_of_air;
      empty = empty || air <= 0.0;
      cur = low + 1;
      continue;
    }
    const Played& n = played[j];
    const double gap_s = played[j + 1].on_s - n.off_s;
    Catch c;
    c.taken = true;
    c.cut_s = std::clamp(p.catch_inhale_s - gap_s, 0.0, p.catch_max_cut * (n.off_s - n.on_s));
    c.gap_beats = meter.beats_between(n.off_q, played[j + 1].on_q);
    catches[j] = c;
    const double air_at = after_note(before[j - begin], n, c.cut_s);
    if (air_at <= 0.0 && !empty) ++out_of_air;  // ran out before this breath
    air = refilled(air_at, gap_s + c.cut_s, p);
    empty = false;
    cur = j + 1;
  }
  return air;
}

// Minimum jerk 0 -> 1 (zero slope and curvature at both ends).
double ease(double u) {
  u = std::clamp(u, 0.0, 1.0);
  return u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
}

// 0 -> 1 -> 0 with zero slope at both ends.
double bump(double u) {
  u = std::clamp(u, 0.0, 1.0);
  return 0.5 - 0.5 * std::cos(2.0 * kPi * u);
}

void add_segment(BreathPlan& plan, double start_s, double end_s, double from, double to,
                 bool inhale) {
  if (!(end_s > start_s)) return;
  plan.air.push_back({start_s, end_s, from, to, inhale});
}

// The played position a mark at t refers to (the first onset >= t), or played.size() for none.
std::size_t marked_note(const std::vector<Played>& played, double t) {
  if (!std::isfinite(t)) return played.size();
  // Marks are written to the millisecond (the editor rounds them): a note starting up to half a
  // millisecond before the mark's time is the one it names.
  constexpr double kMarkTolerance = 0.0005;
  const auto it = std::lower_bound(played.begin(), played.end(), t - kMarkTolerance,
                                   [](const Played& n, double value) { return n.on_s < value; });
  return static_cast<std::size_t>(it - played.begin());
}

// The breath an add mark forces before played note k > 0 where the rules give none. A rest of
// at least inhale_min_s is breathed in as the rules would for its length (a rest under half a
// beat as in_rest, a window the rules found too short widened to inhale_min_s inside the rest);
// a shorter rest, or none, gives a catch-breath that takes the end of the previous note as
// catch-breaths do (as much as catch_max_cut allows): played[k - 1] is shortened in place, so the
// air model drains only what is played, and cut_previous tells the caller to list it.
BreathEvent forced_breath(std::vector<Played>& played, std::size_t k, const RuleBreath& rule,
                          const Meter& meter, const music::TempoMap& map, const BreathParams& p,
                          bool& cut_previous) {
  Played& previous = played[k - 1];
  const Played& next = played[k];
  const double gap_s = next.on_s - previous.off_s;
  BreathEvent e = rule.event;
  e.marked = true;
  e.before_note = next.note;
  e.end_s = next.on_s;
  if (gap_s >= p.inhale_min_s - kTimeTolerance) {
    if (e.rest_beats < 0.5 - kBeatTolerance) {
      e.kind = BreathKind::in_rest;
      e.window_start_s = previous.off_s;
    }
    e.window_start_s =
        std::clamp(std::min(e.window_start_s, e.end_s - p.inhale_min_s), previous.off_s, e.end_s);
    e.start_s = e.end_s - std::clamp(e.end_s - e.window_start_s, p.inhale_min_s, p.inhale_max_s);
    e.start_s = std::max(e.start_s, previous.off_s);
    e.prepare_start_s = e.start_s;
    if (e.kind == BreathKind::prepared) {
      e.prepare_start_s = std::max(previous.off_s, e.start_s - p.prepare_s);
    }
    return e;
  }
  const double cut =
      std::clamp(p.catch_inhale_s - gap_s, 0.0, p.catch_max_cut * (previous.off_s - previous.on_s));
  if (cut > 0.0) {
    previous.off_s -= cut;
    previous.off_q = std::max(previous.on_q, map.beats_at_seconds(previous.off_s));
    cut_previous = true;
  }
  e.kind = BreathKind::catch_breath;
  e.prepare_start_s = e.start_s = e.window_start_s = previous.off_s;
  e.rest_beats = meter.beats_between(std::min(previous.off_q, next.on_q), next.on_q);
  return e;
}

}  // namespace

double strain_at_air(double air, double strain_from_air) {
  if (!(strain_from_air > 0.0)) return 0.0;
  const double x = std::clamp((strain_from_air - air) / strain_from_air, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

BreathPlan plan_breaths(const BrassLine& line, const music::Score& score,
                        const BreathParams& params) {
  return plan_breaths(line, score, params, BreathMarks{});
}

BreathPlan plan_breaths(const BrassLine& line, const music::Score& score,
                        const BreathParams& params, const BreathMarks& marks) {
  BreathPlan plan;
  plan.initial_air = std::clamp(params.resting_air, 0.0, 1.0);
  plan.strain_from_air = params.strain_from_air;
  plan.min_air = plan.initial_air;
  std::vector<Played> played = played_notes(line, params);
  if (played.empty()) {
    plan.ignored_marks = static_cast<int>(marks.add_s.size() + marks.remove_s.size());
    return plan;
  }
  const Meter meter(score);

  // The marks, as flags per played note (the boundary before it).
  std::vector<char> added(played.size(), 0);
  std::vector<char> removed(played.size(), 0);
  for (double t : marks.remove_s) {
    const std::size_t k = marked_note(played, t);
    if (k < played.size()) {
      removed[k] = 1;
    } else {
      ++plan.ignored_marks;
    }
  }
  for (double t : marks.add_s) {
    const std::size_t k = marked_note(played, t);
    if (k < played.size() && removed[k] == 0) {
      added[k] = 1;
    } else {
      ++plan.ignored_marks;
    }
  }

  std::vector<RuleBreath> rules(played.size());
  for (std::size_t k = 0; k < played.size(); ++k) {
    rules[k] = rule_breath(played, k, meter, score.tempo_map, params);
  }
  // After all rules (they read the unshortened notes): a forced catch-breath shortens note k - 1,
  // which no rule looks at again.
  std::vector<char> cut_by_mark(played.size(), 0);
  for (std::size_t k = 0; k < played.size(); ++k) {
    if (removed[k] != 0) {
      rules[k].breathe = false;
      rules[k].skipped = false;
    } else if (added[k] != 0 && !rules[k].breathe && k > 0) {  // the first always has one
      bool cut = false;
      rules[k].event = forced_breath(played, k, rules[k], meter, score.tempo_map, params, cut);
      rules[k].breathe = true;
      rules[k].skipped = false;
      cut_by_mark[k - 1] = cut ? 1 : 0;
    }
    plan.skipped_rests += rules[k].skipped ? 1 : 0;
  }

  // Decide the catch-breaths phrase by phrase.
  std::vector<Catch> catches(played.size());
  double air = plan.initial_air;
  for (std::size_t begin = 0; begin < played.size();) {
    std::size_t end = begin + 1;
    while (end < played.size() && !rules[end].breathe) ++end;
    const BreathEvent& e = rules[begin].event;
    if (rules[begin].breathe) air = refilled(air, e.end_s - e.start_s, params);  // else removed
    air = plan_phrase(played, begin, end, air, meter, params, removed, catches, plan.out_of_air);
    begin = end;
  }

  // Build events and air segments in time order.
  air = plan.initial_air;
  double min_air = 1.0;
  for (std::size_t k = 0; k < played.size(); ++k) {
    const Played& n = played[k];
    if (rules[k].breathe) {
      BreathEvent e = rules[k].event;
      e.depth = refilled(air, e.end_s - e.start_s, params);
      add_segment(plan, e.start_s, e.end_s, air, e.depth, true);
      air = e.depth;
      plan.events.push_back(e);
    }
    const double end_s = n.off_s - catches[k].cut_s;
    const double length = end_s - n.on_s;
    if (length > 0.0 && n.drain_per_s > 0.0 && air > 0.0) {
      const double left = air - n.drain_per_s * length;
      if (left >= 0.0) {
        add_segment(plan, n.on_s, end_s, air, left, false);
        air = left;
      } else {
        add_segment(plan, n.on_s, n.on_s + air / n.drain_per_s, air, 0.0, false);
        air = 0.0;
      }
    }
    min_air = std::min(min_air, air);
    if (cut_by_mark[k] != 0) {
      plan.shortened.push_back({n.note, n.off_s, score.tempo_map.beats_at_seconds(n.off_s)});
    }
    if (catches[k].taken) {
      const Played& next = played[k + 1];
      BreathEvent e;
      e.kind = BreathKind::catch_breath;
      e.prepare_start_s = e.start_s = e.window_start_s = end_s;
      e.end_s = next.on_s;
      e.depth = refilled(air, e.end_s - e.start_s, params);
      e.before_note = next.note;
      e.rest_beats = catches[k].gap_beats;
      add_segment(plan, e.start_s, e.end_s, air, e.depth, true);
      air = e.depth;
      plan.events.push_back(e);
      ++plan.catch_breaths;
      if (catches[k].cut_s > 0.0) {
        plan.shortened.push_back({n.note, end_s, score.tempo_map.beats_at_seconds(end_s)});
      }
    }
  }
  plan.min_air = min_air;
  plan.max_strain = strain_at_air(min_air, plan.strain_from_air);
  return plan;
}

BreathState evaluate_breath(const BreathPlan& plan, double t) {
  BreathState state;
  if (std::isnan(t)) t = -std::numeric_limits<double>::infinity();

  state.air = plan.initial_air;
  const auto segment =
      std::upper_bound(plan.air.begin(), plan.air.end(), t,
                       [](double value, const AirSegment& s) { return value < s.start_s; });
  if (segment != plan.air.begin()) {
    const AirSegment& s = *(segment - 1);
    if (t >= s.end_s) {
      state.air = s.to;
    } else {
      const double u = (t - s.start_s) / (s.end_s - s.start_s);
      state.air = s.from + (s.to - s.from) * (s.inhale ? ease(u) : u);
    }
  }
  state.air = std::clamp(state.air, 0.0, 1.0);
  state.strain = strain_at_air(state.air, plan.strain_from_air);

  const auto event = std::upper_bound(
      plan.events.begin(), plan.events.end(), t,
      [](double value, const BreathEvent& e) { return value < e.prepare_start_s; });
  if (event != plan.events.begin()) {
    const BreathEvent& e = *(event - 1);
    state.breath_index = static_cast<int>(event - plan.events.begin()) - 1;
    if (t < e.start_s && e.start_s > e.prepare_start_s) {
      state.preparing = bump((t - e.prepare_start_s) / (e.start_s - e.prepare_start_s));
    } else if (t >= e.start_s && t < e.end_s) {
      state.inhale = bump((t - e.start_s) / (e.end_s - e.start_s));
    }
  }
  return state;
}

}  // namespace tutti::brass_motion
