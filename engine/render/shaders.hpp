// SPDX-License-Identifier: MIT
#pragma once
// SPIR-V of the shaders in engine/render/shaders/, compiled by glslangValidator at build time and
// embedded in the library (no file lookup at run time).

#include <cstdint>
#include <span>

namespace tutti::render::shaders {

std::span<const std::uint32_t> color_mesh_vert();
std::span<const std::uint32_t> color_mesh_frag();
std::span<const std::uint32_t> lit_vert();
std::span<const std::uint32_t> lit_frag();
std::span<const std::uint32_t> shadow_vert();

}  // namespace tutti::render::shaders
