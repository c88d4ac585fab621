// SPDX-License-Identifier: MIT
// Renders into an offscreen target on the real device (lavapipe on CI) with validation on, reads
// the pixels back and checks them.
#include <tutti/render/offscreen_target.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <iterator>
#include <vector>

#include <tutti/image/png.hpp>
#include <tutti/render/color_mesh_pipeline.hpp>
#include "render_test_support.hpp"
#include "testdata.hpp"

std::vector<std::uint8_t> decode_png_for_test(const std::vector<std::uint8_t>& png, int& width,
                                              int& height);  // stb_image_impl.cpp

namespace tutti::render {
namespace {

using test::pixel_near;
using test::srgb;

const ClearColor kClear{0.1f, 0.2f, 0.4f, 1.0f};
const glm::vec3 kOrange{1.0f, 0.5f, 0.0f};

// A camera 3 units in front of the origin looking at it, y up in the image (Vulkan's clip space
// has y down, so the projection's y is flipped).
glm::mat4 camera_mvp(float aspect) {
  glm::mat4 projection = glm::perspective(glm::radians(60.0f), aspect, 0.1f, 10.0f);
  projection[1][1] *= -1.0f;
  const glm::mat4 view =
      glm::lookAt(glm::vec3(0.0f, 0.0f, 3.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  return projection * view;
}

// Where `mvp` puts `point` in a width x height image, in pixels (x right, y down).
glm::vec2 to_pixel(const glm::mat4& mvp, glm::vec3 point, std::uint32_t width,
                   std::uint32_t height) {
  const glm::vec4 clip = mvp * glm::vec4(point, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return {(ndc.x + 1.0f) * 0.5f * static_cast<float>(width),
          (ndc.y + 1.0f) * 0.5f * static_cast<float>(height)};
}

std::vector<ColorVertex> solid_triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 color) {
  return {{a, color}, {b, color}, {c, color}};
}

class OffscreenTargetTest : public test::VulkanTest {
 protected:
  struct Scene {
    std::unique_ptr<OffscreenTarget> target;
    std::unique_ptr<ColorMeshPipeline> pipeline;
  };

  Scene make_scene(std::uint32_t width, std::uint32_t height, std::uint32_t ring_size = 2) {
    Scene scene;
    auto target = OffscreenTarget::create(context(), width, height, ring_size);
    EXPECT_TRUE(target) << target.error().message;
    if (!target) return scene;
    scene.target = std::move(*target);
    auto pipeline = ColorMeshPipeline::create(context(), scene.target->color_format(),
                                              scene.target->depth_format());
    EXPECT_TRUE(pipeline) << pipeline.error().message;
    if (pipeline) scene.pipeline = std::move(*pipeline);
    return scene;
  }

  // Renders `meshes` (each with `mvp`) over kClear and reads the frame back.
  std::vector<std::uint8_t> render(Scene& scene, const std::vector<const ColorMesh*>& meshes,
                                   const glm::mat4& mvp, ClearColor clear = kClear) {
    std::vector<std::uint8_t> rgba;
    auto frame = scene.target->begin_frame(clear);
    EXPECT_TRUE(frame) << frame.error().message;
    if (!frame) return rgba;
    for (const ColorMesh* mesh : meshes) scene.pipeline->draw(frame->commands, *mesh, mvp);
    auto id = scene.target->end_frame();
    EXPECT_TRUE(id) << id.error().message;
    if (!id) return rgba;
    EXPECT_EQ(*id, frame->id);
    Status read = scene.target->read_pixels(*id, rgba);
    EXPECT_TRUE(read) << read.error().message;
    return rgba;
  }
};

TEST_F(OffscreenTargetTest, RendersTriangleOverClearColour) {
  constexpr std::uint32_t kWidth = 320, kHeight = 240;
  Scene scene = make_scene(kWidth, kHeight);
  ASSERT_TRUE(scene.pipeline);
  const glm::vec3 a{-1.0f, -1.0f, 0.0f}, b{1.0f, -1.0f, 0.0f}, apex{0.0f, 1.0f, 0.0f};
  auto mesh = ColorMesh::create(context(), solid_triangle(a, b, apex, kOrange));
  ASSERT_TRUE(mesh) << mesh.error().message;
  const glm::mat4 mvp = camera_mvp(float(kWidth) / float(kHeight));

  const std::vector<std::uint8_t> rgba = render(scene, {&*mesh}, mvp);
  ASSERT_EQ(rgba.size(), std::size_t{kWidth} * kHeight * 4);

  const test::Rgb clear = srgb(kClear.r, kClear.g, kClear.b);
  const test::Rgb orange = srgb(kOrange.r, kOrange.g, kOrange.b);
  EXPECT_EQ(orange.g, 188);  // 0.5 linear is 188 in sRGB, not 128: the attachment encodes
  EXPECT_TRUE(pixel_near(rgba, kWidth, 0, 0, clear));
  EXPECT_TRUE(pixel_near(rgba, kWidth, kWidth - 1, kHeight - 1, clear));
  const glm::vec2 centroid = to_pixel(mvp, (a + b + apex) / 3.0f, kWidth, kHeight);
  EXPECT_TRUE(
      pixel_near(rgba, kWidth, std::uint32_t(centroid.x), std::uint32_t(centroid.y), orange));
  // The apex points up in the image: just below it is orange, just above it is clear.
  const glm::vec2 top = to_pixel(mvp, apex, kWidth, kHeight);
  EXPECT_LT(top.y, centroid.y);
  EXPECT_TRUE(pixel_near(rgba, kWidth, std::uint32_t(top.x), std::uint32_t(top.y) + 4, orange));
  EXPECT_TRUE(pixel_near(rgba, kWidth, std::uint32_t(top.x), std::uint32_t(top.y) - 4, clear));

  const std::filesystem::path temp = tutti::test::unique_temp_path("triangle.png");
  Status written = image::write_png(temp, rgba, kWidth, kHeight);
  ASSERT_TRUE(written) << written.error().message;
  std::ifstream in(temp, std::ios::binary);
  const std::vector<std::uint8_t> png((std::istreambuf_iterator<char>(in)),
                                      std::istreambuf_iterator<char>());
  std::filesystem::remove(temp);
  int png_width = 0, png_height = 0;
  EXPECT_TRUE(decode_png_for_test(png, png_width, png_height) == rgba)
      << "the PNG holds exactly the rendered pixels";
  // Kept for people (and CI artifacts): build/<dir>/tests/render/artifacts/.
  std::filesystem::create_directories(TUTTI_RENDER_ARTIFACT_DIR);
  Status artifact =
      image::write_png(std::filesystem::path(TUTTI_RENDER_ARTIFACT_DIR) / "triangle_320x240.png",
                       rgba, kWidth, kHeight);
  EXPECT_TRUE(artifact) << artifact.error().message;
}

TEST_F(OffscreenTargetTest, SecondRenderIsByteIdentical) {
  Scene scene = make_scene(320, 240);
  ASSERT_TRUE(scene.pipeline);
  const std::vector<ColorVertex> vertices = {{{-0.9f, 0.7f, 0.3f}, {1.0f, 0.0f, 0.0f}},
                                             {{0.8f, 0.9f, 0.3f}, {0.0f, 1.0f, 0.0f}},
                                             {{0.1f, -0.8f, 0.3f}, {0.0f, 0.0f, 1.0f}}};
  auto mesh = ColorMesh::create(context(), vertices);
  ASSERT_TRUE(mesh) << mesh.error().message;
  const glm::mat4 mvp = camera_mvp(320.0f / 240.0f);
  const std::vector<std::uint8_t> first = render(scene, {&*mesh}, mvp);
  const std::vector<std::uint8_t> second = render(scene, {&*mesh}, mvp);  // other ring slot
  ASSERT_FALSE(first.empty());
  EXPECT_TRUE(first == second) << "two renders of the same frame differ";
  // ... and the frame is not trivially uniform (the interpolated colours are there).
  EXPECT_NE(test::pixel_string(first, 320, 160, 120), test::pixel_string(first, 320, 0, 0));
}

// 317 px rows are 1268 bytes; the readback buffer pads them to 1280. A left-half quad must stay
// exactly in the left half on every row: a wrong pitch would shear it by 3 px per row.
TEST_F(OffscreenTargetTest, OddWidthReadbackHonoursRowPitch) {
  constexpr std::uint32_t kWidth = 317, kHeight = 123;
  Scene scene = make_scene(kWidth, kHeight);
  ASSERT_TRUE(scene.pipeline);
  EXPECT_GT(scene.target->readback_row_pitch_bytes(), kWidth * 4);
  const glm::vec3 green{0.0f, 1.0f, 0.0f};
  std::vector<ColorVertex> quad =
      solid_triangle({-1, -1, 0.5f}, {0, -1, 0.5f}, {0, 1, 0.5f}, green);
  const std::vector<ColorVertex> upper =
      solid_triangle({-1, -1, 0.5f}, {0, 1, 0.5f}, {-1, 1, 0.5f}, green);
  quad.insert(quad.end(), upper.begin(), upper.end());
  auto mesh = ColorMesh::create(context(), quad);
  ASSERT_TRUE(mesh) << mesh.error().message;

  const std::vector<std::uint8_t> rgba = render(scene, {&*mesh}, glm::mat4(1.0f));
  ASSERT_EQ(rgba.size(), std::size_t{kWidth} * kHeight * 4);
  const test::Rgb clear = srgb(kClear.r, kClear.g, kClear.b);
  const test::Rgb expected_green = srgb(green.r, green.g, green.b);
  // NDC x = 0 is pixel 158.5; pixel 158's centre lies on the edge, so it is not checked.
  int bad_rows = 0;
  for (std::uint32_t y = 0; y < kHeight; ++y) {
    for (std::uint32_t x : {0u, 100u, 157u}) {
      if (!pixel_near(rgba, kWidth, x, y, expected_green)) ++bad_rows;
    }
    for (std::uint32_t x : {159u, 250u, kWidth - 1}) {
      if (!pixel_near(rgba, kWidth, x, y, clear)) ++bad_rows;
    }
  }
  EXPECT_EQ(bad_rows, 0);
  EXPECT_TRUE(pixel_near(rgba, kWidth, kWidth - 1, kHeight - 1, clear));
  EXPECT_TRUE(pixel_near(rgba, kWidth, 0, kHeight - 1, expected_green));
}

TEST_F(OffscreenTargetTest, DepthTestKeepsTheNearerTriangle) {
  Scene scene = make_scene(64, 64);
  ASSERT_TRUE(scene.pipeline);
  const glm::vec3 red{1, 0, 0}, blue{0, 0, 1};
  // Near (z = 0.2) drawn first, far (z = 0.8) second; identity MVP, so z is the depth.
  auto near_mesh = ColorMesh::create(
      context(), solid_triangle({-1, -1, 0.2f}, {1, -1, 0.2f}, {-1, 1, 0.2f}, red));
  auto far_mesh = ColorMesh::create(
      context(), solid_triangle({1, 1, 0.8f}, {-1, 1, 0.8f}, {1, -1, 0.8f}, blue));
  ASSERT_TRUE(near_mesh && far_mesh);
  const std::vector<std::uint8_t> rgba = render(scene, {&*near_mesh, &*far_mesh}, glm::mat4(1.0f));
  ASSERT_FALSE(rgba.empty());
  EXPECT_TRUE(pixel_near(rgba, 64, 10, 10, srgb(1, 0, 0)));  // both cover it: near wins
  EXPECT_TRUE(pixel_near(rgba, 64, 60, 60, srgb(0, 0, 1)));  // only the far one
}

TEST_F(OffscreenTargetTest, RingKeepsEarlierFramesReadableUntilReused) {
  Scene scene = make_scene(32, 16, 2);
  ASSERT_TRUE(scene.pipeline);
  const ClearColor colors[3] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}};
  std::uint64_t ids[3] = {};
  for (int i = 0; i < 2; ++i) {
    auto frame = scene.target->begin_frame(colors[i]);
    ASSERT_TRUE(frame) << frame.error().message;
    auto id = scene.target->end_frame();
    ASSERT_TRUE(id) << id.error().message;
    ids[i] = *id;
  }
  std::vector<std::uint8_t> rgba;
  ASSERT_TRUE(scene.target->read_pixels(ids[1], rgba));
  EXPECT_TRUE(pixel_near(rgba, 32, 5, 5, srgb(0, 1, 0)));
  ASSERT_TRUE(scene.target->read_pixels(ids[0], rgba));
  EXPECT_TRUE(pixel_near(rgba, 32, 5, 5, srgb(1, 0, 0)));

  auto frame = scene.target->begin_frame(colors[2]);  // reuses frame 0's slot
  ASSERT_TRUE(frame);
  EXPECT_FALSE(scene.target->begin_frame(colors[2])) << "nested begin_frame must fail";
  EXPECT_FALSE(scene.target->read_pixels(frame->id, rgba)) << "frame not ended yet";
  auto id = scene.target->end_frame();
  ASSERT_TRUE(id);
  ids[2] = *id;
  const Status overwritten = scene.target->read_pixels(ids[0], rgba);
  ASSERT_FALSE(overwritten);
  EXPECT_NE(overwritten.error().message.find("overwritten"), std::string::npos);
  ASSERT_TRUE(scene.target->read_pixels(ids[2], rgba));
  EXPECT_TRUE(pixel_near(rgba, 32, 31, 15, srgb(0, 0, 1)));
  EXPECT_FALSE(scene.target->end_frame()) << "end_frame without begin_frame must fail";
}

TEST_F(OffscreenTargetTest, RejectsEmptySizesAndMeshes) {
  EXPECT_FALSE(OffscreenTarget::create(context(), 0, 10));
  EXPECT_FALSE(OffscreenTarget::create(context(), 10, 10, 0));
  const std::vector<ColorVertex> two(2);
  EXPECT_FALSE(ColorMesh::create(context(), two));
}

}  // namespace
}  // namespace tutti::render
