// SPDX-License-Identifier: MIT
// Morph targets, then skinning (glTF order): the world-space position and normal of this vertex.

void deform(vec3 position, vec3 normal, uvec4 joints, vec4 weights, out vec3 world_position,
            out vec3 world_normal) {
  vec3 p = position;
  vec3 n = normal;
  uint local = uint(gl_VertexIndex) - draw.vertex_base;
  for (uint k = 0u; k < draw.morph_count; ++k) {
    float w = morph_weights[draw.morph_weight_base + k];
    if (w != 0.0) {
      uint d = draw.morph_delta_base + 2u * (k * draw.vertex_count + local);
      p += w * morph_deltas[d].xyz;
      n += w * morph_deltas[d + 1u].xyz;
    }
  }
  mat4 m;
  if (draw.skinned != 0u) {
    m = weights.x * matrices[draw.matrix_index + joints.x] +
        weights.y * matrices[draw.matrix_index + joints.y] +
        weights.z * matrices[draw.matrix_index + joints.z] +
        weights.w * matrices[draw.matrix_index + joints.w];
  } else {
    m = matrices[draw.matrix_index];
  }
  world_position = (m * vec4(p, 1.0)).xyz;
  // Our rigs scale uniformly, so the upper 3x3 keeps normals perpendicular.
  world_normal = mat3(m) * n;
}
