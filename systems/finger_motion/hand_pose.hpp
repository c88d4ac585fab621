// SPDX-License-Identifier: MIT
#pragma once
// The pose of one hand at one time: what evaluate_hand_pose writes into a caller-owned struct.
// Angles radians, positions millimetres in the keyboard frame (x along the keys, y into the keys,
// z up from the white keys' top). Field meanings match components/finger.hpp.

#include <array>

namespace tutti::finger_motion {

struct FingerPose {
  double spread_rad = 0.0;       // > 0 toward the little-finger side
  double abduction_rad = 0.0;    // thumb stroke joint (0 for fingers 2..5)
  double mcp_flexion_rad = 0.0;  // fingers 2..5: stroke joint; thumb: MCP (part of the bend)
  double pip_flexion_rad = 0.0;  // thumb: IP
  double dip_flexion_rad = 0.0;  // thumb: 0
  double press_depth = 0.0;      // 0 = key up .. 1 = key bottom
  double tip_x_mm = 0.0;  // the posed fingertip
  double tip_y_mm = 0.0;
  double tip_z_mm = 0.0;
  // Where the finger meets the key: the pad, pad_drop_mm below the tip (the same point for
  // fingers without a drop). The key follows it.
  double contact_y_mm = 0.0;
  double contact_z_mm = 0.0;
  int key = -1;  // MIDI key the finger is pressing (press_depth > 0), else -1
};

struct HandPose {
  double x_mm = 0.0;          // hand reference point (middle finger root) along the keyboard
  double v_x_mm_per_s = 0.0;  // its lateral speed
  double y_mm = 0.0;          // middle finger root, into the keys
  double z_mm = 0.0;          // middle finger root height
  std::array<FingerPose, 5> fingers{};  // [0] = thumb
};

}  // namespace tutti::finger_motion
