// SPDX-License-Identifier: MIT
#version 450
// Coloured mesh: object-space position and linear RGB colour per vertex, one MVP push constant.
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_color;

layout(push_constant) uniform PushConstants {
  mat4 mvp;
} pc;

layout(location = 0) out vec3 out_color;

void main() {
  gl_Position = pc.mvp * vec4(in_position, 1.0);
  out_color = in_color;
}
