// SPDX-License-Identifier: MIT
// Loading valid glTF files: both containers, external and embedded buffers, index types,
// generated indices and normals, skin attributes, strided accessors, node order, matrices,
// materials, scenes, and the generated piano asset.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>

#include "gltf_test_builder.hpp"
#include "glm_expect.hpp"
#include <tutti/image/png.hpp>
#include <webp/encode.h>
#include <webp/types.h>
#include <tutti/model/model_asset.hpp>
#include "testdata.hpp"

namespace tutti::model {
namespace {

using test::expect_near;
using test::GltfBuilder;
using test::kFloat;
using test::kUnsignedByte;
using test::kUnsignedInt;
using test::kUnsignedShort;

ModelAsset must_load(const std::vector<std::uint8_t>& bytes, const std::string& name) {
  auto asset = test::load_bytes(bytes, name);
  EXPECT_TRUE(asset.ok()) << (asset.ok() ? "" : asset.error().message);
  return asset.ok() ? std::move(*asset) : ModelAsset{};
}

GltfBuilder quad() {
  GltfBuilder b;
  test::add_triangle_mesh(b, "quad", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                          {0, 1, 2, 0, 2, 3});
  b.add_node({{"name", "quad"}, {"mesh", 0}});
  b.set_scene({0});
  return b;
}

TEST(LoadModel, GlbAndGltfGiveTheSameModel) {
  const GltfBuilder b = quad();
  for (const auto& [bytes, name] : {std::pair{b.glb(), std::string("quad.glb")},
                                    std::pair{b.gltf_bytes(), std::string("quad.gltf")}}) {
    const ModelAsset asset = must_load(bytes, name);
    EXPECT_EQ(asset.source, name);
    ASSERT_EQ(asset.meshes.size(), 1u);
    EXPECT_EQ(asset.meshes[0].name, "quad");
    ASSERT_EQ(asset.meshes[0].primitives.size(), 1u);
    const Primitive& p = asset.meshes[0].primitives[0];
    EXPECT_EQ(p.vertex_count, 4u);
    EXPECT_EQ(p.index_count, 6u);
    EXPECT_EQ(p.material, -1);
    EXPECT_EQ(asset.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
    expect_near(asset.vertices[2].position, {1, 1, 0});
    expect_near(asset.vertices[2].normal, {0, 0, 1});
    EXPECT_EQ(asset.vertices[2].weights, glm::vec4(0.0f));
    EXPECT_EQ(asset.roots, (std::vector<int>{0}));
    EXPECT_EQ(asset.find_node("quad"), 0);
    EXPECT_EQ(asset.find_node("nope"), -1);
  }
}

TEST(LoadModel, PrimitivesFollowEachOtherInTheSharedArrays) {
  GltfBuilder b = quad();
  test::add_triangle_mesh(b, "tri", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2});
  b.add_node({{"name", "tri"}, {"mesh", 1}});
  b.set_scene({0, 1});
  const ModelAsset asset = must_load(b.glb(), "two.glb");
  const Primitive& second = asset.meshes.at(1).primitives.at(0);
  EXPECT_EQ(second.first_vertex, 4u);
  EXPECT_EQ(second.first_index, 6u);
  EXPECT_EQ(second.index_count, 3u);
  // Indices are relative to the primitive's first vertex.
  EXPECT_EQ(asset.indices[6], 0u);
  EXPECT_EQ(asset.vertices.size(), 7u);
}

TEST(LoadModel, ReadsEveryIndexTypeAndGeneratesMissingIndices) {
  const std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  for (const int type : {kUnsignedByte, kUnsignedShort, kUnsignedInt, 0}) {
    GltfBuilder b;
    nlohmann::json primitive = {{"attributes",
                                 {{"POSITION", b.add_vec3s(positions)},
                                  {"NORMAL", b.add_vec3s({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}})}}}};
    if (type == kUnsignedByte)
      primitive["indices"] = b.add_data(std::vector<std::uint8_t>{2, 1, 0}, type, "SCALAR");
    if (type == kUnsignedShort)
      primitive["indices"] = b.add_data(std::vector<std::uint16_t>{2, 1, 0}, type, "SCALAR");
    if (type == kUnsignedInt)
      primitive["indices"] = b.add_data(std::vector<std::uint32_t>{2, 1, 0}, type, "SCALAR");
    b.add_mesh({{"primitives", {primitive}}});
    const ModelAsset asset = must_load(b.glb(), "indices.glb");
    const auto expected =
        type == 0 ? std::vector<std::uint32_t>{0, 1, 2} : std::vector<std::uint32_t>{2, 1, 0};
    EXPECT_EQ(asset.indices, expected) << "component type " << type;
  }
}

TEST(LoadModel, ComputesFlatNormalsWhenTheFileHasNone) {
  GltfBuilder b;
  // Two triangles sharing an edge, folded 90 degrees: one faces +Z, the other +Y.
  test::add_triangle_mesh(b, "fold", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}},
                          {0, 1, 2, 0, 1, 3}, /*normals=*/false);
  const ModelAsset asset = must_load(b.glb(), "fold.glb");
  const Primitive& p = asset.meshes.at(0).primitives.at(0);
  // Every corner is its own vertex so each face keeps its own normal.
  ASSERT_EQ(p.vertex_count, 6u);
  EXPECT_EQ(asset.indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
  for (int v = 0; v < 3; ++v)
    expect_near(asset.vertices[static_cast<std::size_t>(v)].normal, {0, 0, 1});
  for (int v = 3; v < 6; ++v)
    expect_near(asset.vertices[static_cast<std::size_t>(v)].normal, {0, 1, 0});
  expect_near(asset.vertices[5].position, {0, 0, -1});
}

TEST(LoadModel, NormalisesWeightsOfEveryComponentType) {
  GltfBuilder b = test::two_bone_strip();
  // Replace WEIGHTS_0 with normalised u8 weights that do not sum to 1, then u16, then floats.
  struct Case {
    int type;
    std::vector<std::uint8_t> bytes;
  };
  auto as_bytes = [](const auto& values) {
    std::vector<std::uint8_t> out(values.size() * sizeof(values[0]));
    std::memcpy(out.data(), values.data(), out.size());
    return out;
  };
  const std::vector<std::uint8_t> u8 = {100, 100, 0, 0, 255, 0,   0, 0, 0, 0, 0, 0,
                                        10,  30,  0, 0, 0,   255, 0, 0, 1, 0, 0, 0};
  const std::vector<std::uint16_t> u16 = {100, 100, 0, 0, 65535, 0,     0, 0, 0, 0, 0, 0,
                                          10,  30,  0, 0, 0,     65535, 0, 0, 1, 0, 0, 0};
  const std::vector<float> f = {2,    2,    0, 0, 1, 0,  0, 0, 0, 0, 0, 0,
                                0.1f, 0.3f, 0, 0, 0, -1, 0, 0, 5, 0, 0, 0};
  for (const Case& c : {Case{kUnsignedByte, as_bytes(u8)}, Case{kUnsignedShort, as_bytes(u16)},
                        Case{kFloat, as_bytes(f)}}) {
    GltfBuilder copy = b;
    const int view = copy.add_view(c.bytes.data(), c.bytes.size());
    copy.json["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"] =
        copy.add_accessor(view, c.type, "VEC4", 6, 0, c.type != kFloat);
    const ModelAsset asset = must_load(copy.glb(), "weights.glb");
    ASSERT_EQ(asset.vertices.size(), 6u);
    expect_near(asset.vertices[0].weights, {0.5f, 0.5f, 0, 0});
    expect_near(asset.vertices[1].weights, {1, 0, 0, 0});
    // All zero: weight 1 on joint 0.
    expect_near(asset.vertices[2].weights, {1, 0, 0, 0});
    EXPECT_EQ(asset.vertices[2].joints, glm::uvec4(0));
    expect_near(asset.vertices[3].weights, {0.25f, 0.75f, 0, 0});
    expect_near(asset.vertices[5].weights, {1, 0, 0, 0});
    if (c.type == kFloat) {
      // Negative weights count as 0; (0, -1) sums to nothing -> joint 0.
      expect_near(asset.vertices[4].weights, {1, 0, 0, 0});
    } else {
      expect_near(asset.vertices[4].weights, {0, 1, 0, 0});
    }
  }
}

TEST(LoadModel, ReadsStridedAndOffsetAccessors) {
  GltfBuilder b;
  // Interleaved position + normal, 24-byte stride; the normal accessor starts at byte 12.
  const std::vector<float> interleaved = {0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 1};
  const int view = b.add_view(interleaved.data(), interleaved.size() * 4, 24);
  const int position = b.add_accessor(view, kFloat, "VEC3", 3);
  const int normal = b.add_accessor(view, kFloat, "VEC3", 3, 12);
  b.add_mesh({{"primitives", {{{"attributes", {{"POSITION", position}, {"NORMAL", normal}}}}}}});
  const ModelAsset asset = must_load(b.gltf_bytes(), "interleaved.gltf");
  ASSERT_EQ(asset.vertices.size(), 3u);
  expect_near(asset.vertices[1].position, {1, 0, 0});
  expect_near(asset.vertices[2].position, {0, 1, 0});
  expect_near(asset.vertices[2].normal, {0, 0, 1});
}

TEST(LoadModel, ReordersNodesSoParentsComeFirst) {
  GltfBuilder b = test::two_bone_strip();
  // File order: 0 hand (child of 1), 1 arm (child of 2), 2 shoulder, 3 strip mesh. The skin's
  // joints and the scene roots must follow the new indices.
  b.json["nodes"] = nlohmann::json::array(
      {{{"name", "hand"}, {"translation", {0, 1, 0}}},
       {{"name", "arm"},
        {"translation", {0, 1, 0}},
        {"children", {0}},
        {"rotation", {0, 0, std::sin(std::numbers::pi / 4), std::cos(std::numbers::pi / 4)}}},
       {{"name", "shoulder"}, {"translation", {1, 0, 0}}, {"children", {1}}},
       {{"name", "strip"}, {"mesh", 0}, {"skin", 0}}});
  b.json["skins"][0]["joints"] = {1, 0};
  b.set_scene({3, 2});
  const ModelAsset asset = must_load(b.glb(), "order.glb");
  ASSERT_EQ(asset.nodes.size(), 4u);
  for (std::size_t i = 0; i < asset.nodes.size(); ++i) {
    EXPECT_LT(asset.nodes[i].parent, static_cast<int>(i));
    for (const int child : asset.nodes[i].children) {
      EXPECT_EQ(asset.nodes.at(static_cast<std::size_t>(child)).parent, static_cast<int>(i));
    }
  }
  const int shoulder = asset.find_node("shoulder");
  const int arm = asset.find_node("arm");
  const int hand = asset.find_node("hand");
  EXPECT_EQ(asset.nodes[static_cast<std::size_t>(arm)].parent, shoulder);
  EXPECT_EQ(asset.nodes[static_cast<std::size_t>(hand)].parent, arm);
  EXPECT_EQ(asset.skins.at(0).joints, (std::vector<int>{arm, hand}));
  EXPECT_EQ(asset.roots, (std::vector<int>{asset.find_node("strip"), shoulder}));

  // shoulder at (1,0,0); arm 1 up and turned 90 degrees about Z; hand 1 further up the turned
  // arm, i.e. along -X: (1,1,0) + (-1,0,0).
  const ModelPose pose = rest_pose(asset);
  std::vector<glm::mat4> world(asset.nodes.size());
  compute_world_matrices(asset, pose, glm::mat4(1.0f), world);
  expect_near(glm::vec3(world[static_cast<std::size_t>(arm)][3]), {1, 1, 0});
  expect_near(glm::vec3(world[static_cast<std::size_t>(hand)][3]), {0, 1, 0});
}

// A node's numeric extras are kept (a valve's travel_mm); other extras and non-numbers are not.
TEST(LoadModel, KeepsTheNumbersOfANodesExtras) {
  GltfBuilder b = test::two_bone_strip();
  b.json["nodes"][0]["extras"] = {{"travel_mm", 10.5}, {"label", "valve"}, {"steps", 3}};
  const ModelAsset asset = must_load(b.glb(), "extras.glb");
  const Node& node = asset.nodes.at(static_cast<std::size_t>(
      asset.find_node(b.json["nodes"][0]["name"].get<std::string>())));
  EXPECT_DOUBLE_EQ(node.number("travel_mm", 18.0), 10.5);
  EXPECT_DOUBLE_EQ(node.number("steps", 0.0), 3.0);
  EXPECT_DOUBLE_EQ(node.number("label", -1.0), -1.0);
  EXPECT_DOUBLE_EQ(node.number("absent", 7.0), 7.0);
}

TEST(LoadModel, KeepsTheFileOrderWhenItIsAlreadyParentsFirst) {
  const ModelAsset asset = must_load(test::two_bone_strip().glb(), "strip.glb");
  EXPECT_EQ(asset.find_node("root_joint"), 0);
  EXPECT_EQ(asset.find_node("tip_joint"), 1);
  EXPECT_EQ(asset.find_node("strip"), 2);
  EXPECT_EQ(asset.nodes[0].children, (std::vector<int>{1}));
  EXPECT_EQ(asset.nodes[2].mesh, 0);
  EXPECT_EQ(asset.nodes[2].skin, 0);
}

std::vector<double> column_major(const glm::dmat4& m) {
  std::vector<double> out;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) out.push_back(m[c][r]);
  }
  return out;
}

TEST(LoadModel, DecomposesNodeMatrices) {
  const glm::dquat rotation = glm::angleAxis(0.9, glm::normalize(glm::dvec3(1, -2, 0.5)));
  const glm::dmat4 trs = glm::translate(glm::dmat4(1.0), glm::dvec3(1, 2, 3)) *
                         glm::mat4_cast(rotation) *
                         glm::scale(glm::dmat4(1.0), glm::dvec3(2, 0.5, 3));
  const glm::dmat4 mirror = glm::scale(glm::dmat4(1.0), glm::dvec3(-1, 1, 1));
  const glm::dmat4 flat = glm::scale(glm::dmat4(1.0), glm::dvec3(1, 0, 1));
  GltfBuilder b;
  b.add_node({{"name", "trs"}, {"matrix", column_major(trs)}});
  b.add_node({{"name", "mirror"}, {"matrix", column_major(mirror)}});
  b.add_node({{"name", "flat"}, {"matrix", column_major(flat)}});
  const ModelAsset asset = must_load(b.gltf_bytes(), "matrices.gltf");
  ASSERT_EQ(asset.nodes.size(), 3u);
  const NodeTransform& t = asset.nodes[0].rest;
  expect_near(t.translation, {1, 2, 3});
  expect_near(t.scale, {2, 0.5f, 3});
  EXPECT_NEAR(std::abs(glm::dot(glm::dquat(t.rotation), rotation)), 1.0, 1e-6);
  for (std::size_t i = 0; i < 3; ++i) {
    const glm::mat4 expected = glm::mat4(i == 0 ? trs : i == 1 ? mirror : flat);
    const glm::mat4 rebuilt = to_matrix(asset.nodes[i].rest);
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) EXPECT_NEAR(rebuilt[c][r], expected[c][r], 1e-5f) << i;
    }
  }
  // Without a matrix or TRS: identity.
  GltfBuilder plain;
  plain.add_node({{"name", "plain"}});
  const ModelAsset identity = must_load(plain.glb(), "plain.glb");
  expect_near(identity.nodes.at(0).rest.scale, {1, 1, 1});
  EXPECT_EQ(identity.nodes.at(0).rest.rotation, glm::quat(1, 0, 0, 0));
}

TEST(LoadModel, ReadsMaterialFactors) {
  GltfBuilder b = quad();
  b.json["materials"] = nlohmann::json::array({{{"name", "ivory"},
                                                {"pbrMetallicRoughness",
                                                 {{"baseColorFactor", {0.9, 0.8, 0.7, 0.5}},
                                                  {"metallicFactor", 0.1},
                                                  {"roughnessFactor", 0.4}}},
                                                {"emissiveFactor", {0.2, 0.0, 0.1}},
                                                {"doubleSided", true}},
                                               {{"name", "plain"}}});
  b.json["meshes"][0]["primitives"][0]["material"] = 1;
  const ModelAsset asset = must_load(b.glb(), "materials.glb");
  ASSERT_EQ(asset.materials.size(), 2u);
  const Material& ivory = asset.materials[0];
  EXPECT_EQ(ivory.name, "ivory");
  expect_near(ivory.base_color, {0.9f, 0.8f, 0.7f, 0.5f});
  EXPECT_FLOAT_EQ(ivory.metallic, 0.1f);
  EXPECT_FLOAT_EQ(ivory.roughness, 0.4f);
  expect_near(ivory.emissive, {0.2f, 0, 0.1f});
  EXPECT_TRUE(ivory.double_sided);
  const Material& plain = asset.materials[1];
  expect_near(plain.base_color, {1, 1, 1, 1});
  EXPECT_FLOAT_EQ(plain.metallic, 1.0f);
  EXPECT_FALSE(plain.double_sided);
  EXPECT_EQ(asset.meshes[0].primitives[0].material, 1);
}

TEST(LoadModel, RootsComeFromTheDefaultSceneElseSceneZeroElseParentlessNodes) {
  GltfBuilder b;
  b.add_node({{"name", "a"}, {"children", {1}}});
  b.add_node({{"name", "b"}});
  b.add_node({{"name", "c"}});
  b.json["scenes"] = nlohmann::json::array({{{"nodes", {2}}}, {{"nodes", {0, 2}}}});
  b.json["scene"] = 1;
  EXPECT_EQ(must_load(b.glb(), "s.glb").roots, (std::vector<int>{0, 2}));
  b.json.erase("scene");
  EXPECT_EQ(must_load(b.glb(), "s.glb").roots, (std::vector<int>{2}));
  b.json.erase("scenes");
  EXPECT_EQ(must_load(b.glb(), "s.glb").roots, (std::vector<int>{0, 2}));
}

TEST(LoadModel, ReadsExternalBuffersNextToTheGltfFile) {
  const std::filesystem::path dir = test::unique_temp_path("external");
  std::filesystem::create_directories(dir / "sub dir");
  const GltfBuilder b = quad();
  {
    std::ofstream bin(dir / "sub dir" / "quad data.bin", std::ios::binary);
    bin.write(reinterpret_cast<const char*>(b.bin.data()),
              static_cast<std::streamsize>(b.bin.size()));
    std::ofstream gltf(dir / "sub dir" / "quad.gltf");
    gltf << b.gltf_text("quad%20data.bin");
  }
  auto asset = load_model(dir / "sub dir" / "quad.gltf");
  ASSERT_TRUE(asset.ok()) << asset.error().message;
  EXPECT_EQ(asset->vertices.size(), 4u);
  EXPECT_EQ(asset->source, (dir / "sub dir" / "quad.gltf").string());

  // From memory there is no folder: external files are refused, not looked for anywhere.
  const std::string text = b.gltf_text("quad%20data.bin");
  auto from_memory =
      load_model_from_memory(std::vector<std::uint8_t>(text.begin(), text.end()), "quad.gltf");
  ASSERT_FALSE(from_memory.ok());
  EXPECT_EQ(from_memory.error().message.rfind("quad.gltf: ", 0), 0u) << from_memory.error().message;

  // A missing .bin names the file.
  std::filesystem::remove(dir / "sub dir" / "quad data.bin");
  auto missing = load_model(dir / "sub dir" / "quad.gltf");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().message.find("quad data.bin"), std::string::npos)
      << missing.error().message;
  std::filesystem::remove_all(dir);
}

// A texture as a user's model carries it: a 2 x 2 PNG (red, green / blue, white), embedded, on
// the base colour with KHR_texture_transform, the quad's UVs read from TEXCOORD_0.
TEST(LoadModel, TexturesAreDecodedWithTheirUvsAndTransforms) {
  GltfBuilder b = quad();
  const std::vector<std::uint8_t> pixels{255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128};
  const std::vector<std::uint8_t> png = image::encode_png(pixels, 2, 2, 4);
  ASSERT_FALSE(png.empty());
  b.json["images"] = nlohmann::json::array(
      {{{"uri", "data:image/png;base64," + test::base64(png)}, {"name", "checker"}}});
  b.json["samplers"] = nlohmann::json::array({{{"magFilter", 9728}, {"wrapS", 33071}}});
  b.json["textures"] = nlohmann::json::array({{{"source", 0}, {"sampler", 0}}});
  b.json["materials"] = nlohmann::json::array(
      {{{"pbrMetallicRoughness",
         {{"baseColorTexture",
           {{"index", 0},
            {"extensions",
             {{"KHR_texture_transform",
               {{"offset", {0.5, 0.25}}, {"rotation", 1.5}, {"scale", {2.0, 3.0}}}}}}}}}},
        {"normalTexture", {{"index", 0}, {"texCoord", 1}, {"scale", 0.5}}},
        {"alphaMode", "MASK"},
        {"alphaCutoff", 0.3}}});
  b.json["extensionsUsed"] = {"KHR_texture_transform"};
  b.json["meshes"][0]["primitives"][0]["material"] = 0;
  const std::vector<float> uvs{0, 0, 1, 0, 1, 1, 0, 1};
  b.json["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] =
      b.add_data(uvs, test::kFloat, "VEC2");
  b.json["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_1"] =
      b.add_data(uvs, test::kFloat, "VEC2");
  const ModelAsset asset = must_load(b.gltf_bytes(), "textured.gltf");
  ASSERT_EQ(asset.images.size(), 1u);
  EXPECT_EQ(asset.images[0].mime_type, "image/png");
  EXPECT_EQ(asset.images[0].width, 2u);
  EXPECT_EQ(asset.images[0].height, 2u);
  EXPECT_EQ(asset.images[0].rgba, pixels);
  EXPECT_EQ(asset.images[0].encoded, png);
  ASSERT_EQ(asset.textures.size(), 1u);
  EXPECT_EQ(asset.textures[0].image, 0);
  EXPECT_EQ(asset.textures[0].mag_filter, 9728);
  EXPECT_EQ(asset.textures[0].wrap_s, 33071);
  EXPECT_EQ(asset.textures[0].wrap_t, 10497);
  const Material& m = asset.materials.at(0);
  EXPECT_EQ(m.base_color_texture.texture, 0);
  EXPECT_TRUE(m.base_color_texture.transformed);
  EXPECT_FLOAT_EQ(m.base_color_texture.offset.x, 0.5f);
  EXPECT_FLOAT_EQ(m.base_color_texture.offset.y, 0.25f);
  EXPECT_FLOAT_EQ(m.base_color_texture.rotation, 1.5f);
  EXPECT_FLOAT_EQ(m.base_color_texture.scale.y, 3.0f);
  EXPECT_EQ(m.normal_texture.texcoord, 1);
  EXPECT_FLOAT_EQ(m.normal_texture.amount, 0.5f);
  EXPECT_EQ(m.alpha_mode, AlphaMode::mask);
  EXPECT_FLOAT_EQ(m.alpha_cutoff, 0.3f);
  ASSERT_EQ(asset.vertices.size(), 4u);
  EXPECT_EQ(asset.vertices[2].uv0, glm::vec2(1.0f, 1.0f));
  EXPECT_EQ(asset.vertices[3].uv1, glm::vec2(0.0f, 1.0f));
}

// EXT_texture_webp: the WebP image (encoded here by libwebp's own encoder, lossless) is the one
// used, the PNG `source` only a fallback for readers without WebP.
TEST(LoadModel, WebpTexturesAreReadThroughTheirExtension) {
  GltfBuilder b = quad();
  const std::vector<std::uint8_t> pixels{10, 20, 30, 255, 40, 50, 60, 255, 70, 80, 90, 255, 100, 110, 120, 255};
  std::uint8_t* encoded = nullptr;
  const std::size_t size = WebPEncodeLosslessRGBA(pixels.data(), 2, 2, 8, &encoded);
  ASSERT_GT(size, 0u);
  const std::vector<std::uint8_t> webp(encoded, encoded + size);
  WebPFree(encoded);
  const std::vector<std::uint8_t> fallback = image::encode_png(std::vector<std::uint8_t>(16, 255), 2, 2, 4);
  b.json["images"] = nlohmann::json::array({{{"uri", "data:image/png;base64," + test::base64(fallback)}},
                                            {{"uri", "data:image/webp;base64," + test::base64(webp)}}});
  b.json["textures"] = nlohmann::json::array(
      {{{"source", 0}, {"extensions", {{"EXT_texture_webp", {{"source", 1}}}}}}});
  b.json["extensionsUsed"] = {"EXT_texture_webp"};
  b.json["extensionsRequired"] = {"EXT_texture_webp"};
  const ModelAsset asset = must_load(b.gltf_bytes(), "webp.gltf");
  ASSERT_EQ(asset.textures.size(), 1u);
  ASSERT_EQ(asset.textures[0].image, 1);
  const Image& image = asset.images[1];
  EXPECT_EQ(image.mime_type, "image/webp");
  EXPECT_EQ(image.rgba, pixels);
}

// An image that cannot be read is a one-line error naming it: a file that is not there, bytes
// that are not the PNG they claim.
TEST(LoadModel, ImagesThatCannotBeReadAreOneLineErrors) {
  GltfBuilder b = quad();
  b.json["images"] = nlohmann::json::array({{{"uri", "missing_texture.png"}}});
  b.json["textures"] = nlohmann::json::array({{{"source", 0}}});
  auto missing = load_model_from_memory(b.gltf_bytes(), "textured.gltf");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().message.find("image 0"), std::string::npos) << missing.error().message;
  EXPECT_EQ(missing.error().message.find('\n'), std::string::npos);
  b.json["images"] = nlohmann::json::array(
      {{{"uri", "data:image/png;base64," + test::base64({0x89, 'P', 'N', 'G', 13, 10, 26, 10, 1, 2})}}});
  auto broken = load_model_from_memory(b.gltf_bytes(), "textured.gltf");
  ASSERT_FALSE(broken.ok());
  EXPECT_NE(broken.error().message.find("textured.gltf: image 0: broken PNG image"),
            std::string::npos)
      << broken.error().message;
}

TEST(LoadModel, LoadsTheGeneratedPiano) {
  const std::filesystem::path piano = TUTTI_MODEL_TEST_PIANO_GLB;
  ASSERT_TRUE(std::filesystem::exists(piano)) << piano << " (built by tutti_content_assets)";
  auto asset = load_model(piano);
  ASSERT_TRUE(asset.ok()) << asset.error().message;
  int keys = 0;
  for (const Node& node : asset->nodes) {
    if (node.name.rfind("key_", 0) == 0) {
      ++keys;
      EXPECT_GE(node.mesh, 0) << node.name;
    }
  }
  EXPECT_EQ(keys, 88);
  EXPECT_FALSE(asset->roots.empty());
  EXPECT_FALSE(asset->materials.empty());
  for (const Mesh& mesh : asset->meshes) {
    for (const Primitive& p : mesh.primitives) {
      EXPECT_EQ(p.index_count % 3, 0u);
      for (std::uint32_t i = 0; i < p.index_count; ++i) {
        EXPECT_LT(asset->indices[p.first_index + i], p.vertex_count);
      }
    }
  }
}

}  // namespace
}  // namespace tutti::model

namespace tutti::model {
namespace {

// The fuzzer's seeds (tests/fuzz/seeds/gltf) must stay loadable, or they seed nothing.
TEST(LoadModel, FuzzSeedsAreValidModels) {
  const std::filesystem::path seeds = test::source_dir() / "tests" / "fuzz" / "seeds" / "gltf";
  auto strip = load_model(seeds / "skinned_strip.glb");
  ASSERT_TRUE(strip.ok()) << strip.error().message;
  EXPECT_EQ(strip->skins.size(), 1u);
  EXPECT_EQ(strip->vertices.size(), 12u);  // no normals in the file: flat, one vertex per corner
  auto face = load_model(seeds / "morph_triangle.gltf");
  ASSERT_TRUE(face.ok()) << face.error().message;
  EXPECT_EQ(face->meshes.at(0).target_names, (std::vector<std::string>{"smile"}));
  EXPECT_EQ(face->nodes.at(0).rest.scale, glm::vec3(2.0f));
}

}  // namespace
}  // namespace tutti::model
