// SPDX-License-Identifier: MIT
#include <tutti/spline_motion/hand_path.hpp>

#include <algorithm>
#include <utility>

namespace tutti::spline_motion {

const char* to_string(SmoothingMode mode) {
  switch (mode) {
    case SmoothingMode::monotone_quintic:
      return "monotone_quintic";
    case SmoothingMode::pchip:
      return "pchip";
    case SmoothingMode::natural_spline:
      return "natural_spline";
    case SmoothingMode::none:
      return "none";
  }
  return "?";
}

std::optional<SmoothingMode> smoothing_mode_from_string(std::string_view name) noexcept {
  for (const SmoothingMode mode : {SmoothingMode::monotone_quintic, SmoothingMode::pchip,
                                   SmoothingMode::natural_spline, SmoothingMode::none}) {
    if (name == to_string(mode)) return mode;
  }
  return std::nullopt;
}

HandPath::HandPath(SmoothingMode mode, std::vector<double> knot_times, std::vector<Poly5> pieces,
                   double end_x_mm, bool monotone)
    : mode_(mode),
      knot_times_(std::move(knot_times)),
      pieces_(std::move(pieces)),
      end_x_mm_(end_x_mm),
      monotone_(monotone) {}

double HandPath::start_x_mm() const { return pieces_.empty() ? end_x_mm_ : pieces_.front().c[0]; }

HandState evaluate(const HandPath& path, double t_s) noexcept {
  const std::span<const double> knots = path.knot_times();
  const std::span<const Poly5> pieces = path.pieces();
  if (knots.empty()) return {};
  if (!(t_s >= knots.front())) return {path.start_x_mm(), 0.0, 0.0};  // also NaN
  if (t_s >= knots.back() || pieces.empty()) return {path.end_x_mm(), 0.0, 0.0};
  // knots[k] <= t_s < knots[k + 1]
  const std::size_t k =
      static_cast<std::size_t>(std::upper_bound(knots.begin(), knots.end(), t_s) - knots.begin()) -
      1;
  const Poly5& piece = pieces[k];
  const double dt = t_s - knots[k];
  double x = piece.value(dt);
  if (path.monotone_pieces()) {
    const double x0 = piece.c[0];
    const double x1 = k + 1 < pieces.size() ? pieces[k + 1].c[0] : path.end_x_mm();
    x = std::clamp(x, std::min(x0, x1), std::max(x0, x1));
  }
  return {x, piece.velocity(dt), piece.acceleration(dt)};
}

}  // namespace tutti::spline_motion
