// SPDX-License-Identifier: MIT
#include <tutti/runtime/dynamic_resolution.hpp>

#include <algorithm>
#include <cmath>

namespace tutti::runtime {

DynamicResolution::DynamicResolution(const DynamicResolutionOptions& options)
    : options_(options), scale_(options.max_scale) {}

float DynamicResolution::update(double frame_s) {
  if (!std::isfinite(frame_s) || frame_s <= 0.0) return scale_;
  // The first frames (shader compilation, first uploads) would drive the scale to its floor.
  if (++frames_ <= 10) return scale_;
  average_s_ = average_s_ == 0.0 ? frame_s : 0.8 * average_s_ + 0.2 * frame_s;
  const double target = options_.target_frame_s;
  // Near the target: stay (no hunting around it). Wider below than above: on a CPU device much of
  // a frame does not shrink with the pixels, so giving some up gains less than the model says.
  if (average_s_ <= target * 1.05 && average_s_ >= target * 0.9) return scale_;
  // Pixels cost ~ scale²: the scale that would meet the target, approached a few % a frame.
  const double wanted = scale_ * std::sqrt(target / average_s_);
  const double moved = std::clamp(wanted, scale_ * 0.96, scale_ * 1.03);
  const double stepped = std::round(moved / options_.step) * options_.step;
  // A step that rounds back to where it was still moves by one step.
  double next = stepped;
  if (stepped == scale_) next = scale_ + (wanted > scale_ ? options_.step : -options_.step);
  scale_ = static_cast<float>(std::clamp(next, static_cast<double>(options_.min_scale),
                                         static_cast<double>(options_.max_scale)));
  return scale_;
}

}  // namespace tutti::runtime
