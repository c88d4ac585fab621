// SPDX-License-Identifier: MIT
// A material's textures and their use (set 1): must match render/material_table.cpp
// (MaterialUniforms, the binding order). Slots: 0 base colour (sRGB), 1 metallic-roughness
// (G roughness, B metallic), 2 normal (tangent space), 3 occlusion (R), 4 emissive (sRGB).

layout(set = 1, binding = 0) uniform sampler2D base_color_map;
layout(set = 1, binding = 1) uniform sampler2D metallic_roughness_map;
layout(set = 1, binding = 2) uniform sampler2D normal_map;
layout(set = 1, binding = 3) uniform sampler2D occlusion_map;
layout(set = 1, binding = 4) uniform sampler2D emissive_map;
layout(set = 1, binding = 5) uniform MaterialData {
  vec4 uv[10];  // per slot: two rows of its KHR_texture_transform; uv[2 slot].w its UV set
  vec4 params;  // x normal scale (0: none), y occlusion strength, z alpha cutoff, w alpha mode
} material;

vec2 slot_uv(int slot, vec2 uv0, vec2 uv1) {
  vec4 first = material.uv[2 * slot];
  vec3 uv = vec3(first.w < 0.5 ? uv0 : uv1, 1.0);
  return vec2(dot(first.xyz, uv), dot(material.uv[2 * slot + 1].xyz, uv));
}

vec3 srgb_to_linear(vec3 c) {
  return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(vec3(0.04045), c));
}

// A tangent-space normal map applied without stored tangents: the cotangent frame from the
// position's and the UV's screen derivatives (Schüler, "Normal Mapping Without Precomputed
// Tangents"). Vulkan's framebuffer y runs down, which turns the frame Schüler's formula gives
// round (both axes); glTF's UVs run down the image while its normal maps' +y points up it, which
// turns the bitangent round again.
vec3 perturbed_normal(vec3 n, vec3 position, vec2 uv, vec3 map_value, float scale) {
  vec3 t_normal = map_value * 2.0 - 1.0;
  t_normal.xy *= scale;
  vec3 dp1 = dFdx(position), dp2 = dFdy(position);
  vec2 duv1 = dFdx(uv), duv2 = dFdy(uv);
  vec3 dp2perp = cross(dp2, n), dp1perp = cross(n, dp1);
  vec3 t = -(dp2perp * duv1.x + dp1perp * duv2.x);
  vec3 b = dp2perp * duv1.y + dp1perp * duv2.y;
  float inv = inversesqrt(max(max(dot(t, t), dot(b, b)), 1e-20));
  return normalize(mat3(t * inv, b * inv, n) * t_normal);
}
