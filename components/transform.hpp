#pragma once
// Where an entity is in the scene: position in millimetres and a unit quaternion.
// Axes (the keyboard frame): x along the keyboard (0 = left edge of the lowest key, as in
// content/piano/keyboard.json), y from the front edge of the white keys toward the fallboard,
// z up (0 = top of the white keys).

namespace tutti::components {

// Unit quaternion, w + xi + yj + zk. The default is the identity (no rotation).
struct Rotation {
  double w = 1.0;
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};

struct Transform {
  double x_mm = 0.0;  // along the keyboard
  double y_mm = 0.0;  // into the keyboard, from the white keys' front edge
  double z_mm = 0.0;  // up, from the white keys' top
  Rotation rotation;  // identity = the performer faces +y
};

}  // namespace tutti::components
