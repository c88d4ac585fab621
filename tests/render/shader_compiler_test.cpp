// SPDX-License-Identifier: MIT
// Runtime GLSL -> SPIR-V (render/shader_compiler.hpp) and the polled file watcher
// (render/shader_watcher.hpp). Only the last tests need a Vulkan device.

#include <tutti/render/shader_compiler.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include <tutti/render/pipeline_builder.hpp>
#include "render/render_test_support.hpp"
#include <tutti/render/shader_watcher.hpp>
#include <tutti/render/shaders.hpp>

namespace tutti::render {
namespace {

namespace fs = std::filesystem;

constexpr std::uint32_t kSpirvMagic = 0x07230203;

fs::path shader_dir() { return fs::path(TUTTI_SOURCE_DIR) / "engine/render/shaders"; }

// A fresh, empty folder per test under the system temp dir.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() /
            ("tutti_shader_compiler_" + std::string(info->test_suite_name()) + "_" + info->name());
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path file = path_ / name;
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }

 private:
  fs::path path_;
};

std::vector<std::uint32_t> words(std::span<const std::uint32_t> span) {
  return {span.begin(), span.end()};
}

::testing::AssertionResult is_one_line(const std::string& message) {
  if (message.find('\n') == std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "more than one line: " << message;
}

::testing::AssertionResult starts_with(const std::string& text, const std::string& prefix) {
  if (text.rfind(prefix, 0) == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "\"" << text << "\" does not start with \"" << prefix << "\"";
}

// --- compiling the shipped shaders ---------------------------------------------------------

struct ShippedShader {
  const char* file;
  std::span<const std::uint32_t> (*build_time)();
};

const ShippedShader kShipped[] = {{"lit.vert", shaders::lit_vert},
                                  {"lit.frag", shaders::lit_frag},
                                  {"shadow.vert", shaders::shadow_vert},
                                  {"color_mesh.vert", shaders::color_mesh_vert},
                                  {"color_mesh.frag", shaders::color_mesh_frag}};

// The run-time compile of each shipped shader is word for word what glslangValidator produced
// at build time (the arrays embedded in tutti::render): same glslang, same settings.
TEST(ShaderCompilerTest, ShippedShadersMatchBuildTimeGlslangValidator) {
  const fs::path include_dirs[] = {shader_dir()};
  for (const ShippedShader& shipped : kShipped) {
    SCOPED_TRACE(shipped.file);
    Result<CompiledShader> compiled = compile_glsl_file(shader_dir() / shipped.file, include_dirs);
    ASSERT_TRUE(compiled) << compiled.error().message;
    ASSERT_FALSE(compiled->spirv.empty());
    EXPECT_EQ(compiled->spirv[0], kSpirvMagic);
    const std::vector<std::uint32_t> expected = words(shipped.build_time());
    ASSERT_EQ(compiled->spirv.size(), expected.size());
    EXPECT_TRUE(compiled->spirv == expected) << "SPIR-V differs from the build-time output";
  }
}

// glslang is initialised once (std::call_once) and each compile has its own state, so
// threads can compile at the same time (the first compiles here may race the initialisation).
TEST(ShaderCompilerTest, CompilesOnSeveralThreads) {
  const fs::path include_dirs[] = {shader_dir()};
  std::vector<std::string> failures(4);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < failures.size(); ++t) {
    threads.emplace_back([&, t] {
      const ShippedShader& shipped = kShipped[t % 2];
      for (int round = 0; round < 3; ++round) {
        Result<CompiledShader> compiled =
            compile_glsl_file(shader_dir() / shipped.file, include_dirs);
        if (!compiled) {
          failures[t] = compiled.error().message;
        } else if (compiled->spirv != words(shipped.build_time())) {
          failures[t] = std::string(shipped.file) + ": SPIR-V differs";
        }
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (const std::string& failure : failures) EXPECT_EQ(failure, "");
}

TEST(ShaderCompilerTest, ReportsIncludedFiles) {
  const fs::path include_dirs[] = {shader_dir()};
  Result<CompiledShader> vert = compile_glsl_file(shader_dir() / "lit.vert", include_dirs);
  ASSERT_TRUE(vert) << vert.error().message;
  const std::vector<fs::path> expected = {shader_dir() / "frame_data.glsl",
                                          shader_dir() / "deform.glsl"};
  EXPECT_EQ(vert->included_files, expected);

  Result<CompiledShader> color = compile_glsl_file(shader_dir() / "color_mesh.vert", include_dirs);
  ASSERT_TRUE(color) << color.error().message;
  EXPECT_TRUE(color->included_files.empty());
}

TEST(ShaderCompilerTest, CompileFromSourceString) {
  const std::string source =
      "#version 450\n"
      "layout(location = 0) out vec4 color;\n"
      "void main() { color = vec4(1.0, 0.5, 0.25, 1.0); }\n";
  Result<std::vector<std::uint32_t>> spirv =
      compile_glsl(source, ShaderStage::fragment, "inline.frag", {});
  ASSERT_TRUE(spirv) << spirv.error().message;
  ASSERT_GE(spirv->size(), 5u);  // the header alone is 5 words
  EXPECT_EQ((*spirv)[0], kSpirvMagic);
  EXPECT_EQ((*spirv)[1], 0x00010600u);  // SPIR-V 1.6, as --target-env vulkan1.3

  // The stage really is passed through: a compute shader has no outputs.
  Result<std::vector<std::uint32_t>> as_compute =
      compile_glsl(source, ShaderStage::compute, "inline.comp", {});
  ASSERT_FALSE(as_compute);
  EXPECT_EQ(as_compute.error().message,
            "inline.comp:2: error: 'out' : global storage output qualifier cannot be used in a "
            "compute shader");
}

TEST(ShaderCompilerTest, LitShadersForModelRenderer) {
  Result<LitShaders> lit = reload_lit_shaders(shader_dir());
  ASSERT_TRUE(lit) << lit.error().message;
  EXPECT_TRUE(lit->lit_vert == words(shaders::lit_vert()));
  EXPECT_TRUE(lit->lit_frag == words(shaders::lit_frag()));
  EXPECT_TRUE(lit->shadow_vert == words(shaders::shadow_vert()));
  const std::vector<fs::path> expected = {
      shader_dir() / "frame_data.glsl", shader_dir() / "deform.glsl", shader_dir() / "lit.vert",
      shader_dir() / "material.glsl",   shader_dir() / "lit.frag",    shader_dir() / "shadow.vert"};
  EXPECT_EQ(lit->files, expected);

  TempDir empty;
  Result<LitShaders> missing = reload_lit_shaders(empty.path());
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().message, (empty.path() / "lit.vert").string() + ": no such file");
}

// --- errors: one line, file and line ---------------------------------------------------------

TEST(ShaderCompilerErrorTest, SyntaxErrorNamesFileAndLine) {
  const std::string source =
      "#version 450\n"
      "void main() {\n"
      "  float x = ;\n"
      "}\n";
  Result<std::vector<std::uint32_t>> spirv =
      compile_glsl(source, ShaderStage::fragment, "broken.frag", {});
  ASSERT_FALSE(spirv);
  const std::string& message = spirv.error().message;
  EXPECT_TRUE(is_one_line(message));
  // glslang's wording, double space included.
  EXPECT_EQ(message, "broken.frag:3: error: '' :  syntax error, unexpected SEMICOLON");
}

TEST(ShaderCompilerErrorTest, UndeclaredIdentifierIsTheFirstErrorOnly) {
  const std::string source =
      "#version 450\n"
      "layout(location = 0) out vec4 color;\n"
      "void main() {\n"
      "  color = vec4(foo);\n"
      "  color = vec4(bar);\n"
      "}\n";
  Result<std::vector<std::uint32_t>> spirv =
      compile_glsl(source, ShaderStage::fragment, "lit.frag", {});
  ASSERT_FALSE(spirv);
  EXPECT_EQ(spirv.error().message, "lit.frag:4: error: 'foo' : undeclared identifier");
}

TEST(ShaderCompilerErrorTest, ErrorInIncludedFileNamesThatFile) {
  TempDir dir;
  dir.write("helper.glsl", "// helper\nfloat helper() { return missing_thing; }\n");
  const std::string source =
      "#version 450\n"
      "#extension GL_GOOGLE_include_directive : require\n"
      "#include \"helper.glsl\"\n"
      "void main() {}\n";
  const fs::path include_dirs[] = {dir.path()};
  Result<std::vector<std::uint32_t>> spirv =
      compile_glsl(source, ShaderStage::vertex, "main.vert", include_dirs);
  ASSERT_FALSE(spirv);
  EXPECT_EQ(spirv.error().message, (dir.path() / "helper.glsl").string() +
                                       ":2: error: 'missing_thing' : undeclared identifier");
}

TEST(ShaderCompilerErrorTest, MissingIncludeNamesTheInclude) {
  TempDir dir;
  const std::string source =
      "#version 450\n"
      "#extension GL_GOOGLE_include_directive : require\n"
      "#include \"nope.glsl\"\n"
      "void main() {}\n";
  const fs::path include_dirs[] = {dir.path()};
  Result<std::vector<std::uint32_t>> spirv =
      compile_glsl(source, ShaderStage::vertex, "main.vert", include_dirs);
  ASSERT_FALSE(spirv);
  EXPECT_EQ(spirv.error().message, "main.vert:3: error: '#include' : not found in " +
                                       dir.path().string() + " for header name: nope.glsl");
}

TEST(ShaderCompilerErrorTest, IncludeWithoutTheExtensionIsAnError) {
  TempDir dir;
  dir.write("helper.glsl", "float helper() { return 1.0; }\n");
  const fs::path include_dirs[] = {dir.path()};
  Result<std::vector<std::uint32_t>> spirv =
      compile_glsl("#version 450\n#include \"helper.glsl\"\nvoid main() {}\n", ShaderStage::vertex,
                   "main.vert", include_dirs);
  ASSERT_FALSE(spirv);
  EXPECT_TRUE(is_one_line(spirv.error().message));
  EXPECT_TRUE(starts_with(spirv.error().message, "main.vert:2: error: '#include' : "));
  EXPECT_NE(spirv.error().message.find("GL_GOOGLE_include_directive"), std::string::npos)
      << spirv.error().message;
}

TEST(ShaderCompilerErrorTest, IncludeCycleIsAnErrorNotAHang) {
  TempDir dir;
  const std::string header = "#extension GL_GOOGLE_include_directive : require\n";
  const fs::path a = dir.write("a.glsl", "#include \"b.glsl\"\n");
  const fs::path b = dir.write("b.glsl", "\n#include \"a.glsl\"\n");
  const fs::path include_dirs[] = {dir.path()};
  Result<std::vector<std::uint32_t>> spirv =
      compile_glsl("#version 450\n" + header + "#include \"a.glsl\"\nvoid main() {}\n",
                   ShaderStage::vertex, "main.vert", include_dirs);
  ASSERT_FALSE(spirv);
  EXPECT_EQ(spirv.error().message,
            b.string() + ":2: error: '#include' : include cycle (main.vert -> " + a.string() +
                " -> " + b.string() + " -> " + a.string() + ") for header name: a.glsl");

  // A file that includes itself, compiled as a file: the top-level file is part of the chain.
  const fs::path self = dir.write(
      "self.vert", "#version 450\n" + header + "#include \"self.vert\"\nvoid main() {}\n");
  Result<CompiledShader> compiled = compile_glsl_file(self, include_dirs);
  ASSERT_FALSE(compiled);
  EXPECT_TRUE(starts_with(compiled.error().message,
                          self.string() + ":3: error: '#include' : include cycle ("));
}

TEST(ShaderCompilerErrorTest, IncludeNestingIsLimited) {
  TempDir dir;
  // level_k.glsl includes level_{k+1}.glsl; the last one defines a function.
  const auto make_chain = [&](std::size_t levels) {
    for (std::size_t k = 1; k < levels; ++k) {
      dir.write("level_" + std::to_string(k) + ".glsl",
                "#include \"level_" + std::to_string(k + 1) + ".glsl\"\n");
    }
    dir.write("level_" + std::to_string(levels) + ".glsl", "float deepest() { return 1.0; }\n");
  };
  const std::string source =
      "#version 450\n"
      "#extension GL_GOOGLE_include_directive : require\n"
      "#include \"level_1.glsl\"\n"
      "void main() { gl_Position = vec4(deepest()); }\n";
  const fs::path include_dirs[] = {dir.path()};

  make_chain(kMaxIncludeDepth);
  Result<CompiledShader> ok =
      compile_glsl_shader(source, ShaderStage::vertex, "main.vert", include_dirs);
  ASSERT_TRUE(ok) << ok.error().message;
  EXPECT_EQ(ok->included_files.size(), kMaxIncludeDepth);

  fs::remove_all(dir.path());
  make_chain(kMaxIncludeDepth + 1);
  Result<CompiledShader> deep =
      compile_glsl_shader(source, ShaderStage::vertex, "main.vert", include_dirs);
  ASSERT_FALSE(deep);
  EXPECT_EQ(deep.error().message,
            (dir.path() / ("level_" + std::to_string(kMaxIncludeDepth) + ".glsl")).string() +
                ":1: error: '#include' : nested deeper than 32 includes for header name: "
                "level_33.glsl");
}

// `"x"` is looked up next to the including file before the include dirs (like
// glslangValidator and C compilers); `<x>` only in the include dirs.
TEST(ShaderCompilerTest, LocalIncludesSearchTheIncludersFolderFirst) {
  TempDir dir;
  dir.write("lib/outer.glsl", "#include \"inner.glsl\"\n");
  dir.write("lib/inner.glsl", "float inner() { return 2.0; }\n");
  dir.write("inc/inner.glsl", "this does not compile\n");
  dir.write("inc/system.glsl", "float from_system() { return 3.0; }\n");
  const fs::path include_dirs[] = {dir.path() / "inc", dir.path() / "lib"};
  const std::string source =
      "#version 450\n"
      "#extension GL_GOOGLE_include_directive : require\n"
      "#include \"outer.glsl\"\n"
      "#include <system.glsl>\n"
      "void main() { gl_Position = vec4(inner() + from_system()); }\n";
  Result<CompiledShader> compiled =
      compile_glsl_shader(source, ShaderStage::vertex, "main.vert", include_dirs);
  ASSERT_TRUE(compiled) << compiled.error().message;
  const std::vector<fs::path> expected = {
      dir.path() / "lib/outer.glsl", dir.path() / "lib/inner.glsl", dir.path() / "inc/system.glsl"};
  EXPECT_EQ(compiled->included_files, expected);

  // <x> does not look next to the includer: lib/ alone has no system.glsl.
  const fs::path lib_only[] = {dir.path() / "lib"};
  Result<CompiledShader> system = compile_glsl_shader(
      "#version 450\n#extension GL_GOOGLE_include_directive : require\n"
      "#include <system.glsl>\nvoid main() {}\n",
      ShaderStage::vertex, (dir.path() / "inc/main.vert").string(), lib_only);
  ASSERT_FALSE(system);
  EXPECT_NE(system.error().message.find("for header name: system.glsl"), std::string::npos)
      << system.error().message;
}

TEST(ShaderCompilerErrorTest, LinkErrorNamesTheShader) {
  Result<std::vector<std::uint32_t>> spirv =
      compile_glsl("#version 450\nvoid not_main() {}\n", ShaderStage::fragment, "nomain.frag", {});
  ASSERT_FALSE(spirv);
  EXPECT_EQ(spirv.error().message,
            "nomain.frag: error: Linking fragment stage: Missing entry point: Each stage requires "
            "one entry point");
}

TEST(ShaderCompilerErrorTest, FileErrors) {
  TempDir dir;
  const fs::path text = dir.write("notes.txt", "#version 450\nvoid main() {}\n");
  Result<CompiledShader> unknown = compile_glsl_file(text, {});
  ASSERT_FALSE(unknown);
  EXPECT_EQ(unknown.error().message, text.string() + ": unknown shader stage (extension .txt)");
  // An explicit stage overrides the extension.
  Result<CompiledShader> explicit_stage = compile_glsl_file(text, {}, ShaderStage::vertex);
  EXPECT_TRUE(explicit_stage) << explicit_stage.error().message;

  Result<CompiledShader> missing = compile_glsl_file(dir.path() / "missing.frag", {});
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().message, (dir.path() / "missing.frag").string() + ": no such file");
}

TEST(ShaderCompilerTest, StageFromExtension) {
  EXPECT_EQ(stage_from_extension("a.vert"), ShaderStage::vertex);
  EXPECT_EQ(stage_from_extension("a.tesc"), ShaderStage::tess_control);
  EXPECT_EQ(stage_from_extension("a.tese"), ShaderStage::tess_evaluation);
  EXPECT_EQ(stage_from_extension("a.geom"), ShaderStage::geometry);
  EXPECT_EQ(stage_from_extension("dir/a.frag"), ShaderStage::fragment);
  EXPECT_EQ(stage_from_extension("a.comp"), ShaderStage::compute);
  EXPECT_EQ(stage_from_extension("a.glsl"), std::nullopt);
  EXPECT_EQ(stage_from_extension("vert"), std::nullopt);
}

// --- the watcher ---------------------------------------------------------------------------

// Sets a file's mtime `seconds` after its current one: deterministic, unlike waiting for the
// clock to tick past the file system's timestamp granularity.
void bump_mtime(const fs::path& file, int seconds) {
  fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(seconds));
}

TEST(ShaderWatcherTest, NothingChangedReportsNothing) {
  TempDir dir;
  const fs::path a = dir.write("a.frag", "aaaa");
  const fs::path b = dir.write("b.glsl", "bbbb");
  const fs::path files[] = {a, b};
  ShaderWatcher watcher(files);
  EXPECT_FALSE(watcher.changed());
  EXPECT_TRUE(watcher.poll().empty());
  EXPECT_TRUE(watcher.poll().empty());
  EXPECT_EQ(watcher.files(), std::vector<fs::path>(std::begin(files), std::end(files)));
}

TEST(ShaderWatcherTest, RewrittenFileIsReportedOnce) {
  TempDir dir;
  const fs::path a = dir.write("a.frag", "aaaa");
  const fs::path b = dir.write("b.glsl", "bbbb");
  const fs::path files[] = {a, b};
  ShaderWatcher watcher(files);
  dir.write("b.glsl", "BBBB");  // same size: only the mtime tells
  bump_mtime(b, 5);
  EXPECT_TRUE(watcher.changed());
  EXPECT_TRUE(watcher.changed());  // changed() records nothing
  EXPECT_EQ(watcher.poll(), std::vector<fs::path>{b});
  EXPECT_FALSE(watcher.changed());
  EXPECT_TRUE(watcher.poll().empty());
}

TEST(ShaderWatcherTest, SizeChangeWithTheSameMtimeIsReported) {
  TempDir dir;
  const fs::path a = dir.write("a.frag", "aaaa");
  const fs::file_time_type mtime = fs::last_write_time(a);
  ShaderWatcher watcher;
  watcher.watch(a);
  dir.write("a.frag", "aaaaaaaa");
  fs::last_write_time(a, mtime);
  EXPECT_EQ(watcher.poll(), std::vector<fs::path>{a});
}

TEST(ShaderWatcherTest, VanishingAndReappearingFilesAreReported) {
  TempDir dir;
  const fs::path a = dir.write("a.frag", "aaaa");
  const fs::path later = dir.path() / "later.glsl";
  const fs::path files[] = {a, later};
  ShaderWatcher watcher(files);
  EXPECT_TRUE(watcher.poll().empty());  // a missing file is a state, not a change
  fs::remove(a);
  EXPECT_EQ(watcher.poll(), std::vector<fs::path>{a});
  dir.write("later.glsl", "x");
  dir.write("a.frag", "aaaa");
  EXPECT_EQ(watcher.poll(), (std::vector<fs::path>{a, later}));
  EXPECT_TRUE(watcher.poll().empty());

  watcher.watch(a);  // already watched: no duplicate
  EXPECT_EQ(watcher.files().size(), 2u);
  watcher.clear();
  EXPECT_TRUE(watcher.files().empty());
}

// The hot-reload loop: compile, watch the shader and its includes, edit an include, see the
// change, recompile to different SPIR-V.
TEST(ShaderWatcherTest, ReloadAfterAnIncludedFileChanges) {
  TempDir dir;
  const fs::path include = dir.write("tint.glsl", "const vec4 kTint = vec4(1.0);\n");
  const fs::path shader = dir.write("tinted.frag",
                                    "#version 450\n"
                                    "#extension GL_GOOGLE_include_directive : require\n"
                                    "#include \"tint.glsl\"\n"
                                    "layout(location = 0) out vec4 color;\n"
                                    "void main() { color = kTint; }\n");
  const fs::path include_dirs[] = {dir.path()};
  Result<CompiledShader> first = compile_glsl_file(shader, include_dirs);
  ASSERT_TRUE(first) << first.error().message;
  ASSERT_EQ(first->included_files, std::vector<fs::path>{include});

  ShaderWatcher watcher;
  watcher.watch(shader);
  watcher.watch(first->included_files);
  EXPECT_TRUE(watcher.poll().empty());

  dir.write("tint.glsl", "const vec4 kTint = vec4(0.5);\n");
  bump_mtime(include, 5);
  EXPECT_EQ(watcher.poll(), std::vector<fs::path>{include});
  Result<CompiledShader> second = compile_glsl_file(shader, include_dirs);
  ASSERT_TRUE(second) << second.error().message;
  EXPECT_NE(second->spirv, first->spirv);
  EXPECT_TRUE(watcher.poll().empty());
}

// --- the SPIR-V works on a device ----------------------------------------------------------

class ShaderCompilerVulkanTest : public test::VulkanTest {};

// Shader modules from the run-time SPIR-V; the validation layer runs spirv-val on each module
// at creation, and the fixture fails the test on any message.
TEST_F(ShaderCompilerVulkanTest, RuntimeSpirvMakesValidShaderModules) {
  const fs::path include_dirs[] = {shader_dir()};
  for (const ShippedShader& shipped : kShipped) {
    SCOPED_TRACE(shipped.file);
    Result<CompiledShader> compiled = compile_glsl_file(shader_dir() / shipped.file, include_dirs);
    ASSERT_TRUE(compiled) << compiled.error().message;
    Result<DeviceHandle<VkShaderModule>> module =
        create_shader_module(context().device(), compiled->spirv);
    ASSERT_TRUE(module) << module.error().message;
    EXPECT_NE(module->get(), VK_NULL_HANDLE);
  }
  EXPECT_EQ(log_->size(), 0u);
}

// The check above can fail: the layer does validate module SPIR-V (a wrong magic number here).
TEST_F(ShaderCompilerVulkanTest, BrokenSpirvIsRefusedBeforeTheDriverSeesIt) {
  Result<std::vector<std::uint32_t>> spirv =
      compile_glsl("#version 450\nvoid main() {}\n", ShaderStage::vertex, "empty.vert", {});
  ASSERT_TRUE(spirv) << spirv.error().message;
  (*spirv)[0] = 0x12345678;
  Result<DeviceHandle<VkShaderModule>> module = create_shader_module(context().device(), *spirv);
  ASSERT_FALSE(module);
  EXPECT_NE(module.error().message.find("not SPIR-V"), std::string::npos) << module.error().message;
  const std::vector<std::uint32_t> too_short = {0x07230203};
  EXPECT_FALSE(create_shader_module(context().device(), too_short));
  // The fixture checks that the validation layer saw nothing.
}

}  // namespace
}  // namespace tutti::render
