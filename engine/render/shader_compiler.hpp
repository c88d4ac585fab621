// SPDX-License-Identifier: MIT
#pragma once
// GLSL -> SPIR-V at run time with the glslang library, for shader hot reload (the editor). The
// shipped shaders are still compiled at build time by glslangValidator and embedded
// (render/shaders.hpp); this is library tutti::shader_compiler, linked only by programs that
// reload shaders, so nothing else links glslang.
//
// Same settings as the build's `glslangValidator -V --target-env vulkan1.3 -I<dir>`: Vulkan 1.3
// client, SPIR-V 1.6, default resource limits, no optimisation, no debug info — for the same file
// the words are identical to the embedded build-time SPIR-V (tested).
//
// Includes (`#extension GL_GOOGLE_include_directive : require`, then `#include "x.glsl"`) are
// looked up like glslangValidator does: `"x"` first in the folder of the file that includes it
// (for the top-level source: the folder of `name`, if `name` has one), then in `include_dirs` in
// order; `<x>` only in `include_dirs`. An include cycle, or nesting deeper than
// kMaxIncludeDepth, is a compile error. No file is read except through includes.
//
// Errors are one line naming the file and line of the first error glslang reports, e.g.
// `lit.frag:42: error: 'foo' : undeclared identifier` or, in an included file,
// `/path/to/shaders/frame_data.glsl:7: error: ...`; a missing include reads
// `lit.frag:5: error: '#include' : not found in /path/to/shaders for header name: nope.glsl`.
//
// Thread safety: glslang is initialised once per process (std::call_once) on first use; after
// that, compiles on different threads are independent. glslang is not finalised at exit.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <tutti/core/result.hpp>

namespace tutti::render {

enum class ShaderStage { vertex, tess_control, tess_evaluation, geometry, fragment, compute };

inline constexpr std::size_t kMaxIncludeDepth = 32;

// The stage glslangValidator infers from a file name's extension: .vert .tesc .tese .geom .frag
// .comp; anything else: nullopt.
std::optional<ShaderStage> stage_from_extension(const std::filesystem::path& file);

struct CompiledShader {
  std::vector<std::uint32_t> spirv;  // starts with the SPIR-V magic 0x07230203
  // Every file pulled in by #include, transitively, as found (include dir or includer's folder
  // joined with the header name, lexically normalised); first inclusion order, no duplicates.
  // Watch these together with the source to know when to recompile.
  std::vector<std::filesystem::path> included_files;
};

// `name` labels the source in errors (and gives the folder searched first for its `"x"` includes).
Result<CompiledShader> compile_glsl_shader(std::string_view source, ShaderStage stage,
                                           const std::string& name,
                                           std::span<const std::filesystem::path> include_dirs);

// compile_glsl_shader without the include list.
Result<std::vector<std::uint32_t>> compile_glsl(
    std::string_view source, ShaderStage stage, const std::string& name,
    std::span<const std::filesystem::path> include_dirs);

// Reads `file` (stage from its extension unless given) and compiles it with name = the path as
// given. Errors: the read errors of core/file_io.hpp, `x.txt: unknown shader stage (extension
// .txt)`, or a compile error.
Result<CompiledShader> compile_glsl_file(const std::filesystem::path& file,
                                         std::span<const std::filesystem::path> include_dirs,
                                         std::optional<ShaderStage> stage = std::nullopt);

// The three shaders ModelRenderer uses, compiled from `shader_dir` (also the include dir), for a
// later ModelRenderer::set_shaders(...). `files`: the sources and everything they include, for a
// ShaderWatcher.
struct LitShaders {
  std::vector<std::uint32_t> lit_vert;
  std::vector<std::uint32_t> lit_frag;
  std::vector<std::uint32_t> shadow_vert;
  std::vector<std::filesystem::path> files;
};
Result<LitShaders> reload_lit_shaders(const std::filesystem::path& shader_dir);

}  // namespace tutti::render
