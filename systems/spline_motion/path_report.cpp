// SPDX-License-Identifier: MIT
#include <tutti/spline_motion/path_report.hpp>

#include <algorithm>
#include <cmath>

namespace tutti::spline_motion {
namespace {

struct Extent {
  double lo = INFINITY;
  double hi = -INFINITY;
  double t_lo = 0.0;
  double t_hi = 0.0;
  void take(double x, double t) {
    if (x < lo) {
      lo = x;
      t_lo = t;
    }
    if (x > hi) {
      hi = x;
      t_hi = t;
    }
  }
};

// Extent of the path over [a, b] from its pieces (analytic extrema).
void piece_extent(const HandPath& path, double a, double b, Extent& e) {
  const std::span<const double> knots = path.knot_times();
  const std::span<const Poly5> pieces = path.pieces();
  if (a < path.start_s()) e.take(path.start_x_mm(), a);
  if (b >= path.end_s()) e.take(path.end_x_mm(), b);
  if (pieces.empty()) return;
  // First piece whose interval [knots[k], knots[k+1]] reaches a.
  std::size_t k =
      static_cast<std::size_t>(std::upper_bound(knots.begin(), knots.end(), a) - knots.begin());
  k = k == 0 ? 0 : k - 1;
  for (; k < pieces.size() && knots[k] <= b; ++k) {
    const double lo_t = std::max(a, knots[k]);
    const double hi_t = std::min(b, knots[k + 1]);
    if (hi_t < lo_t) continue;
    const auto [mn, mx] = pieces[k].range(0, lo_t - knots[k], hi_t - knots[k]);
    e.take(mn, lo_t);  // the time is approximate (the piece's start) for analytic extrema
    e.take(mx, lo_t);
  }
}

}  // namespace

PathReport corridor_violations(const HandPath& path,
                               std::span<const piano_model::HandCorridor> corridors,
                               const ReportOptions& options) {
  PathReport report;
  const int samples = std::max(options.samples_per_corridor, 2);
  for (std::size_t i = 0; i < corridors.size(); ++i) {
    const piano_model::HandCorridor& c = corridors[i];
    Extent e;
    for (int s = 0; s < samples; ++s) {
      const double t = c.start_s + (c.end_s - c.start_s) * s / (samples - 1);
      e.take(evaluate(path, std::min(t, c.end_s)).x_mm, t);
    }
    // Raw pieces, without evaluate()'s clamp: this checks the monotonicity claim itself.
    piece_extent(path, c.start_s, c.end_s, e);
    const double below = c.lo_mm - e.lo;
    const double above = e.hi - c.hi_mm;
    const double worst = std::max(below, above);
    if (worst > options.tolerance_mm) {
      ++report.violating_corridors;
      if (worst > report.worst_violation_mm) {
        report.worst_violation_mm = worst;
        report.worst_corridor = i;
        report.worst_t_s = below >= above ? e.t_lo : e.t_hi;
      }
    }
  }
  const std::span<const double> knots = path.knot_times();
  const std::span<const Poly5> pieces = path.pieces();
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const double h = knots[k + 1] - knots[k];
    const auto [v_lo, v_hi] = pieces[k].range(1, 0.0, h);
    const auto [a_lo, a_hi] = pieces[k].range(2, 0.0, h);
    report.peak_speed_mm_per_s =
        std::max({report.peak_speed_mm_per_s, std::abs(v_lo), std::abs(v_hi)});
    report.peak_acceleration_mm_per_s2 =
        std::max({report.peak_acceleration_mm_per_s2, std::abs(a_lo), std::abs(a_hi)});
  }
  return report;
}

}  // namespace tutti::spline_motion
