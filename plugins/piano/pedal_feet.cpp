// SPDX-License-Identifier: MIT
#include <tutti/piano/pedal_feet.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <tutti/music/part_names.hpp>
#include <tutti/piano_model/keyboard_instruments.hpp>
#include <tutti/piano_model/pedal_geometry.hpp>

namespace tutti::piano {
namespace {

constexpr double kSameOnset_s = 1e-3;
// A foot may cut the note it holds short by up to this share of it to play the next one, at a
// cost (metres of travel per second cut) that makes a nearby free foot the better choice.
constexpr double kMostCut = 0.4;
constexpr double kCutCost_per_s = 2.0;
constexpr double kPi = 3.14159265358979323846;

bool names_the_pedals(const music::Part& part, const piano_model::Pedalboard& board) {
  return music::longest_phrase(music::part_name_words(part.name), board.names) > 0;
}

int fold_onto_board(int key, const piano_model::Pedalboard& board) {
  while (key < board.lowest_key) key += 12;
  while (key > board.highest_key) key -= 12;
  return key;
}

double smoothstep(double u) {
  u = std::clamp(u, 0.0, 1.0);
  return u * u * (3.0 - 2.0 * u);
}

double move_s(double distance_m) {
  return std::clamp(distance_m / FootTiming::move_speed_m_s, FootTiming::min_move_s,
                    FootTiming::max_move_s);
}

// A foot's resting key when it plays nothing: a natural a quarter of the board in from its end.
int resting_key(const piano_model::Pedalboard& board, int foot) {
  const int span = board.highest_key - board.lowest_key;
  int key = foot == kLeftFoot ? board.lowest_key + span / 4 : board.lowest_key + (3 * span) / 4;
  if (piano_model::pedal_is_sharp(key)) --key;
  return key;
}

// The part of lowest median pitch among two or more, if it is a line (at most 5 % of its notes
// share an onset) whose median lies below a fifth over the split; else -1.
int lowest_single_line_part(const music::Score& score, const piano_model::Pedalboard& board) {
  std::vector<std::vector<const music::Note*>> parts;
  for (const music::Note& n : score.notes) {
    if (n.part < 0) continue;
    if (static_cast<std::size_t>(n.part) >= parts.size()) parts.resize(static_cast<std::size_t>(n.part) + 1);
    parts[static_cast<std::size_t>(n.part)].push_back(&n);
  }
  int lowest = -1;
  int lowest_median = 128;
  int played = 0;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    if (parts[p].empty()) continue;
    ++played;
    std::vector<int> pitches;
    for (const music::Note* n : parts[p]) pitches.push_back(n->pitch);
    std::nth_element(pitches.begin(), pitches.begin() + static_cast<std::ptrdiff_t>(pitches.size() / 2),
                     pitches.end());
    const int median = pitches[pitches.size() / 2];
    if (median < lowest_median) {
      lowest_median = median;
      lowest = static_cast<int>(p);
    }
  }
  if (played < 2 || lowest_median >= board.split_below + 7) return -1;
  std::vector<double> onsets;
  for (const music::Note* n : parts[static_cast<std::size_t>(lowest)]) onsets.push_back(n->onset_s);
  std::sort(onsets.begin(), onsets.end());
  std::size_t shared = 0;
  for (std::size_t i = 1; i < onsets.size(); ++i) {
    shared += onsets[i] - onsets[i - 1] < kSameOnset_s ? 1 : 0;
  }
  return 20 * shared <= onsets.size() ? lowest : -1;
}

}  // namespace

std::vector<bool> choose_pedal_notes(const music::Score& score,
                                     const piano_model::Pedalboard& board) {
  std::vector<bool> pedal(score.notes.size(), false);
  // A part named as the pedals'.
  bool named = false;
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    const auto part = static_cast<std::size_t>(score.notes[i].part);
    if (part < score.parts.size() && names_the_pedals(score.parts[part], board)) {
      pedal[i] = true;
      named = true;
    }
  }
  if (named) return pedal;
  // The third staff of a part written on three.
  bool third_staff = false;
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    if (score.notes[i].staff == 3) {
      pedal[i] = true;
      third_staff = true;
    }
  }
  if (third_staff) return pedal;
  // Of several parts, the lowest, when it is a single line in the pedals' register (a chorale's
  // bass, a continuo).
  if (const int part = lowest_single_line_part(score, board); part >= 0) {
    for (std::size_t i = 0; i < score.notes.size(); ++i) pedal[i] = score.notes[i].part == part;
    return pedal;
  }
  // Else the lowest note of each onset, when below the split.
  std::vector<std::size_t> order(score.notes.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return score.notes[a].onset_s < score.notes[b].onset_s;
  });
  for (std::size_t begin = 0; begin < order.size();) {
    std::size_t end = begin + 1;
    while (end < order.size() &&
           score.notes[order[end]].onset_s - score.notes[order[begin]].onset_s < kSameOnset_s) {
      ++end;
    }
    std::size_t lowest = order[begin];
    for (std::size_t j = begin + 1; j < end; ++j) {
      if (score.notes[order[j]].pitch < score.notes[lowest].pitch) lowest = order[j];
    }
    if (score.notes[lowest].pitch < board.split_below) pedal[lowest] = true;
    begin = end;
  }
  return pedal;
}

FeetPlan plan_feet(const music::Score& score, const std::vector<bool>& pedal_notes,
                   const piano_model::Pedalboard& board) {
  FeetPlan plan;
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < score.notes.size() && i < pedal_notes.size(); ++i) {
    if (pedal_notes[i]) order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const music::Note& x = score.notes[a];
    const music::Note& y = score.notes[b];
    return x.onset_s != y.onset_s ? x.onset_s < y.onset_s : x.pitch < y.pitch;
  });
  for (int foot : {kRightFoot, kLeftFoot}) {
    plan.rest_key[static_cast<std::size_t>(foot)] = resting_key(board, foot);
    plan.rest_x_m[static_cast<std::size_t>(foot)] =
        piano_model::pedal_x_m(board, plan.rest_key[static_cast<std::size_t>(foot)]);
  }
  std::array<int, 2> last{-1, -1};  // each foot's latest press
  for (std::size_t index : order) {
    const music::Note& note = score.notes[index];
    PedalPress press;
    press.key = fold_onto_board(note.pitch, board);
    plan.folded += press.key != note.pitch ? 1 : 0;
    press.down_s = note.onset_s;
    press.up_s = std::max(note.offset_s, note.onset_s);
    press.note = index;
    press.x_m = piano_model::pedal_x_m(board, press.key);
    // Each foot's cost: how far it goes, playing on the other's side, crossing the other foot,
    // and how much of the note it holds it must cut short to get there in time (up to
    // kMostCut of it; a foot that would cut more is taken only when both would).
    std::array<double, 2> cost{};
    std::array<double, 2> latest_up{};
    std::array<bool, 2> can{};
    std::array<bool, 2> reaches{};
    for (int foot : {kRightFoot, kLeftFoot}) {
      const auto f = static_cast<std::size_t>(foot);
      const auto other = static_cast<std::size_t>(1 - foot);
      const PedalPress* held = last[f] < 0 ? nullptr : &plan.presses[static_cast<std::size_t>(last[f])];
      const double from_x = held == nullptr ? plan.rest_x_m[f] : held->x_m;
      const double distance = std::abs(press.x_m - from_x);
      latest_up[f] = press.down_s - FootTiming::press_s - FootTiming::release_s -
                     (distance > 1e-6 ? move_s(distance) : 0.0);
      double cut_s = 0.0;
      reaches[f] = piano_model::foot_reaches(board, foot == kRightFoot, press.key);
      can[f] = reaches[f];
      if (held != nullptr && held->up_s > latest_up[f]) {
        cut_s = held->up_s - latest_up[f];
        can[f] = can[f] && latest_up[f] >= held->down_s &&
                 cut_s <= kMostCut * (held->up_s - held->down_s) + 1e-9;
      }
      const double other_x = last[other] < 0
                                 ? plan.rest_x_m[other]
                                 : plan.presses[static_cast<std::size_t>(last[other])].x_m;
      const double wrong_side = foot == kRightFoot ? std::max(0.0, -press.x_m)
                                                   : std::max(0.0, press.x_m);
      const double crossing = foot == kRightFoot ? std::max(0.0, other_x - press.x_m)
                                                 : std::max(0.0, press.x_m - other_x);
      cost[f] = distance + 1.5 * wrong_side + 2.0 * crossing + kCutCost_per_s * cut_s;
    }
    int foot = kRightFoot;
    if (can[0] != can[1]) {
      foot = can[0] ? kRightFoot : kLeftFoot;
    } else if (can[0]) {
      foot = cost[0] <= cost[1] ? kRightFoot : kLeftFoot;
    } else {
      // Neither can: of the feet that reach, the one whose note ends first lets it go as early as
      // it must (a foot that has played nothing yet is free).
      const auto ends = [&](int f) {
        const int held = last[static_cast<std::size_t>(f)];
        return held < 0 ? -std::numeric_limits<double>::infinity()
                        : plan.presses[static_cast<std::size_t>(held)].up_s;
      };
      if (reaches[0] != reaches[1]) {
        foot = reaches[0] ? kRightFoot : kLeftFoot;
      } else {
        foot = ends(kRightFoot) <= ends(kLeftFoot) ? kRightFoot : kLeftFoot;
      }
    }
    if (last[static_cast<std::size_t>(foot)] >= 0) {
      PedalPress& held = plan.presses[static_cast<std::size_t>(last[static_cast<std::size_t>(foot)])];
      held.up_s = std::max(held.down_s, std::min(held.up_s, latest_up[static_cast<std::size_t>(foot)]));
    }
    press.foot = foot;
    last[static_cast<std::size_t>(foot)] = static_cast<int>(plan.presses.size());
    plan.by_foot[static_cast<std::size_t>(foot)].push_back(
        static_cast<std::uint32_t>(plan.presses.size()));
    plan.presses.push_back(press);
  }
  // A foot waits over the first pedal it plays.
  for (std::size_t f = 0; f < 2; ++f) {
    if (plan.by_foot[f].empty()) continue;
    const PedalPress& first = plan.presses[plan.by_foot[f].front()];
    plan.rest_key[f] = first.key;
    plan.rest_x_m[f] = first.x_m;
  }
  return plan;
}

FootState evaluate_foot(const FeetPlan& plan, int foot, double t) {
  FootState state;
  if (plan.empty() || (foot != kRightFoot && foot != kLeftFoot)) return state;
  const auto f = static_cast<std::size_t>(foot);
  const std::vector<std::uint32_t>& mine = plan.by_foot[f];
  state.from_key = state.to_key = plan.rest_key[f];
  state.lift_m = FootTiming::hover_m;
  // The first press that has not begun to go down.
  const auto next = std::partition_point(mine.begin(), mine.end(), [&](std::uint32_t i) {
    return plan.presses[i].down_s - FootTiming::press_s <= t;
  });
  const PedalPress* previous = next == mine.begin() ? nullptr : &plan.presses[*(next - 1)];
  const PedalPress* coming = next == mine.end() ? nullptr : &plan.presses[*next];
  if (previous != nullptr) {
    state.from_key = state.to_key = previous->key;
    const double released = previous->up_s + FootTiming::release_s;
    if (t < released) {
      double depth = 1.0;
      if (t < previous->down_s) {
        depth = smoothstep((t - (previous->down_s - FootTiming::press_s)) / FootTiming::press_s);
      } else if (t > previous->up_s) {
        depth = 1.0 - smoothstep((t - previous->up_s) / FootTiming::release_s);
      }
      state.depth = depth;
      state.lift_m = FootTiming::hover_m * (1.0 - depth);
      return state;
    }
  }
  if (coming == nullptr || coming->key == state.from_key) return state;
  // On the way to the coming pedal: leaving as late as its distance allows.
  const double from_x = previous != nullptr ? previous->x_m : plan.rest_x_m[f];
  const double arrive = coming->down_s - FootTiming::press_s;
  double start = arrive - move_s(std::abs(coming->x_m - from_x));
  if (previous != nullptr) start = std::max(start, previous->up_s + FootTiming::release_s);
  if (t < start || arrive <= start) {
    if (arrive <= start && t >= start) {
      state.from_key = state.to_key = coming->key;
    }
    return state;
  }
  const double u = (t - start) / (arrive - start);
  state.to_key = coming->key;
  state.travel = smoothstep(u);
  state.lift_m = FootTiming::hover_m + FootTiming::step_lift_m * std::sin(kPi * std::clamp(u, 0.0, 1.0));
  return state;
}

}  // namespace tutti::piano
