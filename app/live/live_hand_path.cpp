// SPDX-License-Identifier: MIT
#include <tutti/live/live_hand_path.hpp>

#include <algorithm>
#include <vector>

namespace tutti::live {
namespace {

// x(0) = x0, x'(0) = v0, x''(0) = a0; x(T) = x1, x'(T) = x''(T) = 0.
spline_motion::Poly5 quintic(double x0, double v0, double a0, double x1, double duration) {
  const double t = duration, d = x1 - x0;
  spline_motion::Poly5 p;
  p.c[0] = x0;
  p.c[1] = v0;
  p.c[2] = 0.5 * a0;
  p.c[3] = (20 * d - 12 * v0 * t - 3 * a0 * t * t) / (2 * t * t * t);
  p.c[4] = (-30 * d + 16 * v0 * t + 3 * a0 * t * t) / (2 * t * t * t * t);
  p.c[5] = (12 * d - 6 * v0 * t - a0 * t * t) / (2 * t * t * t * t * t);
  return p;
}

}  // namespace

LiveHandPath::LiveHandPath(double start_x_mm, double move_s, std::size_t kept_moves)
    : move_s_(move_s), kept_(std::max<std::size_t>(kept_moves, 2)) {
  spline_motion::Poly5 hold;
  hold.c[0] = start_x_mm;
  moves_.push_back({-1.0e9, move_s_, start_x_mm, hold});
}

spline_motion::HandState LiveHandPath::state(double t_s) const {
  // The last move started at or before t (moves are in start order).
  auto it = std::upper_bound(moves_.begin(), moves_.end(), t_s,
                             [](double t, const Move& m) { return t < m.start_s; });
  if (it == moves_.begin()) return {moves_.front().poly.c[0], 0.0, 0.0};
  const Move& m = *std::prev(it);
  const double dt = t_s - m.start_s;
  if (dt >= m.duration_s) return {m.to_x_mm, 0.0, 0.0};
  return {m.poly.value(dt), m.poly.velocity(dt), m.poly.acceleration(dt)};
}

void LiveHandPath::move_to(double t_s, double x_mm) {
  while (moves_.size() > 1 && moves_.back().start_s >= t_s) moves_.pop_back();
  const spline_motion::HandState from = state(t_s);
  moves_.push_back(
      {t_s, move_s_, x_mm, quintic(from.x_mm, from.v_mm_per_s, from.a_mm_per_s2, x_mm, move_s_)});
  while (moves_.size() > kept_) moves_.pop_front();
}

spline_motion::HandPath LiveHandPath::build() const {
  std::vector<double> knots;
  std::vector<spline_motion::Poly5> pieces;
  const auto constant = [](double x) {
    spline_motion::Poly5 p;
    p.c[0] = x;
    return p;
  };
  // The first move is the rest position (or an old move whose shape no longer matters): the
  // path starts where the second one starts from.
  for (std::size_t k = 1; k < moves_.size(); ++k) {
    const Move& m = moves_[k];
    const double end = k + 1 < moves_.size()
                           ? std::min(m.start_s + m.duration_s, moves_[k + 1].start_s)
                           : m.start_s + m.duration_s;
    knots.push_back(m.start_s);
    pieces.push_back(m.poly);
    if (k + 1 < moves_.size() && end < moves_[k + 1].start_s) {
      knots.push_back(end);
      pieces.push_back(constant(m.to_x_mm));
    }
  }
  if (knots.empty()) {
    // Never moved: hold the start for ever (two knots make a path that evaluates to it).
    return spline_motion::HandPath(spline_motion::SmoothingMode::none, {0.0, 1.0},
                            {constant(moves_.front().to_x_mm)}, moves_.front().to_x_mm, false);
  }
  knots.push_back(moves_.back().start_s + moves_.back().duration_s);
  return spline_motion::HandPath(spline_motion::SmoothingMode::none, std::move(knots), std::move(pieces),
                          moves_.back().to_x_mm, false);
}

}  // namespace tutti::live
