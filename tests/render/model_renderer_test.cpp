// SPDX-License-Identifier: MIT
// ModelRenderer on the real device (lavapipe on CI), validation on: lighting and shadows, MSAA,
// skinning and morph targets, each checked on pixels of models built in the test.
#include <tutti/render/model_renderer.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <iterator>
#include <string>
#include <vector>

#include <tutti/image/png.hpp>
#include <tutti/render/offscreen_target.hpp>
#include <tutti/render/shader_compiler.hpp>
#include "render_test_support.hpp"

namespace tutti::render {
namespace {

model::Material plain_material(const char* name, glm::vec4 color, float metallic, float roughness) {
  model::Material m;
  m.name = name;
  m.base_color = color;
  m.metallic = metallic;
  m.roughness = roughness;
  return m;
}

constexpr std::uint32_t kWidth = 320;
constexpr std::uint32_t kHeight = 240;

// An axis-aligned box (24 vertices, outward normals) appended to `asset` as one primitive.
model::Primitive add_box(model::ModelAsset& asset, glm::vec3 lo, glm::vec3 hi, int material) {
  model::Primitive p;
  p.first_vertex = static_cast<std::uint32_t>(asset.vertices.size());
  p.first_index = static_cast<std::uint32_t>(asset.indices.size());
  p.material = material;
  const glm::vec3 corners[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z},
                                {lo.x, hi.y, lo.z}, {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z},
                                {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
  struct Face {
    int a, b, c, d;
    glm::vec3 normal;
  };
  const Face faces[6] = {{4, 5, 6, 7, {0, 0, 1}}, {1, 0, 3, 2, {0, 0, -1}},
                         {5, 1, 2, 6, {1, 0, 0}}, {0, 4, 7, 3, {-1, 0, 0}},
                         {7, 6, 2, 3, {0, 1, 0}}, {0, 1, 5, 4, {0, -1, 0}}};
  std::uint32_t v = 0;
  for (const Face& f : faces) {
    for (int corner : {f.a, f.b, f.c, f.d}) {
      model::Vertex vertex;
      vertex.position = corners[corner];
      vertex.normal = f.normal;
      asset.vertices.push_back(vertex);
    }
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) asset.indices.push_back(v + i);
    v += 4;
  }
  p.vertex_count = v;
  p.index_count = 36;
  return p;
}

int add_node(model::ModelAsset& asset, const std::string& name, int mesh, int parent,
             glm::vec3 translation) {
  model::Node node;
  node.name = name;
  node.mesh = mesh;
  node.parent = parent;
  node.rest.translation = translation;
  asset.nodes.push_back(node);
  const int index = static_cast<int>(asset.nodes.size()) - 1;
  if (parent >= 0) {
    asset.nodes[static_cast<std::size_t>(parent)].children.push_back(index);
  } else {
    asset.roots.push_back(index);
  }
  return index;
}

// A grey floor (10 m square, top at y = 0) and a red 0.5 m cube floating 0.5 m above it.
model::ModelAsset floor_and_cube() {
  model::ModelAsset asset;
  asset.source = "floor_and_cube";
  asset.materials.push_back(plain_material("floor", {0.5f, 0.5f, 0.5f, 1.0f}, 0.0f, 0.8f));
  asset.materials.push_back(plain_material("red", {0.8f, 0.05f, 0.05f, 1.0f}, 0.0f, 0.5f));
  model::Mesh floor{"floor", {add_box(asset, {-5, -0.1f, -5}, {5, 0, 5}, 0)}, {}, {}};
  model::Mesh cube{
      "cube", {add_box(asset, {-0.25f, -0.25f, -0.25f}, {0.25f, 0.25f, 0.25f}, 1)}, {}, {}};
  asset.meshes = {floor, cube};
  add_node(asset, "floor", 0, -1, {0, 0, 0});
  add_node(asset, "cube", 1, -1, {0, 0.75f, 0});
  return asset;
}

// Vertical bar from y = 0 to 1, two joints (at 0 and 0.5); the top half follows joint 1.
model::ModelAsset skinned_bar() {
  model::ModelAsset asset;
  asset.source = "skinned_bar";
  asset.materials.push_back(plain_material("white", {0.9f, 0.9f, 0.9f, 1.0f}, 0.0f, 0.5f));
  model::Primitive bottom = add_box(asset, {-0.05f, 0.0f, -0.05f}, {0.05f, 0.5f, 0.05f}, 0);
  model::Primitive top = add_box(asset, {-0.05f, 0.5f, -0.05f}, {0.05f, 1.0f, 0.05f}, 0);
  for (std::uint32_t v = 0; v < asset.vertices.size(); ++v) {
    asset.vertices[v].weights = {1, 0, 0, 0};
    asset.vertices[v].joints = {v < top.first_vertex ? 0u : 1u, 0, 0, 0};
  }
  asset.meshes.push_back({"bar", {bottom, top}, {}, {}});
  const int root = add_node(asset, "root", -1, -1, {0, 0, 0});
  const int upper = add_node(asset, "upper", -1, root, {0, 0.5f, 0});
  const int skinned = add_node(asset, "bar", 0, -1, {0, 0, 0});
  asset.nodes[static_cast<std::size_t>(skinned)].skin = 0;
  model::Skin skin;
  skin.name = "bar";
  skin.joints = {root, upper};
  skin.inverse_bind = {glm::mat4(1.0f), glm::translate(glm::mat4(1.0f), glm::vec3(0, -0.5f, 0))};
  asset.skins.push_back(skin);
  return asset;
}

// A UV sphere of radius 0.5 m (segments x rings quads), the kind of smooth mesh levels of
// detail are for.
model::ModelAsset dense_sphere(int segments, int rings) {
  model::ModelAsset asset;
  asset.source = "dense_sphere";
  asset.materials.push_back(plain_material("white", {0.9f, 0.9f, 0.9f, 1.0f}, 0.0f, 0.5f));
  model::Primitive p;
  p.material = 0;
  for (int r = 0; r <= rings; ++r) {
    const float theta = 3.14159265f * static_cast<float>(r) / static_cast<float>(rings);
    for (int s = 0; s <= segments; ++s) {
      const float phi = 2.0f * 3.14159265f * static_cast<float>(s) / static_cast<float>(segments);
      model::Vertex v;
      v.normal = {std::sin(theta) * std::cos(phi), std::cos(theta),
                  std::sin(theta) * std::sin(phi)};
      v.position = 0.5f * v.normal;
      asset.vertices.push_back(v);
    }
  }
  const auto at = [&](int r, int s) { return static_cast<std::uint32_t>(r * (segments + 1) + s); };
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      for (std::uint32_t i :
           {at(r, s), at(r + 1, s), at(r + 1, s + 1), at(r, s), at(r + 1, s + 1), at(r, s + 1)}) {
        asset.indices.push_back(i);
      }
    }
  }
  p.vertex_count = static_cast<std::uint32_t>(asset.vertices.size());
  p.index_count = static_cast<std::uint32_t>(asset.indices.size());
  asset.meshes.push_back({"sphere", {p}, {}, {}});
  add_node(asset, "sphere", 0, -1, {0, 0, 0});
  return asset;
}

class ModelRendererTest : public test::VulkanTest {
 protected:
  std::vector<std::uint8_t> render(const std::vector<const model::ModelAsset*>& models,
                                   const std::vector<ModelInstance>& instances,
                                   const Camera& camera, VkSampleCountFlagBits samples,
                                   const Lighting& lighting = {},
                                   const ModelRendererOptions& options = {},
                                   RenderStats* stats = nullptr) {
    auto target = OffscreenTarget::create(context(), kWidth, kHeight, 2, samples);
    EXPECT_TRUE(target) << target.error().message;
    if (!target) return {};
    auto renderer = ModelRenderer::create(context(), **target, models, options);
    EXPECT_TRUE(renderer) << renderer.error().message;
    if (!renderer) return {};
    auto frame = (*target)->begin_frame();
    EXPECT_TRUE(frame);
    Status recorded = (*renderer)->record(*frame, **target, instances, camera, lighting,
                                          {0.0f, 0.0f, 0.0f, 1.0f});
    EXPECT_TRUE(recorded) << recorded.error().message;
    if (stats != nullptr) *stats = (*renderer)->last_stats();
    auto id = (*target)->end_frame();
    EXPECT_TRUE(id);
    std::vector<std::uint8_t> rgba;
    Status read = (*target)->read_pixels(*id, rgba);
    EXPECT_TRUE(read) << read.error().message;
    return rgba;
  }

  static int luminance(const std::vector<std::uint8_t>& rgba, glm::ivec2 p) {
    EXPECT_TRUE(p.x >= 0 && p.y >= 0 && p.x < static_cast<int>(kWidth) &&
                p.y < static_cast<int>(kHeight))
        << p.x << ", " << p.y;
    p = glm::clamp(p, glm::ivec2(0), glm::ivec2(kWidth - 1, kHeight - 1));
    const std::size_t i =
        (static_cast<std::size_t>(p.y) * kWidth + static_cast<std::size_t>(p.x)) * 4;
    return rgba[i] + rgba[i + 1] + rgba[i + 2];
  }

  static glm::ivec2 to_pixel(const Camera& camera, glm::vec3 world) {
    const glm::vec4 clip = camera.projection * camera.view * glm::vec4(world, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {static_cast<int>((ndc.x + 1.0f) * 0.5f * kWidth),
            static_cast<int>((ndc.y + 1.0f) * 0.5f * kHeight)};
  }
};

TEST_F(ModelRendererTest, KeyLightCastsAShadowOfTheCubeOnTheFloor) {
  const model::ModelAsset scene = floor_and_cube();
  const Camera camera = look_at_camera({0, 3, 4}, {0, 0.3f, 0}, 45.0f, float(kWidth) / kHeight);
  Lighting lighting;
  lighting.key.direction = {0, -1, 0};  // straight down: the shadow lies right under the cube
  lighting.shadow_center = {0, 0.5f, 0};
  lighting.shadow_radius = 3.0f;
  const auto rgba =
      render({&scene}, {{0, nullptr, glm::mat4(1.0f)}}, camera, VK_SAMPLE_COUNT_1_BIT, lighting);
  ASSERT_EQ(rgba.size(), std::size_t{kWidth} * kHeight * 4);
  (void)image::write_png(std::string(TUTTI_RENDER_ARTIFACT_DIR) + "/model_shadow.png", rgba, kWidth,
                         kHeight);
  // Floor just in front of the cube's shadow footprint (visible past the cube) vs far from it.
  const int shadowed = luminance(rgba, to_pixel(camera, {0.0f, 0.0f, 0.22f}));
  const int lit = luminance(rgba, to_pixel(camera, {1.5f, 0.0f, 0.8f}));
  // Ambient and fill still reach the shadow; the key light does not.
  EXPECT_LT(shadowed * 10, lit * 8) << "shadowed " << shadowed << ", lit " << lit;
  // Without the cube the same spot is as bright as the rest of the floor.
  model::ModelAsset floor_only = scene;
  floor_only.nodes[1].mesh = -1;
  const auto empty = render({&floor_only}, {{0, nullptr, glm::mat4(1.0f)}}, camera,
                            VK_SAMPLE_COUNT_1_BIT, lighting);
  EXPECT_NEAR(luminance(empty, to_pixel(camera, {0.0f, 0.0f, 0.22f})), lit, 12);
  // The cube's top faces the key light and is brighter than its front, which only the fill sees.
  const int top = luminance(rgba, to_pixel(camera, {0.0f, 1.0f, 0.0f}));
  const int front = luminance(rgba, to_pixel(camera, {0.0f, 0.7f, 0.25f}));
  EXPECT_GT(top, front);
}

TEST_F(ModelRendererTest, FourShadowTapsSoftenTheEdgeAndOtherCountsAreErrors) {
  const model::ModelAsset scene = floor_and_cube();
  const Camera camera = look_at_camera({0, 3, 4}, {0, 0.3f, 0}, 45.0f, float(kWidth) / kHeight);
  Lighting lighting;
  lighting.key.direction = {0, -1, 0};
  lighting.shadow_center = {0, 0.5f, 0};
  lighting.shadow_radius = 3.0f;
  // A small map makes the texels big enough to see the filter.
  ModelRendererOptions hard;
  hard.shadow_map_size = 256;
  ModelRendererOptions soft = hard;
  soft.shadow_taps = 4;
  const auto one = render({&scene}, {{0, nullptr, glm::mat4(1.0f)}}, camera, VK_SAMPLE_COUNT_1_BIT,
                          lighting, hard);
  const auto four = render({&scene}, {{0, nullptr, glm::mat4(1.0f)}}, camera, VK_SAMPLE_COUNT_1_BIT,
                           lighting, soft);
  ASSERT_EQ(one.size(), four.size());
  ASSERT_FALSE(one.empty());
  // Both shadow the spot under the cube; they differ along the shadow's edge only.
  const int lit = luminance(one, to_pixel(camera, {1.5f, 0.0f, 0.8f}));
  EXPECT_LT(luminance(one, to_pixel(camera, {0.0f, 0.0f, 0.1f})) * 10, lit * 8);
  EXPECT_LT(luminance(four, to_pixel(camera, {0.0f, 0.0f, 0.1f})) * 10, lit * 8);
  std::size_t differing = 0;
  for (std::size_t i = 0; i < one.size(); ++i) differing += one[i] != four[i] ? 1 : 0;
  EXPECT_GT(differing, 0u);
  EXPECT_LT(differing, one.size() / 20);

  auto target = OffscreenTarget::create(context(), kWidth, kHeight, 2, VK_SAMPLE_COUNT_1_BIT);
  ASSERT_TRUE(target) << target.error().message;
  ModelRendererOptions wrong;
  wrong.shadow_taps = 2;
  const std::vector<const model::ModelAsset*> models = {&scene};
  auto renderer = ModelRenderer::create(context(), **target, models, wrong);
  ASSERT_FALSE(renderer);
  EXPECT_NE(renderer.error().message.find("shadow_taps must be 1 or 4"), std::string::npos)
      << renderer.error().message;
}

TEST_F(ModelRendererTest, FloorThatCastsNoShadowsLeavesNoShadow) {
  const model::ModelAsset scene = floor_and_cube();
  const Camera camera = look_at_camera({0, 3, 4}, {0, 0.3f, 0}, 45.0f, float(kWidth) / kHeight);
  Lighting lighting;
  lighting.key.direction = {0, -1, 0};
  lighting.shadow_center = {0, 0.5f, 0};
  lighting.shadow_radius = 3.0f;
  RenderStats stats;
  ModelInstance instance{0, nullptr, glm::mat4(1.0f)};
  instance.casts_shadows = false;
  const auto rgba =
      render({&scene}, {instance}, camera, VK_SAMPLE_COUNT_1_BIT, lighting, {}, &stats);
  ASSERT_EQ(rgba.size(), std::size_t{kWidth} * kHeight * 4);
  EXPECT_EQ(stats.shadow_draws, 0u);
  EXPECT_EQ(stats.main_draws, 2u);
  const int under_cube = luminance(rgba, to_pixel(camera, {0.0f, 0.0f, 0.22f}));
  const int lit = luminance(rgba, to_pixel(camera, {1.5f, 0.0f, 0.8f}));
  EXPECT_NEAR(under_cube, lit, 12);
}

TEST_F(ModelRendererTest, CubeOutOfViewIsNotDrawnButStillCastsItsShadow) {
  const model::ModelAsset scene = floor_and_cube();
  // Looking steeply down at the floor in front of the cube: the cube (0.5 .. 1.0 m up) is above
  // the view, its shadow in it.
  const Camera camera =
      look_at_camera({0, 0.45f, 0.9f}, {0, 0.0f, 0.6f}, 60.0f, float(kWidth) / kHeight);
  Lighting lighting;
  lighting.key.direction = glm::normalize(glm::vec3(0, -1, 1));  // the shadow falls toward +z
  lighting.shadow_center = {0, 0.5f, 0};
  lighting.shadow_radius = 3.0f;
  RenderStats stats;
  const auto rgba = render({&scene}, {{0, nullptr, glm::mat4(1.0f)}}, camera, VK_SAMPLE_COUNT_1_BIT,
                           lighting, {}, &stats);
  ASSERT_EQ(rgba.size(), std::size_t{kWidth} * kHeight * 4);
  EXPECT_EQ(stats.candidates, 2u);
  EXPECT_EQ(stats.main_draws, 1u) << "the cube is out of view";
  EXPECT_EQ(stats.shadow_draws, 2u);
  // The cube's shadow (offset +z by its height above the floor) vs open floor beside it.
  const int shadowed = luminance(rgba, to_pixel(camera, {0.0f, 0.0f, 0.6f}));
  const int lit = luminance(rgba, to_pixel(camera, {0.36f, 0.0f, 0.6f}));
  EXPECT_LT(shadowed * 10, lit * 8) << "shadowed " << shadowed << ", lit " << lit;
}

TEST_F(ModelRendererTest, DistantModelsDrawCoarserLevelsAndStillCover) {
  const model::ModelAsset sphere = dense_sphere(96, 48);
  const std::uint64_t full = sphere.indices.size() / 3;
  const auto at_distance = [&](float distance, float lod_pixel_error, RenderStats& stats) {
    const Camera camera =
        look_at_camera({0, 0, distance}, {0, 0, 0}, 30.0f, float(kWidth) / kHeight, 0.05f, 500.0f);
    ModelRendererOptions options;
    options.lod_pixel_error = lod_pixel_error;
    return render({&sphere}, {{0, nullptr, glm::mat4(1.0f)}}, camera, VK_SAMPLE_COUNT_1_BIT, {},
                  options, &stats);
  };
  RenderStats near_stats;
  RenderStats far_stats;
  RenderStats exact_stats;
  (void)at_distance(0.7f, 1.0f, near_stats);
  const auto far = at_distance(40.0f, 1.0f, far_stats);
  const auto exact = at_distance(40.0f, 0.0f, exact_stats);
  EXPECT_EQ(near_stats.main_triangles, full);
  EXPECT_EQ(exact_stats.main_triangles, full);
  EXPECT_LT(far_stats.main_triangles * 4, full) << far_stats.main_triangles << " of " << full;
  // The coarse sphere covers the same pixels, give or take its outline.
  ASSERT_EQ(far.size(), exact.size());
  int coverage_far = 0;
  int coverage_exact = 0;
  int differing = 0;
  for (std::size_t i = 0; i < far.size(); i += 4) {
    const bool a = far[i] + far[i + 1] + far[i + 2] > 0;
    const bool b = exact[i] + exact[i + 1] + exact[i + 2] > 0;
    coverage_far += a ? 1 : 0;
    coverage_exact += b ? 1 : 0;
    differing += a != b ? 1 : 0;
  }
  EXPECT_GT(coverage_exact, 30);
  EXPECT_LE(differing, coverage_exact / 5 + 4) << coverage_far << " vs " << coverage_exact;
}

TEST_F(ModelRendererTest, MultisamplingBlendsEdgesAndKeepsInteriors) {
  const model::ModelAsset scene = floor_and_cube();
  const Camera camera = look_at_camera({0, 1, 3}, {0, 0.75f, 0}, 30.0f, float(kWidth) / kHeight);
  const std::vector<ModelInstance> cube_only = {{0, nullptr, glm::mat4(1.0f)}};
  const auto one = render({&scene}, cube_only, camera, VK_SAMPLE_COUNT_1_BIT);
  const auto four = render({&scene}, cube_only, camera, VK_SAMPLE_COUNT_4_BIT);
  ASSERT_EQ(one.size(), four.size());
  // Edge pixels take values between the neighbours' only with MSAA: count distinct reds along a
  // row crossing the cube's silhouette against the black background above the floor's horizon.
  const glm::ivec2 centre = to_pixel(camera, {0, 0.95f, 0.25f});
  auto distinct_levels = [&](const std::vector<std::uint8_t>& rgba) {
    std::vector<int> seen;
    for (int x = 0; x < static_cast<int>(kWidth); ++x) {
      const int r =
          rgba[(static_cast<std::size_t>(centre.y) * kWidth + static_cast<std::size_t>(x)) * 4];
      if (std::find(seen.begin(), seen.end(), r) == seen.end()) seen.push_back(r);
    }
    return seen.size();
  };
  EXPECT_GT(distinct_levels(four), distinct_levels(one));
  // Interior pixels agree within a couple of codes.
  const std::size_t i =
      (static_cast<std::size_t>(centre.y) * kWidth + static_cast<std::size_t>(centre.x)) * 4;
  EXPECT_NEAR(one[i], four[i], 3);
}

TEST_F(ModelRendererTest, SkinningBendsTheBarWhereTheCpuReferenceSays) {
  const model::ModelAsset bar = skinned_bar();
  model::ModelPose pose = model::rest_pose(bar);
  // Bend the upper joint 90 degrees about +Z: the top half now points toward -X.
  pose.local[1].rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
  const Camera camera = look_at_camera({0, 0.5f, 3}, {0, 0.5f, 0}, 45.0f, float(kWidth) / kHeight);
  const auto bent = render({&bar}, {{0, &pose, glm::mat4(1.0f)}}, camera, VK_SAMPLE_COUNT_1_BIT);
  const auto straight =
      render({&bar}, {{0, nullptr, glm::mat4(1.0f)}}, camera, VK_SAMPLE_COUNT_1_BIT);
  ASSERT_FALSE(bent.empty());
  (void)image::write_png(std::string(TUTTI_RENDER_ARTIFACT_DIR) + "/model_skinned_bar.png", bent,
                         kWidth, kHeight);
  std::vector<glm::mat4> world(bar.nodes.size());
  model::compute_world_matrices(bar, pose, glm::mat4(1.0f), world);
  // A vertex at the top's far end, deformed on the CPU: (-0.5, 0.5) give or take the bar width.
  const model::Primitive& top = bar.meshes[0].primitives[1];
  // Vertex 16 of the top half is on its +y face, at (-0.05, 1.0): it swings to (-0.5, 0.45).
  const model::SkinnedVertex tip = model::deform_vertex(bar, pose, world, 2, 1, 16);
  EXPECT_NEAR(tip.position.y, 0.5f, 0.06f);
  EXPECT_LT(tip.position.x, -0.4f);
  (void)top;
  const glm::ivec2 bent_tip = to_pixel(camera, {-0.45f, 0.5f, 0.0f});
  const glm::ivec2 straight_tip = to_pixel(camera, {0.0f, 0.95f, 0.0f});
  EXPECT_GT(luminance(bent, bent_tip), 60);
  EXPECT_LT(luminance(bent, straight_tip), 10);
  EXPECT_LT(luminance(straight, bent_tip), 10);
  EXPECT_GT(luminance(straight, straight_tip), 60);
}

TEST_F(ModelRendererTest, MorphTargetMovesTheMeshByItsWeight) {
  model::ModelAsset asset = floor_and_cube();
  // The cube gets one target that lifts every vertex by 0.5 m.
  model::Mesh& cube = asset.meshes[1];
  cube.target_names = {"lift"};
  cube.default_weights = {0.0f};
  model::Primitive& primitive = cube.primitives[0];
  primitive.first_morph_delta = 0;
  asset.morph_deltas.assign(primitive.vertex_count, model::MorphDelta{{0.0f, 0.5f, 0.0f}, {}});
  model::ModelPose pose = model::rest_pose(asset);
  ASSERT_EQ(pose.morph_weights.size(), 1u);
  const Camera camera = look_at_camera({0, 1, 3}, {0, 1.0f, 0}, 40.0f, float(kWidth) / kHeight);
  const glm::ivec2 lifted = to_pixel(camera, {0, 1.35f, 0.25f});
  const glm::ivec2 resting = to_pixel(camera, {0, 0.6f, 0.25f});
  const auto rest = render({&asset}, {{0, &pose, glm::mat4(1.0f)}}, camera, VK_SAMPLE_COUNT_1_BIT);
  pose.morph_weights[0] = 1.0f;
  const auto moved = render({&asset}, {{0, &pose, glm::mat4(1.0f)}}, camera, VK_SAMPLE_COUNT_1_BIT);
  auto red = [&](const std::vector<std::uint8_t>& rgba, glm::ivec2 p) {
    const std::size_t i =
        (static_cast<std::size_t>(p.y) * kWidth + static_cast<std::size_t>(p.x)) * 4;
    return rgba[i] > 2 * rgba[i + 1] + 20;
  };
  EXPECT_TRUE(red(rest, resting));
  EXPECT_FALSE(red(rest, lifted));
  EXPECT_TRUE(red(moved, lifted));
  EXPECT_FALSE(red(moved, resting));
}

// A 1 m quad facing the camera (+Z), UVs 0..1 left to right and top to bottom, with `material`.
model::ModelAsset textured_quad(const model::Material& material, const model::Image& image) {
  model::ModelAsset asset;
  asset.source = "textured_quad";
  asset.materials.push_back(material);
  asset.images.push_back(image);
  model::Texture texture;
  texture.image = 0;
  texture.mag_filter = 9728;  // NEAREST: each texel a clear block
  texture.min_filter = 9728;
  asset.textures.push_back(texture);
  model::Primitive p;
  p.material = 0;
  const glm::vec2 corners[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (const glm::vec2& c : corners) {
    model::Vertex v;
    v.position = {c.x - 0.5f, 1.0f - c.y, 0.0f};
    v.normal = {0, 0, 1};
    v.uv0 = c;
    asset.vertices.push_back(v);
  }
  asset.indices = {0, 3, 2, 0, 2, 1};
  p.vertex_count = 4;
  p.index_count = 6;
  asset.meshes.push_back({"quad", {p}, {}, {}});
  add_node(asset, "quad", 0, -1, {0, 0, 0});
  return asset;
}

// Texels left to right: opaque red, a half-transparent green, a transparent blue.
model::Image three_texels() {
  model::Image image;
  image.mime_type = "image/png";
  image.width = 3;
  image.height = 1;
  image.rgba = {255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 0};
  return image;
}

TEST_F(ModelRendererTest, TexturesColourTheSurfaceAndAlphaMasksAndBlends) {
  const Camera camera = look_at_camera({0, 0.5f, 1.2f}, {0, 0.5f, 0}, 50.0f, float(kWidth) / kHeight);
  const glm::ivec2 left = to_pixel(camera, {-0.33f, 0.5f, 0.0f});
  const glm::ivec2 middle = to_pixel(camera, {0.0f, 0.5f, 0.0f});
  const glm::ivec2 right = to_pixel(camera, {0.33f, 0.5f, 0.0f});
  const auto rgb = [](const std::vector<std::uint8_t>& rgba, glm::ivec2 p) {
    const std::size_t i = (static_cast<std::size_t>(p.y) * kWidth + static_cast<std::size_t>(p.x)) * 4;
    return glm::ivec3(rgba[i], rgba[i + 1], rgba[i + 2]);
  };
  model::Material m;
  m.metallic = 0.0f;
  m.roughness = 1.0f;
  m.base_color_texture.texture = 0;
  // Opaque: the texels' colours, alpha ignored.
  const model::ModelAsset opaque = textured_quad(m, three_texels());
  const auto a = render({&opaque}, {{0, nullptr, glm::mat4(1.0f)}}, camera, VK_SAMPLE_COUNT_1_BIT);
  ASSERT_FALSE(a.empty());
  (void)image::write_png(std::string(TUTTI_RENDER_ARTIFACT_DIR) + "/textured_quad.png", a, kWidth, kHeight);
  EXPECT_GT(rgb(a, left).r, 3 * rgb(a, left).g) << "red texel";
  EXPECT_GT(rgb(a, middle).g, 3 * rgb(a, middle).r) << "green texel";
  EXPECT_GT(rgb(a, right).b, 3 * rgb(a, right).r) << "blue texel";
  // Mask at 0.6: the half-transparent and transparent texels are not drawn (the black clear).
  m.alpha_mode = model::AlphaMode::mask;
  m.alpha_cutoff = 0.6f;
  const model::ModelAsset masked = textured_quad(m, three_texels());
  const auto b = render({&masked}, {{0, nullptr, glm::mat4(1.0f)}}, camera, VK_SAMPLE_COUNT_1_BIT);
  EXPECT_EQ(rgb(b, left), rgb(a, left));
  EXPECT_EQ(rgb(b, middle), glm::ivec3(0));
  EXPECT_EQ(rgb(b, right), glm::ivec3(0));
  // Blend: half the green over the black, none of the blue.
  m.alpha_mode = model::AlphaMode::blend;
  const model::ModelAsset blended = textured_quad(m, three_texels());
  const auto c = render({&blended}, {{0, nullptr, glm::mat4(1.0f)}}, camera, VK_SAMPLE_COUNT_1_BIT);
  EXPECT_EQ(rgb(c, left), rgb(a, left));
  EXPECT_GT(rgb(c, middle).g, rgb(a, middle).g / 3);
  EXPECT_LT(rgb(c, middle).g, rgb(a, middle).g * 3 / 4);
  EXPECT_EQ(rgb(c, right), glm::ivec3(0));
}

TEST_F(ModelRendererTest, ANormalMapTurnsTheLitSurface) {
  // Key light from the upper left; the normal map tilts the surface toward +X (away from it) on
  // the left half and toward -X (toward it) on the right half.
  const Camera camera = look_at_camera({0, 0.5f, 1.2f}, {0, 0.5f, 0}, 50.0f, float(kWidth) / kHeight);
  Lighting lighting;
  lighting.key.direction = {1.0f, 0.0f, -0.6f};
  model::Image flat;
  flat.mime_type = "image/png";
  flat.width = 2;
  flat.height = 1;
  flat.rgba = {128, 128, 255, 255, 128, 128, 255, 255};
  model::Image tilted = flat;
  tilted.rgba = {230, 128, 180, 255, 26, 128, 180, 255};
  model::Material m;
  m.metallic = 0.0f;
  m.roughness = 1.0f;
  m.base_color = {0.8f, 0.8f, 0.8f, 1.0f};
  m.normal_texture.texture = 0;
  const model::ModelAsset plain = textured_quad(m, flat);
  const model::ModelAsset bumped = textured_quad(m, tilted);
  const auto a = render({&plain}, {{0, nullptr, glm::mat4(1.0f)}}, camera, VK_SAMPLE_COUNT_1_BIT, lighting);
  const auto b = render({&bumped}, {{0, nullptr, glm::mat4(1.0f)}}, camera, VK_SAMPLE_COUNT_1_BIT, lighting);
  const glm::ivec2 left = to_pixel(camera, {-0.25f, 0.5f, 0.0f});
  const glm::ivec2 right = to_pixel(camera, {0.25f, 0.5f, 0.0f});
  // A flat map leaves the surface as it is; the tilted one darkens the half turned away from the
  // key light and brightens the half turned toward it.
  EXPECT_NEAR(luminance(a, left), luminance(a, right), 6);
  EXPECT_LT(luminance(b, left) + 20, luminance(a, left));
  EXPECT_GT(luminance(b, right), luminance(a, right) + 20);
  // The map's +y is up the image (glTF): with the key light from above, a map tilted to +y
  // brightens the quad and one tilted to -y darkens it.
  lighting.key.direction = {0.0f, -1.0f, -0.6f};
  model::Image up = flat, down = flat;
  up.rgba = {128, 230, 180, 255, 128, 230, 180, 255};
  down.rgba = {128, 26, 180, 255, 128, 26, 180, 255};
  const model::ModelAsset facing_up = textured_quad(m, up);
  const model::ModelAsset facing_down = textured_quad(m, down);
  const auto c = render({&plain}, {{0, nullptr, glm::mat4(1.0f)}}, camera, VK_SAMPLE_COUNT_1_BIT, lighting);
  const auto d = render({&facing_up}, {{0, nullptr, glm::mat4(1.0f)}}, camera, VK_SAMPLE_COUNT_1_BIT, lighting);
  const auto e = render({&facing_down}, {{0, nullptr, glm::mat4(1.0f)}}, camera, VK_SAMPLE_COUNT_1_BIT, lighting);
  EXPECT_GT(luminance(d, left), luminance(c, left) + 20);
  EXPECT_LT(luminance(e, left) + 20, luminance(c, left));
}

TEST_F(ModelRendererTest, SameFrameTwiceIsByteIdentical) {
  const model::ModelAsset scene = floor_and_cube();
  const Camera camera = look_at_camera({1, 2, 3}, {0, 0.5f, 0}, 45.0f, float(kWidth) / kHeight);
  const auto a = render({&scene}, {{0, nullptr, glm::mat4(1.0f)}}, camera, VK_SAMPLE_COUNT_4_BIT);
  const auto b = render({&scene}, {{0, nullptr, glm::mat4(1.0f)}}, camera, VK_SAMPLE_COUNT_4_BIT);
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(a, b);
}

TEST_F(ModelRendererTest, HotReloadedShadersReplaceThePipelines) {
  const model::ModelAsset scene = floor_and_cube();
  const Camera camera = look_at_camera({1, 2, 3}, {0, 0.5f, 0}, 45.0f, float(kWidth) / kHeight);
  auto target = OffscreenTarget::create(context(), kWidth, kHeight);
  ASSERT_TRUE(target);
  std::vector<const model::ModelAsset*> models = {&scene};
  auto renderer = ModelRenderer::create(context(), **target, models);
  ASSERT_TRUE(renderer) << renderer.error().message;
  const std::vector<ModelInstance> instances = {{0, nullptr, glm::mat4(1.0f)}};
  auto draw = [&] {
    auto frame = (*target)->begin_frame();
    EXPECT_TRUE(frame);
    EXPECT_TRUE((*renderer)->record(*frame, **target, instances, camera, {}, {0, 0, 0, 1}));
    auto id = (*target)->end_frame();
    std::vector<std::uint8_t> rgba;
    EXPECT_TRUE((*target)->read_pixels(*id, rgba));
    return rgba;
  };
  const auto built_in = draw();
  // The shipped sources compiled at run time draw the same picture.
  const std::filesystem::path dir =
      std::filesystem::path(TUTTI_SOURCE_DIR) / "engine" / "render" / "shaders";
  auto shaders = reload_lit_shaders(dir);
  ASSERT_TRUE(shaders) << shaders.error().message;
  ASSERT_TRUE((*renderer)->set_shaders(shaders->lit_vert, shaders->lit_frag, shaders->shadow_vert));
  EXPECT_EQ(draw(), built_in);
  // An edited fragment shader (everything emissive green) changes it.
  std::ifstream in(dir / "lit.frag");
  std::string source((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string last = "out_color = vec4(tone_map(color * frame.sky_color.w), alpha);";
  ASSERT_NE(source.find(last), std::string::npos);
  source.replace(source.find(last), last.size(), "out_color = vec4(0.0, 1.0, 0.0, 1.0);");
  const std::filesystem::path include[] = {dir};
  auto green = compile_glsl(source, ShaderStage::fragment, "lit.frag", include);
  ASSERT_TRUE(green) << green.error().message;
  ASSERT_TRUE((*renderer)->set_shaders(shaders->lit_vert, *green, shaders->shadow_vert));
  const auto edited = draw();
  const std::size_t centre = (std::size_t{kHeight / 2} * kWidth + kWidth / 2) * 4;
  EXPECT_EQ(edited[centre], 0);
  EXPECT_EQ(edited[centre + 1], 255);
  // Broken SPIR-V is an error and the last good pipelines stay.
  std::vector<std::uint32_t> broken = *green;
  broken[0] = 0;
  EXPECT_FALSE((*renderer)->set_shaders(shaders->lit_vert, broken, shaders->shadow_vert));
  EXPECT_EQ(draw(), edited);
}

TEST_F(ModelRendererTest, UnknownModelAndMismatchedPoseAreErrors) {
  const model::ModelAsset scene = floor_and_cube();
  auto target = OffscreenTarget::create(context(), 64, 64);
  ASSERT_TRUE(target);
  std::vector<const model::ModelAsset*> models = {&scene};
  auto renderer = ModelRenderer::create(context(), **target, models);
  ASSERT_TRUE(renderer) << renderer.error().message;
  const Camera camera = look_at_camera({0, 1, 3}, {0, 0, 0}, 45.0f, 1.0f);
  auto frame = (*target)->begin_frame();
  ASSERT_TRUE(frame);
  const std::vector<ModelInstance> unknown = {{3, nullptr, glm::mat4(1.0f)}};
  Status s = (*renderer)->record(*frame, **target, unknown, camera, {}, {});
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("only 1 models"), std::string::npos) << s.error().message;
  model::ModelPose wrong;
  const std::vector<ModelInstance> bad_pose = {{0, &wrong, glm::mat4(1.0f)}};
  s = (*renderer)->record(*frame, **target, bad_pose, camera, {}, {});
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("does not fit"), std::string::npos) << s.error().message;
  ASSERT_TRUE((*target)->end_frame());
}

}  // namespace
}  // namespace tutti::render
