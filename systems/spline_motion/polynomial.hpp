// SPDX-License-Identifier: MIT
#pragma once
// A polynomial of degree <= 5 in local time dt = t - t0 (seconds), value in millimetres: the
// piece of a hand path between two knots. Header-only, allocation-free.

#include <array>
#include <cmath>
#include <utility>

namespace tutti::spline_motion {

struct Poly5 {
  std::array<double, 6> c{};  // x(dt) = c[0] + c[1] dt + ... + c[5] dt^5

  double value(double dt) const {
    return c[0] + dt * (c[1] + dt * (c[2] + dt * (c[3] + dt * (c[4] + dt * c[5]))));
  }
  double velocity(double dt) const {
    return c[1] + dt * (2 * c[2] + dt * (3 * c[3] + dt * (4 * c[4] + dt * 5 * c[5])));
  }
  double acceleration(double dt) const {
    return 2 * c[2] + dt * (6 * c[3] + dt * (12 * c[4] + dt * 20 * c[5]));
  }
  double jerk(double dt) const { return 6 * c[3] + dt * (24 * c[4] + dt * 60 * c[5]); }
  // order 0: value, 1: velocity, 2: acceleration, 3: jerk.
  double derivative(int order, double dt) const {
    switch (order) {
      case 0:
        return value(dt);
      case 1:
        return velocity(dt);
      case 2:
        return acceleration(dt);
      default:
        return jerk(dt);
    }
  }

  // Minimum and maximum of derivative `order` (0..2) on [a, b]: the ends plus every root of the
  // next derivative, bracketed on `probes` equal steps and refined by bisection. Close pairs of
  // roots inside one step can be missed; the probe values themselves still count.
  std::pair<double, double> range(int order, double a, double b, int probes = 16) const {
    double lo = derivative(order, a);
    double hi = lo;
    const auto take = [&](double dt) {
      const double v = derivative(order, dt);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    };
    take(b);
    if (!(b > a)) return {lo, hi};
    const double step = (b - a) / probes;
    double x0 = a;
    double d0 = derivative(order + 1, a);
    for (int i = 1; i <= probes; ++i) {
      const double x1 = i == probes ? b : a + step * i;
      const double d1 = derivative(order + 1, x1);
      take(x1);
      if ((d0 < 0.0 && d1 > 0.0) || (d0 > 0.0 && d1 < 0.0)) {
        double l = x0;
        double r = x1;
        double dl = d0;
        for (int it = 0; it < 60 && r - l > 0.0; ++it) {
          const double m = l + 0.5 * (r - l);
          if (m <= l || m >= r) break;
          const double dm = derivative(order + 1, m);
          if ((dm < 0.0) == (dl < 0.0)) {
            l = m;
            dl = dm;
          } else {
            r = m;
          }
        }
        take(l);
        take(r);
      }
      x0 = x1;
      d0 = d1;
    }
    return {lo, hi};
  }
};

}  // namespace tutti::spline_motion
