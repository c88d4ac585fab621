// SPDX-License-Identifier: MIT
#include <tutti/render/shader_compiler.hpp>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <algorithm>
#include <cctype>
#include <memory>
#include <mutex>
#include <system_error>
#include <utility>

#include <tutti/core/file_io.hpp>

namespace tutti::render {

namespace fs = std::filesystem;

namespace {

// Shader sources and includes are small; a bigger file is a mistake, not a shader.
constexpr std::size_t kMaxShaderBytes = std::size_t{16} << 20;

void initialize_glslang_once() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

EShLanguage to_glslang(ShaderStage stage) {
  switch (stage) {
    case ShaderStage::vertex:
      return EShLangVertex;
    case ShaderStage::tess_control:
      return EShLangTessControl;
    case ShaderStage::tess_evaluation:
      return EShLangTessEvaluation;
    case ShaderStage::geometry:
      return EShLangGeometry;
    case ShaderStage::fragment:
      return EShLangFragment;
    case ShaderStage::compute:
      return EShLangCompute;
  }
  return EShLangVertex;
}

std::string trim(std::string_view text) {
  const auto is_space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
  return std::string(text);
}

// Where `rest` (a log line after "ERROR: ") has the form "<file>:<line>: <message>", the length
// of "<file>:<line>"; else 0. The first ": " preceded by ":<digits>" ends the location.
std::size_t location_length(std::string_view rest) {
  for (std::size_t colon = rest.find(": "); colon != std::string_view::npos;
       colon = rest.find(": ", colon + 1)) {
    std::size_t digits = colon;
    while (digits > 0 && std::isdigit(static_cast<unsigned char>(rest[digits - 1])) != 0) {
      --digits;
    }
    if (digits < colon && digits >= 2 && rest[digits - 1] == ':') return colon;
  }
  return 0;
}

// glslang's info log ("ERROR: lit.frag:42: 'foo' : undeclared identifier \nERROR: lit.frag:42:
// '' : compilation terminated \nERROR: 2 compilation errors.  No code generated.") as one line
// in tutti's form: "lit.frag:42: error: 'foo' : undeclared identifier". Only the first error is
// kept: the rest usually follow from it.
std::string first_error(std::string_view log, const std::string& name) {
  std::string_view remaining = log;
  while (!remaining.empty()) {
    const std::size_t end = remaining.find('\n');
    const std::string_view line = remaining.substr(0, end);
    remaining = end == std::string_view::npos ? std::string_view{} : remaining.substr(end + 1);
    constexpr std::string_view kError = "ERROR: ";
    if (line.substr(0, kError.size()) != kError) continue;
    const std::string_view rest = line.substr(kError.size());
    if (const std::size_t at = location_length(rest); at > 0) {
      return std::string(rest.substr(0, at)) + ": error: " + trim(rest.substr(at + 2));
    }
    return name + ": error: " + trim(rest);
  }
  // No "ERROR:" line (should not happen): the whole log, folded onto one line.
  std::string folded;
  for (char c : trim(log)) folded += c == '\n' ? ' ' : c;
  return name + ": error: " + (folded.empty() ? std::string("compilation failed") : folded);
}

// glslang's hook for #include: reads files from the includer's folder and the include dirs,
// refuses cycles and runaway nesting, and records what it included.
class FileIncluder final : public glslang::TShader::Includer {
 public:
  FileIncluder(std::span<const fs::path> include_dirs, const std::string& root_name)
      : include_dirs_(include_dirs), root_name_(root_name) {
    std::error_code ec;
    const fs::path root = fs::weakly_canonical(root_name, ec);
    if (!ec && fs::is_regular_file(root, ec)) root_ = root;
  }

  // `"x"`: glslang calls this first and, when it returns null, includeSystem. So this one does
  // the whole lookup (includer's folder, then include dirs); a failure's message is handed to
  // the includeSystem call that follows, which reports it.
  IncludeResult* includeLocal(const char* header_name, const char* includer_name,
                              std::size_t depth) override {
    std::vector<fs::path> dirs;
    const fs::path includer_dir = fs::path(includer_name).parent_path();
    if (!includer_dir.empty()) dirs.push_back(includer_dir);
    dirs.insert(dirs.end(), include_dirs_.begin(), include_dirs_.end());
    IncludeResult* result = resolve(header_name, dirs, depth);
    if (!result->headerName.empty()) return result;
    deferred_error_ = std::string(result->headerData, result->headerLength);
    releaseInclude(result);
    return nullptr;
  }

  // `<x>`, or the second half of a failed `"x"`.
  IncludeResult* includeSystem(const char* header_name, const char* /*includer_name*/,
                               std::size_t depth) override {
    if (deferred_error_) {
      IncludeResult* result = failure(std::move(*deferred_error_));
      deferred_error_.reset();
      return result;
    }
    return resolve(header_name, std::vector<fs::path>(include_dirs_.begin(), include_dirs_.end()),
                   depth);
  }

  void releaseInclude(IncludeResult* result) override {
    if (result == nullptr) return;
    delete static_cast<std::string*>(result->userData);
    delete result;
  }

  std::vector<fs::path> take_included_files() { return std::move(included_files_); }

 private:
  // The text lives in userData until glslang releases the result; an empty headerName says
  // "failed, headerData is the reason".
  static IncludeResult* make_result(std::string header_name, std::string text) {
    auto owned = std::make_unique<std::string>(std::move(text));
    auto* result =
        new IncludeResult(std::move(header_name), owned->data(), owned->size(), owned.get());
    owned.release();
    return result;
  }
  static IncludeResult* failure(std::string reason) { return make_result("", std::move(reason)); }

  IncludeResult* resolve(const std::string& header_name, const std::vector<fs::path>& dirs,
                         std::size_t depth) {
    if (depth > kMaxIncludeDepth) {
      return failure("nested deeper than " + std::to_string(kMaxIncludeDepth) + " includes");
    }
    for (const fs::path& dir : dirs) {
      const fs::path path = (dir / header_name).lexically_normal();
      std::error_code ec;
      if (!fs::is_regular_file(path, ec)) continue;
      const fs::path canonical = fs::weakly_canonical(path, ec);
      // open_[i] is the file at include depth i + 1; the includer of this one is at depth - 1.
      open_.resize(std::min(open_.size(), depth - 1));
      const bool open = std::any_of(open_.begin(), open_.end(),
                                    [&](const auto& entry) { return entry.first == canonical; });
      if (open || canonical == root_) {
        std::string chain = root_name_ + " -> ";
        for (const auto& entry : open_) chain += entry.second.string() + " -> ";
        return failure("include cycle (" + chain + path.string() + ")");
      }
      Result<std::vector<std::uint8_t>> bytes = read_file_bytes(path, kMaxShaderBytes);
      if (!bytes) return failure(bytes.error().message);
      open_.emplace_back(canonical, path);
      if (std::find(included_files_.begin(), included_files_.end(), path) ==
          included_files_.end()) {
        included_files_.push_back(path);
      }
      return make_result(path.string(), std::string(bytes->begin(), bytes->end()));
    }
    std::string searched;
    for (const fs::path& dir : dirs) searched += (searched.empty() ? "" : ", ") + dir.string();
    return failure(searched.empty() ? std::string("no include directories given")
                                    : "not found in " + searched);
  }

  std::span<const fs::path> include_dirs_;
  std::string root_name_;
  fs::path root_;  // canonical path of the top-level file, if it is one
  std::vector<std::pair<fs::path, fs::path>> open_;  // (canonical, as found) per open include
  std::vector<fs::path> included_files_;
  std::optional<std::string> deferred_error_;
};

}  // namespace

std::optional<ShaderStage> stage_from_extension(const fs::path& file) {
  const std::string extension = file.extension().string();
  if (extension == ".vert") return ShaderStage::vertex;
  if (extension == ".tesc") return ShaderStage::tess_control;
  if (extension == ".tese") return ShaderStage::tess_evaluation;
  if (extension == ".geom") return ShaderStage::geometry;
  if (extension == ".frag") return ShaderStage::fragment;
  if (extension == ".comp") return ShaderStage::compute;
  return std::nullopt;
}

Result<CompiledShader> compile_glsl_shader(std::string_view source, ShaderStage stage,
                                           const std::string& name,
                                           std::span<const fs::path> include_dirs) {
  initialize_glslang_once();
  const EShLanguage language = to_glslang(stage);

  // glslangValidator -V --target-env vulkan1.3: client input semantics 100, Vulkan 1.3,
  // SPIR-V 1.6, SPIR-V and Vulkan rules, default version 100 (our shaders say #version 450).
  glslang::TShader shader(language);
  const char* text = source.data();
  const int length = static_cast<int>(source.size());
  const char* names[] = {name.c_str()};
  shader.setStringsWithLengthsAndNames(&text, &length, names, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_3);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_6);
  const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);

  FileIncluder includer(include_dirs, name);
  if (!shader.parse(GetDefaultResources(), 100, false, messages, includer)) {
    return Error{first_error(shader.getInfoLog(), name)};
  }
  // Declared after the shader it points to, so destroyed first.
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) return Error{first_error(program.getInfoLog(), name)};

  CompiledShader compiled;
  spv::SpvBuildLogger logger;
  glslang::SpvOptions options;  // defaults = glslangValidator's: no debug info, no optimiser
  glslang::GlslangToSpv(*program.getIntermediate(language), compiled.spirv, &logger, &options);
  if (compiled.spirv.empty()) {
    return Error{name + ": error: SPIR-V generation failed: " + trim(logger.getAllMessages())};
  }
  compiled.included_files = includer.take_included_files();
  return compiled;
}

Result<std::vector<std::uint32_t>> compile_glsl(std::string_view source, ShaderStage stage,
                                                const std::string& name,
                                                std::span<const fs::path> include_dirs) {
  Result<CompiledShader> compiled = compile_glsl_shader(source, stage, name, include_dirs);
  if (!compiled) return compiled.error();
  return std::move(compiled->spirv);
}

Result<CompiledShader> compile_glsl_file(const fs::path& file,
                                         std::span<const fs::path> include_dirs,
                                         std::optional<ShaderStage> stage) {
  if (!stage) stage = stage_from_extension(file);
  if (!stage) {
    return Error{file.string() + ": unknown shader stage (extension " +
                 (file.extension().empty() ? std::string("none") : file.extension().string()) +
                 ")"};
  }
  Result<std::vector<std::uint8_t>> bytes = read_file_bytes(file, kMaxShaderBytes);
  if (!bytes) return bytes.error();
  const std::string source(bytes->begin(), bytes->end());
  return compile_glsl_shader(source, *stage, file.string(), include_dirs);
}

Result<LitShaders> reload_lit_shaders(const fs::path& shader_dir) {
  const fs::path include_dirs[] = {shader_dir};
  LitShaders shaders;
  const std::pair<const char*, std::vector<std::uint32_t>*> outputs[] = {
      {"lit.vert", &shaders.lit_vert},
      {"lit.frag", &shaders.lit_frag},
      {"shadow.vert", &shaders.shadow_vert}};
  for (const auto& [file_name, spirv] : outputs) {
    const fs::path file = shader_dir / file_name;
    Result<CompiledShader> compiled = compile_glsl_file(file, include_dirs);
    if (!compiled) return compiled.error();
    *spirv = std::move(compiled->spirv);
    compiled->included_files.push_back(file);
    for (fs::path& path : compiled->included_files) {
      if (std::find(shaders.files.begin(), shaders.files.end(), path) == shaders.files.end()) {
        shaders.files.push_back(std::move(path));
      }
    }
  }
  return shaders;
}

}  // namespace tutti::render
