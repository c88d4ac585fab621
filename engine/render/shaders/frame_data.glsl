// SPDX-License-Identifier: MIT
// What every lit and shadow shader sees: the frame's uniforms, the per-frame matrices and morph
// weights, the model geometry's morph deltas, and the per-draw push constants. Must match
// render/model_renderer.cpp (FrameUniforms, DrawConstants).

layout(set = 0, binding = 0) uniform FrameUniforms {
  mat4 view_projection;
  mat4 light_view_projection;  // world -> shadow map clip space
  vec4 camera_position;        // xyz, w unused
  vec4 key_direction;          // xyz: direction the key light travels (normalised); w: shadow bias
  vec4 key_color;              // rgb * intensity; w: shadow map texel size
  vec4 fill_direction;
  vec4 fill_color;
  vec4 sky_color;     // hemisphere ambient from above; w: exposure
  vec4 ground_color;  // from below
} frame;

layout(std430, set = 0, binding = 1) readonly buffer Matrices { mat4 matrices[]; };
layout(std430, set = 0, binding = 2) readonly buffer MorphWeights { float morph_weights[]; };
// Per target and vertex: two vec4 (position delta xyz, normal delta xyz).
layout(std430, set = 0, binding = 3) readonly buffer MorphDeltas { vec4 morph_deltas[]; };

layout(push_constant) uniform DrawConstants {
  uint matrix_index;       // the node's world matrix, or the skin's first joint matrix
  uint skinned;            // 1: blend matrices[matrix_index + joint] by the vertex weights
  uint morph_count;        // morph targets of the mesh (0 = none)
  uint morph_delta_base;   // first delta of this primitive (vec4 pairs)
  uint morph_weight_base;  // first weight of the mesh in this instance's weights
  uint vertex_base;        // the primitive's first vertex (gl_VertexIndex - vertex_base = local)
  uint vertex_count;
  uint flags;              // bit 0: double-sided
  vec4 base_color;         // linear RGBA
  vec4 material;           // x metallic, y roughness
  vec4 emissive;           // rgb
} draw;
