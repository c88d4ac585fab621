// SPDX-License-Identifier: MIT
#include <tutti/spline_motion/taut_string.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace tutti::spline_motion {
namespace {

// (b - a) x (c - a). For b and c later than a: >= 0 <=> slope(a, c) >= slope(a, b).
double cross(const PathPoint& a, const PathPoint& b, const PathPoint& c) {
  return (b.t_s - a.t_s) * (c.x_mm - a.x_mm) - (b.x_mm - a.x_mm) * (c.t_s - a.t_s);
}

// A chain of points kept as a vector with a moving head: push/pop at the back, pop at the
// front, all O(1); the storage is reused when the chain restarts.
class Chain {
 public:
  explicit Chain(std::size_t capacity) { points_.reserve(capacity); }
  bool empty() const { return head_ == points_.size(); }
  std::size_t size() const { return points_.size() - head_; }
  const PathPoint& front() const { return points_[head_]; }
  const PathPoint& back() const { return points_.back(); }
  const PathPoint& from_back(std::size_t i) const { return points_[points_.size() - 1 - i]; }
  void pop_front() { ++head_; }
  void pop_back() { points_.pop_back(); }
  void push(const PathPoint& p) { points_.push_back(p); }
  void restart(const PathPoint& p) {
    points_.clear();
    head_ = 0;
    points_.push_back(p);
  }
  const PathPoint* begin() const { return points_.data() + head_; }
  const PathPoint* end() const { return points_.data() + points_.size(); }

 private:
  std::vector<PathPoint> points_;
  std::size_t head_ = 0;
};

// Free ends: the optimal path starts flat at the level where the common range of the first
// portals runs out (see header). Returns the start level scanning portals in the given order.
template <typename It>
double free_end_level(It first, It last, bool* all_common, double* common_mid) {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  for (It it = first; it != last; ++it) {
    if (it->lo_mm > hi) return hi;  // the next portal is entirely above: rise from hi
    if (it->hi_mm < lo) return lo;  // entirely below: fall from lo
    lo = std::max(lo, it->lo_mm);
    hi = std::min(hi, it->hi_mm);
  }
  *all_common = true;
  *common_mid = lo + 0.5 * (hi - lo);
  return *common_mid;
}

void drop_collinear(std::vector<PathPoint>& points) {
  if (points.size() < 3) return;
  std::size_t out = 1;
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    if (cross(points[out - 1], points[i], points[i + 1]) != 0.0) points[out++] = points[i];
  }
  points[out++] = points.back();
  points.resize(out);
}

}  // namespace

TautString taut_string(std::span<const Portal> portals) {
  TautString result;
  if (portals.empty()) return result;
  bool all_common = false;
  double mid = 0.0;
  const double x_start = free_end_level(portals.begin(), portals.end(), &all_common, &mid);
  if (all_common) {
    result.points.push_back({portals.front().t_s, mid});
    if (portals.size() > 1) result.points.push_back({portals.back().t_s, mid});
    return result;
  }
  const double x_end = free_end_level(portals.rbegin(), portals.rend(), &all_common, &mid);
  const PathPoint start{portals.front().t_s, x_start};
  const PathPoint finish{portals.back().t_s, x_end};

  // Funnel: `apex` is the last vertex known to be on the string; `upper` is the shortest path
  // from the apex to the newest upper portal end (a convex chain: it bends under upper ends),
  // `lower` the one to the newest lower end (concave, bends over lower ends). Every chain point
  // is strictly later than the apex. Each portal end enters each chain at most once, so the
  // whole loop is O(n).
  std::vector<PathPoint>& out = result.points;
  out.reserve(portals.size());
  out.push_back(start);
  PathPoint apex = start;
  Chain upper(portals.size());
  Chain lower(portals.size());

  const auto add_upper = [&](const PathPoint& p) {
    if (!lower.empty() && cross(apex, lower.front(), p) <= 0.0) {
      // p is on or below the lower chain's first edge: the string wraps over lower ends.
      while (!lower.empty() && cross(apex, lower.front(), p) <= 0.0) {
        apex = lower.front();
        out.push_back(apex);
        lower.pop_front();
      }
      upper.restart(p);
      return;
    }
    while (!upper.empty()) {
      const PathPoint& prev = upper.size() >= 2 ? upper.from_back(1) : apex;
      if (cross(prev, upper.back(), p) > 0.0) break;  // upper.back() still pulls the path down
      upper.pop_back();
    }
    upper.push(p);
  };
  const auto add_lower = [&](const PathPoint& q) {
    if (!upper.empty() && cross(apex, upper.front(), q) > 0.0) {
      // q is above the upper chain's first edge: the string wraps under upper ends. The upper
      // end of q's own portal is never popped (it is directly above q), so `upper` stays
      // non-empty.
      while (!upper.empty() && cross(apex, upper.front(), q) > 0.0) {
        apex = upper.front();
        out.push_back(apex);
        upper.pop_front();
      }
      lower.restart(q);
      return;
    }
    while (!lower.empty()) {
      const PathPoint& prev = lower.size() >= 2 ? lower.from_back(1) : apex;
      if (cross(prev, lower.back(), q) < 0.0) break;  // lower.back() still pushes the path up
      lower.pop_back();
    }
    lower.push(q);
  };

  for (std::size_t k = 1; k + 1 < portals.size(); ++k) {
    add_upper({portals[k].t_s, portals[k].hi_mm});
    add_lower({portals[k].t_s, portals[k].lo_mm});
  }
  // The end is a degenerate portal; after adding it as an upper end, the upper chain is the
  // shortest path from the apex to it (it lies above the lower chain by the funnel invariant).
  add_upper(finish);
  for (const PathPoint& p : upper) out.push_back(p);
  drop_collinear(out);
  return result;
}

Result<TautString> taut_string(std::span<const piano_model::HandCorridor> corridors) {
  Result<std::vector<Portal>> portals = corridor_portals(corridors);
  if (!portals) return portals.error();
  return taut_string(std::span<const Portal>(*portals));
}

double TautString::position(double t_s) const {
  if (t_s <= points.front().t_s) return points.front().x_mm;
  if (t_s >= points.back().t_s) return points.back().x_mm;
  const auto it = std::upper_bound(points.begin(), points.end(), t_s,
                                   [](double t, const PathPoint& p) { return t < p.t_s; });
  const PathPoint& b = *it;
  const PathPoint& a = *(it - 1);
  const double u = (t_s - a.t_s) / (b.t_s - a.t_s);
  return a.x_mm + u * (b.x_mm - a.x_mm);
}

double TautString::length() const {
  double total = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    total += std::hypot(points[i].t_s - points[i - 1].t_s, points[i].x_mm - points[i - 1].x_mm);
  }
  return total;
}

std::vector<PathPoint> sample_at_portals(const TautString& string,
                                         std::span<const Portal> portals) {
  std::vector<PathPoint> samples;
  samples.reserve(portals.size());
  const std::vector<PathPoint>& pts = string.points;
  std::size_t seg = 0;  // pts[seg] <= t < pts[seg + 1]
  for (const Portal& portal : portals) {
    const double t = portal.t_s;
    double x = 0.0;
    if (pts.size() == 1 || t <= pts.front().t_s) {
      x = pts.front().x_mm;
    } else if (t >= pts.back().t_s) {
      x = pts.back().x_mm;
    } else {
      while (pts[seg + 1].t_s <= t) ++seg;
      const PathPoint& a = pts[seg];
      const PathPoint& b = pts[seg + 1];
      x = t == a.t_s ? a.x_mm : a.x_mm + (t - a.t_s) / (b.t_s - a.t_s) * (b.x_mm - a.x_mm);
    }
    // Rounding in the interpolation must not push a sample outside its portal.
    samples.push_back({t, std::clamp(x, portal.lo_mm, portal.hi_mm)});
  }
  return samples;
}

}  // namespace tutti::spline_motion
