// SPDX-License-Identifier: MIT
#include <tutti/piano_performance/idle_hand_room.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace tutti::piano_performance {
namespace {

bool sorted_and_well_formed(std::span<const piano_model::HandCorridor> corridors) {
  for (std::size_t i = 0; i < corridors.size(); ++i) {
    const piano_model::HandCorridor& c = corridors[i];
    if (!std::isfinite(c.start_s) || !std::isfinite(c.end_s) || !std::isfinite(c.lo_mm) ||
        !std::isfinite(c.hi_mm) || c.start_s > c.end_s || c.lo_mm > c.hi_mm) {
      return false;
    }
    if (i > 0 && corridors[i - 1].end_s > c.start_s) return false;
  }
  return true;
}

}  // namespace

piano_model::HandCorridors with_idle_room(
    std::span<const piano_model::HandCorridor> corridors,
    std::span<const piano_model::HandCorridor> other_corridors,
    const spline_motion::HandPath& other, music::Hand side, const IdleRoomOptions& options) {
  piano_model::HandCorridors out(corridors.begin(), corridors.end());
  if (other.empty() || !(options.step_s > 0.0) || !(options.leave_s >= 0.0) ||
      !std::isfinite(options.thumb_mm) || !std::isfinite(options.clearance_mm) ||
      corridors.empty() || !sorted_and_well_formed(corridors)) {
    return out;
  }
  // One-sided: the open side reaches a keyboard's length and more past any key.
  constexpr double kOpenMm = 5000.0;
  constexpr double kShortestGapS = 0.02;
  const bool below = side == music::Hand::left;
  // The other hand's thumb side at t: its reference point + thumb_mm toward this hand, or its
  // outermost key on that side while it plays, if further.
  const auto other_thumb_side = [&](double t) {
    const double x = spline_motion::evaluate(other, t).x_mm;
    auto it =
        std::partition_point(other_corridors.begin(), other_corridors.end(),
                             [&](const piano_model::HandCorridor& c) { return c.start_s <= t; });
    const bool playing = it != other_corridors.begin() && std::prev(it)->end_s >= t &&
                         std::prev(it)->keys_known;
    if (below) {  // the other hand is the right one: its low side
      const double side_x = x - options.thumb_mm;
      return playing ? std::min(side_x, std::prev(it)->keys_lo_mm) : side_x;
    }
    const double side_x = x + options.thumb_mm;
    return playing ? std::max(side_x, std::prev(it)->keys_hi_mm) : side_x;
  };
  const double room_mm = options.thumb_mm + options.clearance_mm;
  const auto crossed = [&](const piano_model::HandCorridor& c, double t) {
    const double x = spline_motion::evaluate(other, t).x_mm;
    return below ? c.lo_mm > x : c.hi_mm < x;
  };
  // Corridors of step_s or less over [from_s, to_s], each keeping the hand room_mm short of the
  // other hand's nearest thumb side over it (its ends and middle: steps are short).
  const auto add_room = [&](double from_s, double to_s) {
    if (to_s - from_s < kShortestGapS) return;
    const int steps = static_cast<int>(std::ceil((to_s - from_s) / options.step_s));
    for (int k = 0; k < steps; ++k) {
      const double t0 = from_s + (to_s - from_s) * k / steps;
      const double t1 = k + 1 == steps ? to_s : from_s + (to_s - from_s) * (k + 1) / steps;
      double nearest = other_thumb_side(t0);
      for (const double t : {0.5 * (t0 + t1), t1}) {
        const double x = other_thumb_side(t);
        nearest = below ? std::min(nearest, x) : std::max(nearest, x);
      }
      piano_model::HandCorridor room{t0, t1, 0.0, 0.0};
      if (below) {
        room.hi_mm = nearest - room_mm;
        room.lo_mm = room.hi_mm - kOpenMm;
      } else {
        room.lo_mm = nearest + room_mm;
        room.hi_mm = room.lo_mm + kOpenMm;
      }
      out.push_back(room);
    }
  };
  out.clear();
  // Before this hand's first keys and after its last, while the other hand plays, too.
  if (!other_corridors.empty() && !crossed(corridors.front(), corridors.front().start_s)) {
    add_room(other_corridors.front().start_s, corridors.front().start_s - options.leave_s);
  }
  for (std::size_t i = 0; i < corridors.size(); ++i) {
    out.push_back(corridors[i]);
    if (i + 1 == corridors.size()) break;
    // A hand crossing the other (its keys beyond the other hand's middle, before or after the
    // gap) plays from over it: no room to keep on this side then.
    if (crossed(corridors[i], corridors[i].end_s) ||
        crossed(corridors[i + 1], corridors[i + 1].start_s)) {
      continue;
    }
    add_room(corridors[i].end_s + options.leave_s, corridors[i + 1].start_s - options.leave_s);
  }
  if (!other_corridors.empty() && !crossed(corridors.back(), corridors.back().end_s)) {
    add_room(corridors.back().end_s + options.leave_s, other_corridors.back().end_s);
  }
  return out;
}

}  // namespace tutti::piano_performance
