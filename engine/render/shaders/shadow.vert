// SPDX-License-Identifier: MIT
#version 450
#extension GL_GOOGLE_include_directive : require
// Depth from the key light: the same deformation as lit.vert, so shadows move with the bodies.
#include "frame_data.glsl"
#include "deform.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in uvec4 in_joints;
layout(location = 3) in vec4 in_weights;

void main() {
  vec3 world_position;
  vec3 world_normal;
  deform(in_position, in_normal, in_joints, in_weights, world_position, world_normal);
  gl_Position = frame.light_view_projection * vec4(world_position, 1.0);
}
