// SPDX-License-Identifier: MIT
#pragma once
// The statistics an interactive view shows on F3 (tutti play, the editor): the last frame's time
// and rate, the smoothed time the dynamic resolution acts on, the 3D view's size against the
// window's, and the quality. An ImGui window; call between ImGuiLayer::new_frame and its render.

#include <tutti/render/window_target.hpp>

namespace tutti::runtime {

struct ViewStats {
  double frame_s = 0.0;    // the last frame
  double average_s = 0.0;  // DynamicResolution::average_frame_s()
  bool draft = false;      // ViewQuality::draft
  bool dynamic = false;    // the scale follows the frame time
};

// `corner`: 0 top-left, 1 bottom-left of the window.
void draw_view_stats(const ViewStats& stats, const render::WindowTarget& target, int corner = 0);

}  // namespace tutti::runtime
