// SPDX-License-Identifier: MIT
#pragma once
// Shared by the spline-motion tests: random corridor sequences and the taut string's
// optimality certificate.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <span>
#include <string>

#include <tutti/piano_model/hand_corridor.hpp>
#include <tutti/spline_motion/corridor_portals.hpp>
#include <tutti/spline_motion/taut_string.hpp>

namespace tutti::spline_motion::testing {

using piano_model::HandCorridor;
using piano_model::HandCorridors;

// Piano-like sequences: held notes of 0..0.5 s, gaps of 0 (legato, touching) to 0.3 s, quick
// shifts (a few ms) between long holds, zero-length and zero-width corridors, big leaps.
inline HandCorridors random_corridors(std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  HandCorridors out;
  double t = unit(rng);
  double centre = 300.0 + 600.0 * unit(rng);
  double inst_lo = 0.0;  // the range allowed at time t by the corridors that touch it
  double inst_hi = 0.0;
  for (int i = 0; i < count; ++i) {
    const double r = unit(rng);
    double gap = r < 0.2 ? 0.0 : r < 0.45 ? 0.001 + 0.01 * unit(rng) : 0.3 * unit(rng);
    const double duration = unit(rng) < 0.1 ? 0.0 : 0.02 + 0.5 * unit(rng);
    const double width = unit(rng) < 0.1 ? 0.0 : 40.0 * unit(rng);
    const double leap = unit(rng) < 0.15 ? 300.0 : 40.0;
    centre = std::clamp(centre + leap * (2.0 * unit(rng) - 1.0), 0.0, 1300.0);
    HandCorridor c{0.0, 0.0, centre - width / 2, centre + width / 2};
    // No jumps: a corridor touching the previous ones must overlap what they allow at t.
    if (i > 0 && gap == 0.0 && (c.lo_mm > inst_hi || c.hi_mm < inst_lo)) gap = 0.002;
    if (i > 0) t += gap;
    c.start_s = t;
    c.end_s = t + duration;
    t = c.end_s;
    if (i > 0 && gap == 0.0 && duration == 0.0) {
      inst_lo = std::max(inst_lo, c.lo_mm);
      inst_hi = std::min(inst_hi, c.hi_mm);
    } else {
      inst_lo = c.lo_mm;
      inst_hi = c.hi_mm;
    }
    out.push_back(c);
  }
  return out;
}

// Checks that `s` is THE shortest path through `portals` (free ends) by the convex problem's
// optimality (KKT) conditions: it is feasible at every portal; every vertex lies at a portal
// time; where the slope increases the vertex is on that portal's upper end, where it decreases
// on the lower end; a sloped first (last) link starts (ends) on the end its slope pulls toward.
// Returns "" or a description of the first failure.
inline std::string certificate(const TautString& s, std::span<const Portal> portals) {
  if (portals.empty()) return s.points.empty() ? "" : "points for no portals";
  const auto& p = s.points;
  if (p.empty()) return "no points";
  if (p.front().t_s != portals.front().t_s || p.back().t_s != portals.back().t_s) {
    return "does not span the portals";
  }
  const double eps = 1e-9;
  for (const Portal& q : portals) {
    const double x = s.position(q.t_s);
    if (x < q.lo_mm - eps || x > q.hi_mm + eps) {
      return "infeasible at t=" + std::to_string(q.t_s);
    }
  }
  const auto portal_at = [&](double t) -> const Portal* {
    auto it = std::lower_bound(portals.begin(), portals.end(), t,
                               [](const Portal& a, double v) { return a.t_s < v; });
    return it != portals.end() && it->t_s == t ? &*it : nullptr;
  };
  const auto slope = [&](std::size_t i) {
    return (p[i + 1].x_mm - p[i].x_mm) / (p[i + 1].t_s - p[i].t_s);
  };
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Portal* q = portal_at(p[i].t_s);
    if (q == nullptr) return "vertex " + std::to_string(i) + " not at a portal time";
    if (i + 1 < p.size() && !(p[i + 1].t_s > p[i].t_s)) return "times not increasing";
    double pull = 0.0;  // > 0: the string pulls the vertex up (needs the upper end)
    if (p.size() == 1) break;
    if (i == 0) {
      pull = slope(0);
    } else if (i + 1 == p.size()) {
      pull = -slope(i - 1);
    } else {
      pull = slope(i) - slope(i - 1);
    }
    const double scale = 1e-9 * (1.0 + std::abs(i > 0 ? slope(i - 1) : 0.0) +
                                 std::abs(i + 1 < p.size() ? slope(i) : 0.0));
    if (pull > scale && p[i].x_mm != q->hi_mm) {
      return "vertex " + std::to_string(i) + " pulled up but not on an upper end";
    }
    if (pull < -scale && p[i].x_mm != q->lo_mm) {
      return "vertex " + std::to_string(i) + " pulled down but not on a lower end";
    }
    if (i > 0 && i + 1 < p.size() && std::abs(pull) <= scale * 1e-3) {
      return "vertex " + std::to_string(i) + " is not a bend";
    }
  }
  return "";
}

}  // namespace tutti::spline_motion::testing
