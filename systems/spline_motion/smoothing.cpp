// SPDX-License-Identifier: MIT
#include <tutti/spline_motion/smoothing.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <vector>

namespace tutti::spline_motion {
namespace {

// Knot slopes for a monotone interpolant: 0 at the ends and where the secants change sign or
// vanish, otherwise the Fritsch-Butland weighted harmonic mean capped at cap x the smaller
// secant (cap 3 keeps a cubic monotone, cap 2 a quintic with zero end accelerations).
std::vector<double> monotone_slopes(std::span<const PathPoint> k, double cap) {
  const std::size_t n = k.size();
  std::vector<double> d(n, 0.0);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double h0 = k[i].t_s - k[i - 1].t_s;
    const double h1 = k[i + 1].t_s - k[i].t_s;
    const double s0 = (k[i].x_mm - k[i - 1].x_mm) / h0;
    const double s1 = (k[i + 1].x_mm - k[i].x_mm) / h1;
    if (!(s0 * s1 > 0.0)) continue;  // sign change, flat secant (or underflow): stop here
    const double w0 = 2.0 * h1 + h0;
    const double w1 = h1 + 2.0 * h0;
    const double mean = (w0 + w1) / (w0 / s0 + w1 / s1);
    const double limit = cap * std::min(std::abs(s0), std::abs(s1));
    d[i] = std::copysign(std::min(std::abs(mean), limit), s0);
  }
  return d;
}

// Natural cubic spline slopes (second derivative 0 at both ends), Thomas algorithm.
std::vector<double> natural_spline_slopes(std::span<const PathPoint> k) {
  const std::size_t n = k.size();
  std::vector<double> d(n, 0.0);
  if (n < 2) return d;
  std::vector<double> h(n - 1);
  std::vector<double> s(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    h[i] = k[i + 1].t_s - k[i].t_s;
    s[i] = (k[i + 1].x_mm - k[i].x_mm) / h[i];
  }
  std::vector<double> m(n, 0.0);  // second derivatives
  if (n > 2) {
    // rows i = 1..n-2: h[i-1] m[i-1] + 2 (h[i-1] + h[i]) m[i] + h[i] m[i+1] = 6 (s[i] - s[i-1])
    std::vector<double> cp(n, 0.0);
    std::vector<double> dp(n, 0.0);
    for (std::size_t i = 1; i + 1 < n; ++i) {
      const double a = h[i - 1];
      const double b = 2.0 * (h[i - 1] + h[i]);
      const double c = h[i];
      const double r = 6.0 * (s[i] - s[i - 1]);
      const double denom = b - a * cp[i - 1];
      cp[i] = c / denom;
      dp[i] = (r - a * dp[i - 1]) / denom;
    }
    for (std::size_t i = n - 2; i >= 1; --i) {
      m[i] = dp[i] - cp[i] * m[i + 1];
    }
  }
  for (std::size_t i = 0; i + 1 < n; ++i) d[i] = s[i] - h[i] * (2.0 * m[i] + m[i + 1]) / 6.0;
  d[n - 1] = s[n - 2] + h[n - 2] * (m[n - 2] + 2.0 * m[n - 1]) / 6.0;
  return d;
}

enum class PieceShape { linear, cubic, quintic };

// Hermite pieces through knots with slopes d (zero end accelerations for quintics), converted
// from the unit parameter u = dt / h to dt.
Result<HandPath> build_path(std::span<const PathPoint> k, std::span<const double> d,
                            PieceShape shape, SmoothingMode mode, bool monotone) {
  std::vector<double> times(k.size());
  for (std::size_t i = 0; i < k.size(); ++i) times[i] = k[i].t_s;
  std::vector<Poly5> pieces(k.empty() ? 0 : k.size() - 1);
  for (std::size_t i = 0; i + 1 < k.size(); ++i) {
    const double h = k[i + 1].t_s - k[i].t_s;
    const double delta = k[i + 1].x_mm - k[i].x_mm;
    std::array<double, 6> u{};  // coefficients in u
    u[0] = k[i].x_mm;
    if (shape == PieceShape::linear) {
      u[1] = delta;
    } else {
      const double d0 = d[i] * h;
      const double d1 = d[i + 1] * h;
      u[1] = d0;
      if (shape == PieceShape::cubic) {
        u[2] = 3.0 * delta - 2.0 * d0 - d1;
        u[3] = -2.0 * delta + d0 + d1;
      } else {
        u[3] = 10.0 * delta - 6.0 * d0 - 4.0 * d1;
        u[4] = -15.0 * delta + 8.0 * d0 + 7.0 * d1;
        u[5] = 6.0 * delta - 3.0 * d0 - 3.0 * d1;
      }
    }
    Poly5& p = pieces[i];
    const double inv_h = 1.0 / h;
    double scale = 1.0;
    for (std::size_t j = 0; j < 6; ++j) {
      p.c[j] = u[j] * scale;
      scale *= inv_h;
      if (!std::isfinite(p.c[j])) {
        std::ostringstream out;
        out.precision(17);
        out << "hand path: knots at t=" << k[i].t_s << " s and t=" << k[i + 1].t_s
            << " s are too close in time for a polynomial piece";
        return Error{out.str()};
      }
    }
  }
  return HandPath(mode, std::move(times), std::move(pieces), k.empty() ? 0.0 : k.back().x_mm,
                  monotone);
}

}  // namespace

Result<HandPath> smooth_taut_string(const TautString& string, std::span<const Portal> portals,
                                    SmoothingMode mode) {
  if (string.points.empty()) return HandPath(mode, {}, {}, 0.0, true);
  switch (mode) {
    case SmoothingMode::monotone_quintic: {
      const std::vector<PathPoint> knots = sample_at_portals(string, portals);
      const std::vector<double> d = monotone_slopes(knots, 2.0);
      return build_path(knots, d, PieceShape::quintic, mode, true);
    }
    case SmoothingMode::pchip: {
      const std::vector<PathPoint> knots = sample_at_portals(string, portals);
      const std::vector<double> d = monotone_slopes(knots, 3.0);
      return build_path(knots, d, PieceShape::cubic, mode, true);
    }
    case SmoothingMode::natural_spline: {
      const std::vector<double> d = natural_spline_slopes(string.points);
      return build_path(string.points, d, PieceShape::cubic, mode, false);
    }
    case SmoothingMode::none:
      return build_path(string.points, {}, PieceShape::linear, mode, true);
  }
  return Error{"hand path: unknown smoothing mode"};
}

Result<HandPath> plan_hand_path(std::span<const piano_model::HandCorridor> corridors,
                                const PlanOptions& options) {
  Result<std::vector<Portal>> portals = corridor_portals(corridors);
  if (!portals) return portals.error();
  const TautString string = taut_string(std::span<const Portal>(*portals));
  return smooth_taut_string(string, *portals, options.smoothing);
}

}  // namespace tutti::spline_motion
