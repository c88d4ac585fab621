// SPDX-License-Identifier: MIT
#include <tutti/fingering_planner/chord_roll.hpp>

#include <algorithm>
#include <cmath>

namespace tutti::fingering_planner {

// The piano model's names this planner uses (systems/piano_model).
using piano_model::FingerRange;

namespace {

constexpr double kSameOnsetS = 1e-4;  // notes struck together
constexpr double kShortestStepS = 0.012;
constexpr double kReleaseBeforeS = 0.01;  // a key let go this long before the next strikes
constexpr double kShortestHoldS = 0.02;

// Where the hand's reference point must be for `finger` on `key` (hand_model.hpp).
struct Span {
  double lo_mm, hi_mm;
};
Span reference_span(const FingeringModel& model, music::Hand side, int key, int finger) {
  const FingerRange& r = model.hand.range(side, finger);
  const double x = model.keyboard.x_mm(std::clamp(key, model.keyboard.lowest_key(),
                                                 model.keyboard.highest_key()));
  return {x - r.hi_mm, x - r.lo_mm};
}

}  // namespace

ChordRolls plan_chord_rolls(const music::Score& score, const ScorePlan& plan,
                            const FingeringModel& model, double step_s) {
  ChordRolls rolls;
  const std::size_t n = score.notes.size();
  if (plan.fingers.size() != n || plan.hands.size() != n || !(step_s > 0.0)) return rolls;
  // Each hand's notes by onset, then by key.
  std::vector<int> order;
  order.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (plan.fingers[i] >= 1 && plan.fingers[i] <= 5) order.push_back(static_cast<int>(i));
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    const auto& na = score.notes[static_cast<std::size_t>(a)];
    const auto& nb = score.notes[static_cast<std::size_t>(b)];
    const int ha = static_cast<int>(plan.hands[static_cast<std::size_t>(a)]);
    const int hb = static_cast<int>(plan.hands[static_cast<std::size_t>(b)]);
    if (ha != hb) return ha < hb;
    if (na.onset_s != nb.onset_s) return na.onset_s < nb.onset_s;
    return na.pitch < nb.pitch;
  });
  for (std::size_t begin = 0; begin < order.size();) {
    const auto& first = score.notes[static_cast<std::size_t>(order[begin])];
    const music::Hand side = plan.hands[static_cast<std::size_t>(order[begin])];
    std::size_t end = begin + 1;
    while (end < order.size() && plan.hands[static_cast<std::size_t>(order[end])] == side &&
           score.notes[static_cast<std::size_t>(order[end])].onset_s - first.onset_s < kSameOnsetS) {
      ++end;
    }
    const std::size_t count = end - begin;
    std::vector<Span> spans;
    spans.reserve(count);
    double lo = -1e300, hi = 1e300, shortest = 1e300;
    for (std::size_t k = begin; k < end; ++k) {
      const auto note = static_cast<std::size_t>(order[k]);
      spans.push_back(reference_span(model, side, score.notes[note].pitch, plan.fingers[note]));
      lo = std::max(lo, spans.back().lo_mm);
      hi = std::min(hi, spans.back().hi_mm);
      shortest = std::min(shortest, score.notes[note].offset_s - score.notes[note].onset_s);
    }
    if (count >= 2 && lo > hi) {
      ++rolls.chords;
      const double step = std::max(
          kShortestStepS, std::min(step_s, 0.5 * shortest / static_cast<double>(count - 1)));
      for (std::size_t k = 0; k < count; ++k) {
        const auto note = static_cast<std::size_t>(order[begin + k]);
        RolledNote rolled;
        rolled.note = order[begin + k];
        rolled.onset_s = score.notes[note].onset_s + step * static_cast<double>(k);
        rolled.release_s = score.notes[note].offset_s;
        // Let go before the first later note that no hand position reaches together with it.
        for (std::size_t j = k + 1; j < count; ++j) {
          if (std::max(spans[k].lo_mm, spans[j].lo_mm) > std::min(spans[k].hi_mm, spans[j].hi_mm)) {
            const double strike = score.notes[note].onset_s + step * static_cast<double>(j);
            rolled.release_s = std::min(rolled.release_s, strike - kReleaseBeforeS);
            break;
          }
        }
        rolled.release_s = std::max(rolled.release_s, rolled.onset_s + kShortestHoldS);
        if (rolled.onset_s != score.notes[note].onset_s ||
            rolled.release_s != score.notes[note].offset_s) {
          rolls.notes.push_back(rolled);
        }
      }
    }
    begin = end;
  }
  std::sort(rolls.notes.begin(), rolls.notes.end(),
            [](const RolledNote& a, const RolledNote& b) { return a.note < b.note; });
  return rolls;
}

void apply_chord_rolls(const ChordRolls& rolls, music::Score& score) {
  for (const RolledNote& r : rolls.notes) {
    if (r.note < 0 || static_cast<std::size_t>(r.note) >= score.notes.size()) continue;
    music::Note& note = score.notes[static_cast<std::size_t>(r.note)];
    note.onset_s = r.onset_s;
    note.offset_s = std::max(r.onset_s, r.release_s);
  }
}

}  // namespace tutti::fingering_planner
