// SPDX-License-Identifier: MIT
#pragma once
// Where an entity is: position in millimetres and a unit quaternion, in the frame its kind
// says.
//  - A performer (written by its family when staged): on the stage, in the scene's frame (the
//    scene's position_m in mm, y up); the rotation turns the performer, who faces +z when it is
//    the identity, about +y by the scene's facing_deg.
//  - The keyboard frame (a Hand's rotation): x along the keyboard (0 = left edge of the lowest
//    key, as in content/piano/keyboard.json), y from the front edge of the white keys toward the
//    fallboard, z up (0 = top of the white keys).

namespace tutti::components {

// Unit quaternion, w + xi + yj + zk. The default is the identity (no rotation).
struct Rotation {
  double w = 1.0;
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};

struct Transform {
  double x_mm = 0.0;
  double y_mm = 0.0;
  double z_mm = 0.0;
  Rotation rotation;
};

}  // namespace tutti::components
