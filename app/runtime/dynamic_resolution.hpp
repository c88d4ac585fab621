// SPDX-License-Identifier: MIT
#pragma once
// DynamicResolution: how much of the window the 3D view renders, chosen each frame from the last
// frames' cost so an interactive view keeps its frame rate on a slow device (lavapipe on two
// cores) — WindowTarget::set_render_scale applies it. The cost of a frame is taken as a fixed
// part plus a part that grows with the pixels (scale²); the scale moves toward the one that
// meets the target, a few percent a frame, in steps of 1/32, so it settles instead of hunting.
//
//   DynamicResolution resolution({.target_frame_s = 1.0 / 28.0});
//   every frame: target.set_render_scale(resolution.update(last_frame_s));

namespace tutti::runtime {

// How an interactive view is drawn. draft: 1 sample per pixel, hard shadows, the 3D view at a
// dynamic scale; full: the scene's own settings at full size (offline renders always are).
enum class ViewQuality { draft, full };

struct DynamicResolutionOptions {
  double target_frame_s = 1.0 / 28.0;  // aim here (24 fps needs 41.7 ms: a margin for spikes)
  float min_scale = 0.5f;              // per axis
  float max_scale = 1.0f;
  float step = 1.0f / 32.0f;  // the scale is a multiple of this
};

class DynamicResolution {
 public:
  explicit DynamicResolution(const DynamicResolutionOptions& options = {});

  // The scale for the next frame, after a frame that took `frame_s` seconds at scale().
  float update(double frame_s);
  float scale() const { return scale_; }
  // The smoothed frame time the choice is made from.
  double average_frame_s() const { return average_s_; }

 private:
  DynamicResolutionOptions options_;
  float scale_ = 1.0f;
  double average_s_ = 0.0;
  int frames_ = 0;
};

}  // namespace tutti::runtime
