#include <tutti/fingering_planner/hand_assignment.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numeric>
#include <string>

namespace tutti::piano {
namespace {

music::Hand hand_from_name(const std::string& name) {
  std::string lower;
  for (char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const bool right = lower.find("right") != std::string::npos ||
                     lower.find("r.h.") != std::string::npos || lower == "rh";
  const bool left = lower.find("left") != std::string::npos ||
                    lower.find("l.h.") != std::string::npos || lower == "lh";
  if (right == left) return music::Hand::unknown;
  return right ? music::Hand::right : music::Hand::left;
}

// Automatic split of the notes `indices` (one part) into hands.
void split_automatically(const music::Score& score, std::vector<int> indices,
                         const FingeringModel& model, HandAssignment& out) {
  const Keyboard& keyboard = model.keyboard;
  const double white = keyboard.white_key_width_mm();
  // Widest reach: thumb's lowest to little finger's highest.
  const double reach_mm =
      model.hand.range(music::Hand::right, 5).hi_mm - model.hand.range(music::Hand::right, 1).lo_mm;
  auto x_of = [&](int key) {
    return keyboard.x_mm(std::clamp(key, keyboard.lowest_key(), keyboard.highest_key()));
  };
  std::stable_sort(indices.begin(), indices.end(), [&](int a, int b) {
    const auto& x = score.notes[static_cast<std::size_t>(a)];
    const auto& y = score.notes[static_cast<std::size_t>(b)];
    return x.onset_ticks != y.onset_ticks ? x.onset_ticks < y.onset_ticks : x.pitch < y.pitch;
  });
  double last_right = 67.0;  // hands start around G4 and C3
  double last_left = 48.0;
  for (std::size_t start = 0; start < indices.size();) {
    std::size_t stop = start;
    const auto onset = score.notes[static_cast<std::size_t>(indices[start])].onset_ticks;
    while (stop < indices.size() &&
           score.notes[static_cast<std::size_t>(indices[stop])].onset_ticks == onset) {
      ++stop;
    }
    const auto n = static_cast<int>(stop - start);
    auto pitch = [&](int i) {
      return score.notes[static_cast<std::size_t>(indices[start + static_cast<std::size_t>(i)])]
          .pitch;
    };
    auto hand_cost = [&](int lo, int hi, bool right) {  // notes [lo, hi)
      if (lo >= hi) return 0.0;
      double cost = 0.0;
      const double span = x_of(pitch(hi - 1)) - x_of(pitch(lo));
      if (span > reach_mm) cost += 100.0 * (span - reach_mm) / white;
      if (hi - lo > 5) cost += 100.0 * (hi - lo - 5);
      double centre = 0.5 * (pitch(lo) + pitch(hi - 1));
      // Stay near where the hand was (a far jump counts as an octave), right hand above middle
      // C, left hand below it.
      cost += 0.05 * std::min(12.0, std::abs(centre - (right ? last_right : last_left)));
      if (right) cost += 0.2 * std::max(0, 60 - pitch(lo));
      if (!right) cost += 0.2 * std::max(0, pitch(hi - 1) - 59);
      return cost;
    };
    int best_split = 0;
    double best_cost = 1e300;
    for (int split = 0; split <= n; ++split) {  // [0, split) left, [split, n) right
      const double cost = hand_cost(0, split, false) + hand_cost(split, n, true);
      if (cost < best_cost) best_cost = cost, best_split = split;
    }
    for (int i = 0; i < n; ++i) {
      const auto note = static_cast<std::size_t>(indices[start + static_cast<std::size_t>(i)]);
      out.hand[note] = i < best_split ? music::Hand::left : music::Hand::right;
      out.source[note] = HandSource::automatic;
    }
    if (best_split > 0) last_left = 0.5 * (pitch(0) + pitch(best_split - 1));
    if (best_split < n) last_right = 0.5 * (pitch(best_split) + pitch(n - 1));
    start = stop;
  }
}

}  // namespace

HandAssignment assign_hands(const music::Score& score, const FingeringModel& model) {
  HandAssignment out;
  out.hand.assign(score.notes.size(), music::Hand::unknown);
  out.source.assign(score.notes.size(), HandSource::none);
  // Parts without hands of their own (voices of a fugue on separate tracks, a one-staff piano
  // part) are split together: one pianist plays them all, so each hand's span must hold across
  // parts.
  std::vector<int> automatic;
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    const music::Note& note = score.notes[i];
    if (note.part < 0 || static_cast<std::size_t>(note.part) >= score.parts.size()) continue;
    const music::Part& part = score.parts[static_cast<std::size_t>(note.part)];
    if (part.percussion) continue;
    if (note.hand != music::Hand::unknown) {
      out.hand[i] = note.hand;
      out.source[i] = HandSource::file;
    } else if (const music::Hand named = hand_from_name(part.name); named != music::Hand::unknown) {
      out.hand[i] = named;
      out.source[i] = HandSource::part_name;
    } else if (part.staves >= 2 && note.staff >= 1) {
      out.hand[i] = note.staff == 1 ? music::Hand::right : music::Hand::left;
      out.source[i] = HandSource::staff;
    } else {
      automatic.push_back(static_cast<int>(i));
    }
  }
  if (!automatic.empty()) split_automatically(score, std::move(automatic), model, out);
  return out;
}

}  // namespace tutti::piano
