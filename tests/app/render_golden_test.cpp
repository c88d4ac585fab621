// SPDX-License-Identifier: MIT
// Golden images: the piano close-up, the brass-quartet wide shot and a textured character (a
// Blender-made fixture with a PNG checker on its base colour, tests/data/characters/) rendered by
// `tutti render --still` on lavapipe, compared with the PNGs committed in tests/data/golden/. Tolerance: a
// channel may differ by at most 24 codes, on at most 0.5 % of the pixels (rasterisation rules at
// edges, LLVM versions), and the mean absolute difference over all channels must stay below 0.5
// codes. Regenerate after an intended change with TUTTI_UPDATE_GOLDEN=1 (the test then writes
// the new PNGs into the source tree and fails, so an update is never silent).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include <nlohmann/json.hpp>

#include <tutti/cli/render_command.hpp>
#include <tutti/render/vulkan_context.hpp>

std::vector<std::uint8_t> decode_png_for_test(const std::vector<std::uint8_t>& png, int& width,
                                              int& height);

namespace tutti::cli {
namespace {

std::vector<std::uint8_t> read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Golden {
  const char* scene;
  const char* time_s;
  const char* file;
};

class RenderGoldenTest : public ::testing::TestWithParam<Golden> {};

// Renders `o` (a still) and compares it with tests/data/golden/`file`.
void expect_golden(RenderOptions o, const char* file) {
  const std::filesystem::path source(TUTTI_SOURCE_DIR);
  const std::filesystem::path out =
      std::filesystem::temp_directory_path() /
      ("tutti-golden-" + std::to_string(getpid()) + "-" + file);
  o.output = out;
  o.size = "640x360";
  o.validate = true;  // any validation message fails the render
  o.progress = false;
  std::ostringstream stdout_text;
  std::ostringstream stderr_text;
  ASSERT_EQ(run_render(o, stdout_text, stderr_text), 0) << stderr_text.str();
  const std::filesystem::path committed = source / "tests" / "data" / "golden" / file;
  if (const char* update = std::getenv("TUTTI_UPDATE_GOLDEN");
      update != nullptr && *update == '1') {
    std::filesystem::create_directories(committed.parent_path());
    std::filesystem::copy_file(out, committed, std::filesystem::copy_options::overwrite_existing);
    std::filesystem::remove(out);
    FAIL() << "updated " << committed << " (TUTTI_UPDATE_GOLDEN=1)";
  }
  int width = 0;
  int height = 0;
  int expected_width = 0;
  int expected_height = 0;
  const std::vector<std::uint8_t> got = decode_png_for_test(read_file(out), width, height);
  const std::vector<std::uint8_t> expected =
      decode_png_for_test(read_file(committed), expected_width, expected_height);
  std::filesystem::remove(out);
  ASSERT_FALSE(expected.empty()) << "no golden image " << committed;
  ASSERT_EQ(width, expected_width);
  ASSERT_EQ(height, expected_height);
  ASSERT_EQ(got.size(), expected.size());
  std::size_t off_pixels = 0;
  double total = 0.0;
  int worst = 0;
  for (std::size_t p = 0; p < got.size() / 4; ++p) {
    int pixel_worst = 0;
    for (std::size_t c = 0; c < 3; ++c) {
      const int d = std::abs(int(got[p * 4 + c]) - int(expected[p * 4 + c]));
      total += d;
      pixel_worst = std::max(pixel_worst, d);
    }
    worst = std::max(worst, pixel_worst);
    if (pixel_worst > 24) ++off_pixels;
  }
  const double pixels = static_cast<double>(got.size() / 4);
  const double mean = total / (pixels * 3);
  EXPECT_LE(static_cast<double>(off_pixels), 0.005 * pixels)
      << off_pixels << " pixels differ by more than 24 codes (worst " << worst << ")";
  EXPECT_LT(mean, 0.5) << "mean absolute difference " << mean << " codes";
  std::printf("%s: mean difference %.4f codes, worst %d, %zu pixels over 24\n", file, mean,
              worst, off_pixels);
}

TEST_P(RenderGoldenTest, MatchesTheCommittedImage) {
  auto devices = render::list_vulkan_devices();
  if (!devices || devices->empty()) GTEST_SKIP() << "SKIPPED: no Vulkan device";
  const Golden& golden = GetParam();
  RenderOptions o;
  o.scene = std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "scenes" / golden.scene;
  o.still = golden.time_s;
  expect_golden(o, golden.file);
}

// A user's character with a texture renders with it: the Blender fixture's red and cream checker
// (8 squares round each tube), no mapping file, playing Trumpet 1 of the quartet.
TEST(RenderGolden, ATexturedCharacterShowsItsTexture) {
  auto devices = render::list_vulkan_devices();
  if (!devices || devices->empty()) GTEST_SKIP() << "SKIPPED: no Vulkan device";
  if (std::system("command -v blender > /dev/null 2>&1") != 0) GTEST_SKIP() << "no blender";
  const std::filesystem::path source(TUTTI_SOURCE_DIR);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("tutti-golden-characters-" + std::to_string(getpid()));
  const std::string make = "blender -b --factory-startup --python '" +
                           (source / "tests/data/characters/make_fixtures.py").string() +
                           "' -- '" + dir.string() + "' > /dev/null 2>&1";
  ASSERT_EQ(std::system(make.c_str()), 0) << make;
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(source / "content/scenes/quartet.json"));
  scene["music"] = (source / "content/music/quartet.musicxml").string();
  nlohmann::json player = scene["performers"][0];
  player["character"] = "rigify_a_textured.glb";
  scene["performers"] = nlohmann::json::array({player});
  const auto& at = player["position_m"];
  const double x = at[0].get<double>(), z = at[2].get<double>();
  scene["cameras"] = nlohmann::json::array(
      {{{"name", "front"}, {"position_m", {x + 0.4, 1.7, z + 2.4}}, {"target_m", {x, 1.35, z}},
        {"fov_deg", 40}}});
  scene.erase("shots");
  std::ofstream(dir / "textured.json") << scene.dump(1);
  RenderOptions o;
  o.scene = dir / "textured.json";
  o.camera = "front";
  o.still = "4";
  expect_golden(o, "textured_character.png");
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Scenes, RenderGoldenTest,
                         ::testing::Values(Golden{"piano.json", "6", "piano_closeup.png"},
                                           Golden{"quartet.json", "3", "quartet_wide.png"}),
                         [](const auto& param_info) {
                           return std::string(param_info.param.file)
                               .substr(0, std::string(param_info.param.file).find('.'));
                         });

}  // namespace
}  // namespace tutti::cli
