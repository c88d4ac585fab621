// SPDX-License-Identifier: MIT
#version 450
#extension GL_GOOGLE_include_directive : require
// Lit meshes: morph targets, GPU skinning, world position, normal and UVs for lit.frag.
#include "frame_data.glsl"
#include "deform.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in uvec4 in_joints;
layout(location = 3) in vec4 in_weights;
layout(location = 4) in vec2 in_uv0;
layout(location = 5) in vec2 in_uv1;

layout(location = 0) out vec3 out_world_position;
layout(location = 1) out vec3 out_world_normal;
layout(location = 2) out vec2 out_uv0;
layout(location = 3) out vec2 out_uv1;

void main() {
  deform(in_position, in_normal, in_joints, in_weights, out_world_position, out_world_normal);
  out_uv0 = in_uv0;
  out_uv1 = in_uv1;
  gl_Position = frame.view_projection * vec4(out_world_position, 1.0);
}
