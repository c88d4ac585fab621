// SPDX-License-Identifier: MIT
#version 450
#extension GL_GOOGLE_include_directive : require
// Metallic-roughness shading: a shadowed key light, a fill light, hemisphere ambient with a
// cheap specular term, filmic tone mapping. Writes linear light; the sRGB attachment encodes it.
#include "frame_data.glsl"
#include "material.glsl"

layout(set = 0, binding = 4) uniform sampler2DShadow shadow_map;
// Shadow-map comparisons per pixel (ModelRendererOptions::shadow_taps): 1 or 4.
layout(constant_id = 0) const uint SHADOW_TAPS = 1u;
// The pipeline's material kind (model_renderer.cpp): alpha 0 opaque, 1 mask (discards: early
// depth tests are off for it alone), 2 blend; textured 0 reads no texture at all (lavapipe
// samples on the CPU).
layout(constant_id = 1) const uint ALPHA_MODE = 0u;
layout(constant_id = 2) const uint TEXTURED = 0u;

layout(location = 0) in vec3 in_world_position;
layout(location = 1) in vec3 in_world_normal;
layout(location = 2) in vec2 in_uv0;
layout(location = 3) in vec2 in_uv1;
layout(location = 0) out vec4 out_color;

const float PI = 3.14159265;

float distribution_ggx(float n_dot_h, float alpha) {
  float a2 = alpha * alpha;
  float d = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
  return a2 / (PI * d * d);
}

float visibility_smith(float n_dot_v, float n_dot_l, float alpha) {
  float k = alpha * 0.5;
  return 0.25 / ((n_dot_v * (1.0 - k) + k) * (n_dot_l * (1.0 - k) + k));
}

vec3 fresnel_schlick(float cos_theta, vec3 f0) {
  float m = 1.0 - cos_theta;
  float m2 = m * m;
  return f0 + (1.0 - f0) * (m2 * m2 * m);
}

vec3 direct_light(vec3 n, vec3 v, vec3 l, vec3 radiance, vec3 albedo, float metallic,
                  float roughness) {
  float n_dot_l = max(dot(n, l), 0.0);
  if (n_dot_l <= 0.0) return vec3(0.0);
  vec3 h = normalize(v + l);
  float n_dot_v = max(dot(n, v), 1e-4);
  float alpha = roughness * roughness;
  vec3 f0 = mix(vec3(0.04), albedo, metallic);
  vec3 f = fresnel_schlick(max(dot(h, v), 0.0), f0);
  vec3 specular = f * distribution_ggx(max(dot(n, h), 0.0), alpha) *
                  visibility_smith(n_dot_v, n_dot_l, alpha);
  vec3 diffuse = (1.0 - f) * (1.0 - metallic) * albedo / PI;
  return (diffuse + specular) * radiance * n_dot_l;
}

// The hardware 2x2 comparison filter, once (hard edges) or at four taps half a texel apart (a
// 3x3-texel footprint, soft edges). Branch-free where it can be: lavapipe shades eight pixels
// at a time on the CPU and runs both sides of a branch it cannot prove uniform. Outside the map the sampler's white
// border reads as lit.
float key_shadow(vec3 world_position, vec3 n, float n_dot_l) {
  // Normal offset keeps grazing surfaces from shadowing themselves.
  float texel = frame.key_color.w;
  vec3 offset_position = world_position + n * (texel * 1.5);
  vec4 clip = frame.light_view_projection * vec4(offset_position, 1.0);
  vec3 coords = clip.xyz / clip.w;
  vec2 uv = coords.xy * 0.5 + 0.5;
  float bias = frame.key_direction.w * (1.0 + 2.0 * (1.0 - n_dot_l));
  float depth = min(coords.z - bias, 1.0);
  if (SHADOW_TAPS == 1u) return texture(shadow_map, vec3(uv, depth));
  vec2 half_texel = 0.5 / vec2(textureSize(shadow_map, 0));
  float lit = texture(shadow_map, vec3(uv + vec2(-half_texel.x, -half_texel.y), depth)) +
              texture(shadow_map, vec3(uv + vec2(half_texel.x, -half_texel.y), depth)) +
              texture(shadow_map, vec3(uv + vec2(-half_texel.x, half_texel.y), depth)) +
              texture(shadow_map, vec3(uv + vec2(half_texel.x, half_texel.y), depth));
  return lit * 0.25;
}

// Narkowicz's fit of the ACES filmic curve.
vec3 tone_map(vec3 x) {
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

void main() {
  vec4 base = draw.base_color;
  vec4 metal_rough = vec4(1.0);
  float occlusion = 1.0;
  vec3 emissive = draw.emissive.rgb;
  if (TEXTURED == 1u) {
    vec4 texel = texture(base_color_map, slot_uv(0, in_uv0, in_uv1));
    base *= vec4(srgb_to_linear(texel.rgb), texel.a);
    metal_rough = texture(metallic_roughness_map, slot_uv(1, in_uv0, in_uv1));
    occlusion = mix(1.0, texture(occlusion_map, slot_uv(3, in_uv0, in_uv1)).r, material.params.y);
    emissive *= srgb_to_linear(texture(emissive_map, slot_uv(4, in_uv0, in_uv1)).rgb);
  }
  // MASK: below the cutoff nothing is drawn; OPAQUE ignores alpha; BLEND keeps it.
  if (ALPHA_MODE == 1u && base.a < material.params.z) discard;
  float alpha = ALPHA_MODE == 2u ? base.a : 1.0;

  vec3 n = normalize(in_world_normal);
  // Nothing is culled (mirrored nodes flip the winding), so a back face is shaded as the
  // side of the surface the camera sees.
  if (!gl_FrontFacing) n = -n;
  if (TEXTURED == 1u && material.params.x != 0.0) {
    vec2 normal_uv = slot_uv(2, in_uv0, in_uv1);
    n = perturbed_normal(n, in_world_position, normal_uv, texture(normal_map, normal_uv).rgb,
                         material.params.x);
  }
  vec3 v = normalize(frame.camera_position.xyz - in_world_position);

  vec3 albedo = base.rgb;
  float metallic = clamp(draw.material.x * metal_rough.b, 0.0, 1.0);
  float roughness = clamp(draw.material.y * metal_rough.g, 0.045, 1.0);

  float key_n_dot_l = max(dot(n, -frame.key_direction.xyz), 0.0);
  vec3 color = direct_light(n, v, -frame.key_direction.xyz, frame.key_color.rgb, albedo,
                            metallic, roughness) *
               key_shadow(in_world_position, n, key_n_dot_l);
  // The fill is soft and dim: diffuse only.
  color += albedo * (1.0 - metallic) / PI * frame.fill_color.rgb *
           max(dot(n, -frame.fill_direction.xyz), 0.0);

  float up = n.y * 0.5 + 0.5;
  vec3 ambient = mix(frame.ground_color.rgb, frame.sky_color.rgb, up);
  vec3 f0 = mix(vec3(0.04), albedo, metallic);
  vec3 r = reflect(-v, n);
  vec3 reflected = mix(frame.ground_color.rgb, frame.sky_color.rgb, r.y * 0.5 + 0.5);
  vec3 f = fresnel_schlick(max(dot(n, v), 0.0), f0) * (1.0 - roughness * 0.7);
  color += (ambient * albedo * (1.0 - metallic) + reflected * f * 2.0) * occlusion;
  color += emissive;

  out_color = vec4(tone_map(color * frame.sky_color.w), alpha);
}
