// SPDX-License-Identifier: MIT
#include <tutti/fingering_planner/hand_assignment.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numeric>
#include <string>

namespace tutti::fingering_planner {

// The piano model's names this planner uses (systems/piano_model).
using piano_model::Keyboard;

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
  const double reach_mm = model.hand.reach_mm();
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
  // Notes already given to a hand that still sound: a fugue voice holds a key while the others
  // move, and the hand holding it can neither let the other hand's thumb past it nor stretch
  // beyond its reach from it. A MIDI note overlapping the next by a legato moment is not held.
  constexpr double kLegatoOverlapS = 0.05;
  struct Held {
    double offset_s;
    int pitch;
    bool right;
  };
  std::vector<Held> held;
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
    const double onset_s = score.notes[static_cast<std::size_t>(indices[start])].onset_s;
    std::erase_if(held, [&](const Held& h) { return h.offset_s <= onset_s + kLegatoOverlapS; });
    int held_left_top = -1, held_right_bottom = 128;
    for (const Held& h : held) {
      if (h.right) held_right_bottom = std::min(held_right_bottom, h.pitch);
      else held_left_top = std::max(held_left_top, h.pitch);
    }
    auto hand_cost = [&](int lo, int hi, bool right) {  // notes [lo, hi)
      if (lo >= hi) return 0.0;
      double cost = 0.0;
      int bottom = pitch(lo), top = pitch(hi - 1), keys = hi - lo;
      for (const Held& h : held) {
        if (h.right != right) continue;
        bool struck_again = false;
        for (int i = lo; i < hi; ++i) struck_again = struck_again || pitch(i) == h.pitch;
        if (struck_again) continue;
        bottom = std::min(bottom, h.pitch);
        top = std::max(top, h.pitch);
        ++keys;
      }
      const double span = x_of(top) - x_of(bottom);
      if (span > reach_mm) cost += 100.0 * (span - reach_mm) / white;
      if (keys > 5) cost += 100.0 * (keys - 5);
      // Passing a key the other hand holds puts one thumb through the other: worse than a
      // stretch too wide, which the planner resolves by letting the held key go early.
      for (int i = lo; i < hi; ++i) {
        if (right ? pitch(i) <= held_left_top : pitch(i) >= held_right_bottom) cost += 1000.0;
      }
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
      held.push_back({score.notes[note].offset_s, score.notes[note].pitch, i >= best_split});
    }
    if (best_split > 0) last_left = 0.5 * (pitch(0) + pitch(best_split - 1));
    if (best_split < n) last_right = 0.5 * (pitch(best_split) + pitch(n - 1));
    start = stop;
  }
}

// A note the other hand can take: no crossing (the left hand's notes around it stay below it,
// the right hand's above), and the other hand's keys over the note's whole length, with it, stay
// in one hand's reach and at most five.
bool other_hand_takes(const music::Score& score, const HandAssignment& out, std::size_t note,
                      music::Hand other, double reach_mm, const Keyboard& keyboard) {
  // The other hand needs a moment to arrive: its notes ending just before count too.
  constexpr double kArriveS = 0.08;
  const music::Note& n = score.notes[note];
  auto x_of = [&](int key) {
    return keyboard.x_mm(std::clamp(key, keyboard.lowest_key(), keyboard.highest_key()));
  };
  double lo = x_of(n.pitch), hi = lo;
  int at_onset = 1;
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    const music::Note& o = score.notes[i];
    if (out.hand[i] != other || o.offset_s <= n.onset_s - kArriveS || o.onset_s >= n.offset_s) {
      continue;
    }
    if (o.pitch == n.pitch) return false;
    if (other == music::Hand::left ? o.pitch > n.pitch : o.pitch < n.pitch) return false;
    lo = std::min(lo, x_of(o.pitch));
    hi = std::max(hi, x_of(o.pitch));
    if (o.onset_s <= n.onset_s && o.offset_s > n.onset_s) ++at_onset;
  }
  return hi - lo <= reach_mm && at_onset <= 5;
}

// Notes struck together that one hand cannot span (a score's staff gives a right hand D4 and B5
// at once): the outer notes go to the other hand where it is free to take them, as a pianist
// reads such a chord. What no hand can take is left to the planner (it reports it).
void keep_chords_in_reach(const music::Score& score, const FingeringModel& model,
                          HandAssignment& out) {
  const Keyboard& keyboard = model.keyboard;
  auto x_of = [&](int key) {
    return keyboard.x_mm(std::clamp(key, keyboard.lowest_key(), keyboard.highest_key()));
  };
  // Both hands reach as far (the left hand mirrors the right: its range(5) lies below its
  // range(1), so `range(side, 5).hi - range(side, 1).lo` would be 0 for it).
  const double reach_mm = model.hand.reach_mm();
  for (const music::Hand side : {music::Hand::right, music::Hand::left}) {
    const music::Hand other = side == music::Hand::right ? music::Hand::left : music::Hand::right;
    std::vector<int> notes;
    for (std::size_t i = 0; i < score.notes.size(); ++i) {
      // A hand the file itself states (PIG) is kept.
      if (out.hand[i] == side && out.source[i] != HandSource::file) notes.push_back(static_cast<int>(i));
    }
    std::stable_sort(notes.begin(), notes.end(), [&](int a, int b) {
      const auto& x = score.notes[static_cast<std::size_t>(a)];
      const auto& y = score.notes[static_cast<std::size_t>(b)];
      return x.onset_ticks != y.onset_ticks ? x.onset_ticks < y.onset_ticks : x.pitch < y.pitch;
    });
    for (std::size_t start = 0; start < notes.size();) {
      std::size_t stop = start;
      const auto onset = score.notes[static_cast<std::size_t>(notes[start])].onset_ticks;
      while (stop < notes.size() &&
             score.notes[static_cast<std::size_t>(notes[stop])].onset_ticks == onset) {
        ++stop;
      }
      // [lo, hi): the chord's notes this hand keeps, low to high.
      std::size_t lo = start, hi = stop;
      const auto span = [&] {
        return x_of(score.notes[static_cast<std::size_t>(notes[hi - 1])].pitch) -
               x_of(score.notes[static_cast<std::size_t>(notes[lo])].pitch);
      };
      while (hi - lo > 1 && (span() > reach_mm || hi - lo > 5)) {
        // The right hand gives away its lowest note, the left its highest.
        const auto note = static_cast<std::size_t>(side == music::Hand::right ? notes[lo] : notes[hi - 1]);
        if (!other_hand_takes(score, out, note, other, reach_mm, keyboard)) break;
        out.hand[note] = other;
        out.source[note] = HandSource::reach;
        side == music::Hand::right ? ++lo : --hi;
      }
      start = stop;
    }
  }
}

// A note that takes its hand across the other (a right-hand note at or below a key the left hand
// holds or strikes meanwhile, or a left-hand note at or above one of the right hand's) goes to
// the other hand when that hand can add it at its own outer side: the left hand's lowest or
// highest key then, the other hand's remaining keys all beyond it, the whole within one hand's
// reach and at most five keys. A pianist reads such a note into the other hand rather than
// crossing through it (Chopin's op. 1 no. 4 writes G3 in the right hand's staff under the left
// hand's D4-G4). What the other hand cannot take stays a crossing.
// The other hand is where it plays from kNearS before the note to kNearS after it: a hand that
// has just left a key, or is about to strike one, is still there (the lilypond suite's 43d
// writes B4 in the left hand's staff between the right hand's E4 and C4, a quarter second
// apart; Scarlatti's K. 27 hands B3 from the right thumb to the left thumb as the right lets it
// go). So the same key struck by the other hand just before or just after, not with it, is a
// crossing too: the two thumbs would meet on it.
void take_crossed_notes(const music::Score& score, const FingeringModel& model,
                        HandAssignment& out) {
  constexpr double kArriveS = 0.08;  // the hands' keys ending just before count too
  constexpr double kNearS = 0.3;     // where the other hand is: its keys this near in time
  const Keyboard& keyboard = model.keyboard;
  auto x_of = [&](int key) {
    return keyboard.x_mm(std::clamp(key, keyboard.lowest_key(), keyboard.highest_key()));
  };
  const double reach_mm = model.hand.reach_mm();
  for (std::size_t note = 0; note < score.notes.size(); ++note) {
    const music::Hand side = out.hand[note];
    if (side == music::Hand::unknown || out.source[note] == HandSource::file) continue;
    const music::Hand other = side == music::Hand::right ? music::Hand::left : music::Hand::right;
    const music::Note& n = score.notes[note];
    const auto during = [&](const music::Note& o) {
      return o.offset_s > n.onset_s - kArriveS && o.onset_s < n.offset_s;
    };
    const auto near = [&](const music::Note& o) {
      return o.offset_s > n.onset_s - kNearS && o.onset_s < n.offset_s + kNearS;
    };
    bool crosses = false, other_above = false, other_below = false;
    double lo = x_of(n.pitch), hi = lo;
    int at_onset = 1;
    for (std::size_t i = 0; i < score.notes.size(); ++i) {
      const music::Note& o = score.notes[i];
      if (i == note || out.hand[i] != other || !near(o)) continue;
      if (o.pitch != n.pitch && !during(o)) continue;
      if (o.pitch == n.pitch) {
        if (o.onset_ticks == n.onset_ticks) {
          crosses = false;
          other_above = other_below = true;  // a unison: share_unisons' to settle
          break;
        }
        // The key struck again just after the other hand let it go, or while it holds it: the
        // hand on it plays it. (The other way round, the later note comes to this hand.)
        if (o.onset_ticks > n.onset_ticks) continue;
        crosses = true;
      } else {
        crosses = crosses || (side == music::Hand::right ? o.pitch > n.pitch : o.pitch < n.pitch);
        (o.pitch > n.pitch ? other_above : other_below) = true;
      }
      lo = std::min(lo, x_of(o.pitch));
      hi = std::max(hi, x_of(o.pitch));
      if (o.onset_s <= n.onset_s && o.offset_s > n.onset_s) ++at_onset;
    }
    if (!crosses || (other_above && other_below)) continue;
    if (hi - lo > reach_mm || at_onset > 5) continue;
    // This hand's keys meanwhile must stay beyond the other hand's new span. A key it lets go
    // as the note strikes is not meanwhile: the hand leaves it (43e writes a right-hand line
    // C#5-B4-A4 against the left's B4-C#5-D5, each hand crossing the other note by note).
    const auto meanwhile = [&](const music::Note& o) {
      return o.offset_s > n.onset_s && o.onset_s < n.offset_s;
    };
    bool clear = true;
    for (std::size_t i = 0; i < score.notes.size() && clear; ++i) {
      const music::Note& o = score.notes[i];
      if (i == note || out.hand[i] != side || !meanwhile(o)) continue;
      const double x = x_of(o.pitch);
      clear = other == music::Hand::left ? x > hi : x < lo;
    }
    if (!clear) continue;
    out.hand[note] = other;
    out.source[note] = HandSource::crossing;
  }
}

// A key struck by both hands at once (a score doubles a note in both staves: Clara Schumann's
// op. 1 no. 3 writes D3 in the right hand's staff under the left hand's D3) is one key: one hand
// plays it, the one with more of its other keys at that moment within an octave (ties: the left
// hand below middle C, the right from it up). Otherwise the other hand would fly to it and press
// it through the first hand's fingers.
void share_unisons(const music::Score& score, HandAssignment& out) {
  std::vector<int> order;
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    if (out.hand[i] != music::Hand::unknown) order.push_back(static_cast<int>(i));
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    const auto& x = score.notes[static_cast<std::size_t>(a)];
    const auto& y = score.notes[static_cast<std::size_t>(b)];
    return x.onset_ticks != y.onset_ticks ? x.onset_ticks < y.onset_ticks : x.pitch < y.pitch;
  });
  for (std::size_t start = 0; start < order.size();) {
    std::size_t stop = start;
    const auto onset = score.notes[static_cast<std::size_t>(order[start])].onset_ticks;
    while (stop < order.size() &&
           score.notes[static_cast<std::size_t>(order[stop])].onset_ticks == onset) {
      ++stop;
    }
    for (std::size_t a = start; a < stop;) {
      const int pitch = score.notes[static_cast<std::size_t>(order[a])].pitch;
      std::size_t b = a;
      bool right = false, left = false, stated = false;
      while (b < stop && score.notes[static_cast<std::size_t>(order[b])].pitch == pitch) {
        const auto i = static_cast<std::size_t>(order[b]);
        right = right || out.hand[i] == music::Hand::right;
        left = left || out.hand[i] == music::Hand::left;
        stated = stated || out.source[i] == HandSource::file;
        ++b;
      }
      if (right && left && !stated) {
        int near_right = 0, near_left = 0;
        for (std::size_t k = start; k < stop; ++k) {
          const auto i = static_cast<std::size_t>(order[k]);
          const int p = score.notes[i].pitch;
          if (p == pitch || std::abs(p - pitch) > 12) continue;
          (out.hand[i] == music::Hand::right ? near_right : near_left) += 1;
        }
        const music::Hand keeper = near_right != near_left
                                       ? (near_right > near_left ? music::Hand::right : music::Hand::left)
                                       : (pitch < 60 ? music::Hand::left : music::Hand::right);
        for (std::size_t k = a; k < b; ++k) {
          const auto i = static_cast<std::size_t>(order[k]);
          if (out.hand[i] != keeper) {
            out.hand[i] = keeper;
            out.source[i] = HandSource::unison;
          }
        }
      }
      a = b;
    }
    start = stop;
  }
}

// Crowded hands: the left hand's highest key less than this many white keys below the right
// hand's lowest (or above it). The hands' thumb sides then meet: a hand's keys lie up to about
// two white keys from its thumb, which reaches one more.
constexpr double kCrowdedWhiteKeys = 3.5;
// The widest passage one hand takes over (white keys, lowest to highest).
constexpr double kPassageWhiteKeys = 6.0;

// Passages where both hands play crowded together at every onset and one hand could play all of
// their keys (within its reach, at most five at once) go to one hand: the one with more of the
// passage's notes (ties: the side of middle C the passage is on). A hand a file states is kept.
void one_hand_for_crowded_passages(const music::Score& score, const FingeringModel& model,
                                   HandAssignment& out) {
  constexpr double kLegatoOverlapS = 0.05;  // a key overlapping the next onset this little has gone
  constexpr double kNearS = 0.3;  // where the other hand is: its keys this near in time
  const Keyboard& keyboard = model.keyboard;
  auto x_of = [&](int key) {
    return keyboard.x_mm(std::clamp(key, keyboard.lowest_key(), keyboard.highest_key()));
  };
  const double reach_mm = model.hand.reach_mm();
  const double crowded_mm = kCrowdedWhiteKeys * keyboard.white_key_width_mm();
  std::vector<int> order;
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    if (out.hand[i] != music::Hand::unknown) order.push_back(static_cast<int>(i));
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return score.notes[static_cast<std::size_t>(a)].onset_ticks <
           score.notes[static_cast<std::size_t>(b)].onset_ticks;
  });
  // Each onset: whether the hands are crowded there and one hand could take all their keys.
  struct Onset {
    std::size_t begin, end;  // into `order`: the notes struck here
    bool crowded_and_fits;
    double onset_s;
  };
  std::vector<Onset> onsets;
  std::vector<std::size_t> sounding;  // notes struck so far and not yet let go
  for (std::size_t start = 0; start < order.size();) {
    std::size_t stop = start;
    const auto& first = score.notes[static_cast<std::size_t>(order[start])];
    while (stop < order.size() &&
           score.notes[static_cast<std::size_t>(order[stop])].onset_ticks == first.onset_ticks) {
      ++stop;
    }
    // The keys sounding as this onset strikes, by hand (held ones included).
    std::erase_if(sounding, [&](std::size_t i) {
      return score.notes[i].offset_s <= first.onset_s + kLegatoOverlapS;
    });
    for (std::size_t k = start; k < stop; ++k) sounding.push_back(static_cast<std::size_t>(order[k]));
    int left_top = -1, right_bottom = 128, lowest = 128, highest = -1, keys = 0;
    bool stated = false;
    for (const std::size_t i : sounding) {
      const music::Note& n = score.notes[i];
      stated = stated || out.source[i] == HandSource::file;
      if (out.hand[i] == music::Hand::left) left_top = std::max(left_top, n.pitch);
      else right_bottom = std::min(right_bottom, n.pitch);
      lowest = std::min(lowest, n.pitch);
      highest = std::max(highest, n.pitch);
      ++keys;
    }
    const bool both = left_top >= 0 && right_bottom < 128;
    const bool crowded = both && x_of(right_bottom) - x_of(left_top) < crowded_mm;
    const bool fits = keys <= 5 && x_of(highest) - x_of(lowest) <= reach_mm;
    onsets.push_back({start, stop, crowded && fits && !stated, first.onset_s});
    start = stop;
  }
  for (std::size_t a = 0; a < onsets.size();) {
    if (!onsets[a].crowded_and_fits) {
      ++a;
      continue;
    }
    std::size_t b = a;
    while (b < onsets.size() && onsets[b].crowded_and_fits) ++b;
    // The passage: onsets [a, b). Its notes, and which hand has more of them.
    int right = 0, left = 0;
    double pitch_sum = 0.0;
    for (std::size_t k = onsets[a].begin; k < onsets[b - 1].end; ++k) {
      const auto i = static_cast<std::size_t>(order[k]);
      (out.hand[i] == music::Hand::right ? right : left) += 1;
      pitch_sum += score.notes[i].pitch;
    }
    const double centre = pitch_sum / static_cast<double>(right + left);
    // The passage's keys (lo_mm..hi_mm) and time, and whether `giver` is free of it: none of its
    // other keys this near in time (struck or held) lies crowded against the passage's keys.
    // A hand that has just played there, or goes on there, would meet the keeper's thumb.
    double lo_mm = 1e300, hi_mm = -1e300, start_s = onsets[a].onset_s, end_s = start_s;
    for (std::size_t k = onsets[a].begin; k < onsets[b - 1].end; ++k) {
      const music::Note& n = score.notes[static_cast<std::size_t>(order[k])];
      lo_mm = std::min(lo_mm, x_of(n.pitch));
      hi_mm = std::max(hi_mm, x_of(n.pitch));
      end_s = std::max(end_s, n.offset_s);
    }
    // A passage that sits in one place (a seventh: 43e's thirds between F#4 and D5), not one a
    // hand would leap through (a left-hand D3-A3 taken by the right hand from C5).
    if (hi_mm - lo_mm > std::min(reach_mm, kPassageWhiteKeys * keyboard.white_key_width_mm())) {
      a = b;
      continue;
    }
    const auto free_of_passage = [&](music::Hand giver) {
      for (std::size_t k = 0; k < order.size(); ++k) {
        if (k >= onsets[a].begin && k < onsets[b - 1].end) continue;
        const auto i = static_cast<std::size_t>(order[k]);
        const music::Note& n = score.notes[i];
        if (out.hand[i] != giver || n.offset_s <= start_s - kNearS || n.onset_s >= end_s + kNearS) continue;
        const double x = x_of(n.pitch);
        if (x > lo_mm - crowded_mm && x < hi_mm + crowded_mm) return false;
      }
      return true;
    };
    const music::Hand preferred = right != left ? (right > left ? music::Hand::right : music::Hand::left)
                                                : (centre >= 60.0 ? music::Hand::right : music::Hand::left);
    const music::Hand other = preferred == music::Hand::right ? music::Hand::left : music::Hand::right;
    music::Hand keeper = music::Hand::unknown;
    if (free_of_passage(other)) keeper = preferred;
    else if (free_of_passage(preferred)) keeper = other;
    if (keeper == music::Hand::unknown) {
      a = b;
      continue;
    }
    for (std::size_t k = onsets[a].begin; k < onsets[b - 1].end; ++k) {
      const auto i = static_cast<std::size_t>(order[k]);
      if (out.hand[i] == keeper) continue;
      out.hand[i] = keeper;
      out.source[i] = HandSource::crowded;
    }
    a = b;
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
  keep_chords_in_reach(score, model, out);
  // Unisons first: a doubled key given to one hand no longer blocks a crossing note beside it.
  share_unisons(score, out);
  take_crossed_notes(score, model, out);
  one_hand_for_crowded_passages(score, model, out);
  return out;
}

}  // namespace tutti::fingering_planner
