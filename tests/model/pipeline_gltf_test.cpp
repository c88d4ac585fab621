// SPDX-License-Identifier: MIT
// glTF as real pipelines write it (engine/model/gltf_extensions.hpp): gltfpack's quantized and
// meshopt-compressed output of the project's own models loads to the same shapes; sparse
// accessors, eight weights per vertex and quantized attributes read as the spec says; required
// extensions tutti does not read, and broken compressed data, are one-line errors.
#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>
#include <dlfcn.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "gltf_test_builder.hpp"
#include "scratch_dir.hpp"
#include <tutti/model/model_asset.hpp>

namespace tutti::model {
namespace {

using test::GltfBuilder;
using test::kFloat;
using test::kShort;
using test::kUnsignedByte;
using test::kUnsignedShort;

struct Bounds {
  glm::vec3 min{1e9f}, max{-1e9f};
  std::size_t vertices = 0;
};

// World-space bounds of every drawn vertex at the rest pose (skinning and morphs included).
Bounds rest_bounds(const ModelAsset& asset) {
  const ModelPose pose = rest_pose(asset);
  std::vector<glm::mat4> world(asset.nodes.size());
  compute_world_matrices(asset, pose, glm::mat4(1.0f), world);
  Bounds b;
  for (std::size_t n = 0; n < asset.nodes.size(); ++n) {
    const Node& node = asset.nodes[n];
    if (node.mesh < 0) continue;
    const Mesh& mesh = asset.meshes[static_cast<std::size_t>(node.mesh)];
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
      for (std::uint32_t v = 0; v < mesh.primitives[p].vertex_count; ++v) {
        const glm::vec3 at =
            deform_vertex(asset, pose, world, static_cast<int>(n), static_cast<int>(p), v).position;
        b.min = glm::min(b.min, at);
        b.max = glm::max(b.max, at);
        ++b.vertices;
      }
    }
  }
  return b;
}

std::string gltfpack(const std::filesystem::path& in, const std::filesystem::path& out,
                     const std::string& options) {
  const std::string command = "gltfpack " + options + " -i '" + in.string() + "' -o '" +
                              out.string() + "' > /dev/null 2>&1";
  return std::system(command.c_str()) == 0 ? std::string() : command;
}

std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The performer (skinned, 70 joints, face morphs) and the trumpet (rigid parts on named nodes),
// packed by Debian's gltfpack three ways: quantized (KHR_mesh_quantization), and compressed
// (EXT_meshopt_compression, -c and -cc). Each loads, and its rest shape spans the same box as
// the original within the quantization's error.
TEST(PipelineGltf, GltfpackOutputLoadsToTheSameShape) {
  if (std::system("command -v gltfpack > /dev/null 2>&1") != 0) {
    GTEST_SKIP() << "no gltfpack (Debian package gltfpack, in scripts/packages-test.txt)";
  }
  test::ScratchDir dir;
  for (const char* name : {"performer.glb", "trumpet.glb"}) {
    const std::filesystem::path original = std::filesystem::path(TUTTI_MODEL_TEST_ASSET_DIR) / name;
    auto reference = load_model(original);
    ASSERT_TRUE(reference) << reference.error().message;
    const Bounds expected = rest_bounds(*reference);
    for (const char* options : {"-kn -km", "-kn -km -c", "-kn -km -cc"}) {
      const std::filesystem::path packed =
          dir.path() / (std::string(options).substr(7) + "_" + name);
      ASSERT_EQ(gltfpack(original, packed, options), "");
      const std::string text = file_text(packed);
      EXPECT_NE(text.find("KHR_mesh_quantization"), std::string::npos) << options;
      if (std::string(options).find("-c") != std::string::npos) {
        EXPECT_NE(text.find("EXT_meshopt_compression"), std::string::npos) << options;
      }
      auto asset = load_model(packed);
      ASSERT_TRUE(asset) << options << ": " << asset.error().message;
      const Bounds got = rest_bounds(*asset);
      EXPECT_GT(got.vertices, 0u);
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(got.min[c], expected.min[c], 0.002f) << name << " " << options << " axis " << c;
        EXPECT_NEAR(got.max[c], expected.max[c], 0.002f) << name << " " << options << " axis " << c;
      }
      // Named nodes survive (-kn): the rig's roles and the valves are found by name.
      for (const char* node : {"hand_r", "head", "valve_2"}) {
        if (reference->find_node(node) >= 0) {
          EXPECT_GE(asset->find_node(node), 0) << node;
        }
      }
      EXPECT_EQ(asset->skins.size(), reference->skins.size()) << options;
    }
  }
}

// A Draco-compressed primitive, encoded by Debian's libdraco (its own encoder, sequential, without
// quantization): the decoded positions and triangles are the ones encoded.
TEST(PipelineGltf, DracoPrimitivesAreDecoded) {
  const std::vector<glm::vec3> points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5f, 2, 0.25f}};
  const std::vector<std::array<std::uint32_t, 3>> faces = {{0, 1, 2}, {0, 2, 3}, {3, 2, 4}};
  draco::Mesh mesh;
  draco::GeometryAttribute position;
  position.Init(draco::GeometryAttribute::POSITION, nullptr, 3, draco::DT_FLOAT32, false,
                sizeof(float) * 3, 0);
  const int id = mesh.AddAttribute(position, true, static_cast<std::uint32_t>(points.size()));
  mesh.set_num_points(static_cast<std::uint32_t>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    mesh.attribute(id)->SetAttributeValue(draco::AttributeValueIndex(static_cast<std::uint32_t>(i)),
                                          &points[i].x);
  }
  for (const auto& f : faces) {
    mesh.AddFace({draco::PointIndex(f[0]), draco::PointIndex(f[1]), draco::PointIndex(f[2])});
  }
  draco::Encoder encoder;
  encoder.SetEncodingMethod(draco::MESH_SEQUENTIAL_ENCODING);
  draco::EncoderBuffer encoded;
  const draco::Status encoded_ok = encoder.EncodeMeshToBuffer(mesh, &encoded);
  ASSERT_TRUE(encoded_ok.ok()) << encoded_ok.error_msg_string();

  GltfBuilder b;
  const int view = b.add_view(encoded.data(), encoded.size());
  b.json["accessors"] = nlohmann::json::array(
      {{{"componentType", kFloat}, {"type", "VEC3"}, {"count", points.size()}},
       {{"componentType", kUnsignedShort}, {"type", "SCALAR"}, {"count", faces.size() * 3}}});
  b.add_mesh({{"name", "kite"},
              {"primitives",
               {{{"attributes", {{"POSITION", 0}}},
                 {"indices", 1},
                 {"extensions",
                  {{"KHR_draco_mesh_compression",
                    {{"bufferView", view},
                     {"attributes", {{"POSITION", mesh.attribute(id)->unique_id()}}}}}}}}}}});
  b.add_node({{"name", "kite"}, {"mesh", 0}});
  b.set_scene({0});
  b.json["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  b.json["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  for (const bool binary : {true, false}) {
    auto asset = test::load_bytes(binary ? b.glb() : b.gltf_bytes(), "kite.glb");
    ASSERT_TRUE(asset) << asset.error().message;
    // No normals in the file: every corner becomes its own vertex (flat normals).
    ASSERT_EQ(asset->indices.size(), 9u);
    for (std::size_t corner = 0; corner < 9; ++corner) {
      EXPECT_EQ(asset->vertices.at(asset->indices[corner]).position,
                points[faces[corner / 3][corner % 3]])
          << corner;
    }
  }
  // The compressed bytes cut short: one line naming the extension.
  b.json["bufferViews"][static_cast<std::size_t>(view)]["byteLength"] = encoded.size() / 2;
  auto cut = test::load_bytes(b.glb(), "cut.glb");
  ASSERT_FALSE(cut);
  EXPECT_NE(cut.error().message.find("KHR_draco_mesh_compression"), std::string::npos)
      << cut.error().message;
  EXPECT_EQ(cut.error().message.find('\n'), std::string::npos);
}

// libdraco.so exports its own tinygltf: the loader's tinygltf calls must bind to Debian's
// libtinygltf, not to it.
TEST(PipelineGltf, TinygltfIsTheSystemLibrary) {
  Dl_info info{};
  bool (tinygltf::TinyGLTF::*load)(tinygltf::Model*, std::string*, std::string*,
                                   const unsigned char*, unsigned int, const std::string&,
                                   unsigned int) = &tinygltf::TinyGLTF::LoadBinaryFromMemory;
  void* address = nullptr;
  static_assert(sizeof(load) >= sizeof(address));
  std::memcpy(&address, &load, sizeof(address));
  ASSERT_NE(dladdr(address, &info), 0);
  EXPECT_NE(std::string(info.dli_fname).find("tinygltf"), std::string::npos) << info.dli_fname;
}

// A required extension that tutti does not read: one line naming it.
TEST(PipelineGltf, UnreadRequiredExtensionsAreNamed) {
  GltfBuilder b = test::two_bone_strip();
  b.json["extensionsUsed"] = {"EXT_made_up"};
  b.json["extensionsRequired"] = {"EXT_made_up"};
  auto asset = test::load_bytes(b.glb(), "made_up.glb");
  ASSERT_FALSE(asset);
  EXPECT_EQ(asset.error().message,
            "made_up.glb: requires the glTF extension EXT_made_up, which tutti does not read");
  b.json["extensionsRequired"] = {"EXT_made_up", "KHR_mesh_quantization"};
  asset = test::load_bytes(b.gltf_bytes(), "made_up.gltf");
  ASSERT_FALSE(asset);
  EXPECT_EQ(asset.error().message.find('\n'), std::string::npos);
  // Appearance-only extensions leave the geometry whole: the file loads.
  b.json["extensionsRequired"] = {"KHR_texture_transform", "KHR_materials_unlit"};
  EXPECT_TRUE(test::load_bytes(b.glb(), "looks.glb"));
}

// A sparse POSITION accessor: the base view's values, two of them replaced.
TEST(PipelineGltf, SparseAccessorsAreWrittenOutDense) {
  GltfBuilder b = test::two_bone_strip();
  const std::vector<std::uint16_t> at = {1, 4};
  const std::vector<float> values = {9, 8, 7, 6, 5, 4};
  b.json["accessors"][0]["sparse"] = {
      {"count", 2},
      {"indices", {{"bufferView", b.add_view(at.data(), 4)}, {"componentType", kUnsignedShort}}},
      {"values", {{"bufferView", b.add_view(values.data(), 24)}}}};
  for (const bool binary : {true, false}) {
    auto asset = test::load_bytes(binary ? b.glb() : b.gltf_bytes(), "sparse.glb");
    ASSERT_TRUE(asset) << asset.error().message;
    EXPECT_EQ(asset->vertices[0].position, glm::vec3(-0.5f, 0, 0));
    EXPECT_EQ(asset->vertices[1].position, glm::vec3(9, 8, 7));
    EXPECT_EQ(asset->vertices[2].position, glm::vec3(-0.5f, 1, 0));
    EXPECT_EQ(asset->vertices[4].position, glm::vec3(6, 5, 4));
  }
  // Without a base view the rest are zeros.
  b.json["accessors"][0].erase("bufferView");
  auto asset = test::load_bytes(b.glb(), "sparse_zero.glb");
  ASSERT_TRUE(asset) << asset.error().message;
  EXPECT_EQ(asset->vertices[0].position, glm::vec3(0));
  EXPECT_EQ(asset->vertices[4].position, glm::vec3(6, 5, 4));
}

// Eight influences: the four largest kept, renormalised, and the asset says so.
TEST(PipelineGltf, EightWeightsBecomeTheFourLargest) {
  GltfBuilder b = test::two_bone_strip();
  const std::vector<std::uint8_t> joints_1(24, 1);
  std::vector<float> weights_1(24, 0.0f);
  weights_1[0] = 3.0f;  // vertex 0: joint 1 weighs 3 against joint 0's 1
  b.json["meshes"][0]["primitives"][0]["attributes"]["JOINTS_1"] =
      b.add_data(joints_1, kUnsignedByte, "VEC4");
  b.json["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_1"] =
      b.add_data(weights_1, kFloat, "VEC4");
  auto asset = test::load_bytes(b.glb(), "eight.glb");
  ASSERT_TRUE(asset) << asset.error().message;
  EXPECT_EQ(asset->primitives_over_four_weights, 1u);
  const Vertex& v = asset->vertices[0];
  EXPECT_EQ(v.joints[0], 1u);
  EXPECT_FLOAT_EQ(v.weights[0], 0.75f);
  EXPECT_EQ(v.joints[1], 0u);
  EXPECT_FLOAT_EQ(v.weights[1], 0.25f);
  b.json["meshes"][0]["primitives"][0]["attributes"].erase("WEIGHTS_1");
  auto half = test::load_bytes(b.glb(), "half.glb");
  ASSERT_FALSE(half);
  EXPECT_NE(half.error().message.find("JOINTS_1 without WEIGHTS_1"), std::string::npos);
}

// KHR_mesh_quantization: normalized short positions and normals.
TEST(PipelineGltf, QuantizedAttributesAreDequantized) {
  GltfBuilder b;
  // Three vertices, each VEC3 of short padded to 8 bytes (stride 8, as the extension requires).
  const std::vector<std::int16_t> positions = {0, 0, 0, 0, 32767, 0, 0, 0, 0, 32767, 0, 0};
  const std::vector<std::int16_t> normals = {0, 0, 32767, 0, 0, 0, 32767, 0, 0, 0, 32767, 0};
  const int pv = b.add_view(positions.data(), 24, 8);
  const int nv = b.add_view(normals.data(), 24, 8);
  b.add_mesh({{"name", "tri"},
              {"primitives",
               {{{"attributes",
                  {{"POSITION", b.add_accessor(pv, kShort, "VEC3", 3, 0, true)},
                   {"NORMAL", b.add_accessor(nv, kShort, "VEC3", 3, 0, true)}}}}}}});
  b.add_node({{"name", "tri"}, {"mesh", 0}, {"scale", {2, 2, 2}}});
  b.set_scene({0});
  b.json["extensionsUsed"] = {"KHR_mesh_quantization"};
  b.json["extensionsRequired"] = {"KHR_mesh_quantization"};
  auto asset = test::load_bytes(b.glb(), "quantized.glb");
  ASSERT_TRUE(asset) << asset.error().message;
  EXPECT_EQ(asset->vertices[1].position, glm::vec3(1, 0, 0));
  EXPECT_EQ(asset->vertices[2].position, glm::vec3(0, 1, 0));
  EXPECT_EQ(asset->vertices[0].normal, glm::vec3(0, 0, 1));
  // Unnormalized shorts are not a normal: refused.
  b.json["accessors"][1].erase("normalized");
  EXPECT_FALSE(test::load_bytes(b.glb(), "bad_normal.glb"));
}

// Broken meshopt data: every cut of a compressed file is an error, never a crash; a stride the
// decoder cannot take is named.
TEST(PipelineGltf, BrokenMeshoptDataIsAnError) {
  if (std::system("command -v gltfpack > /dev/null 2>&1") != 0) {
    GTEST_SKIP() << "no gltfpack (Debian package gltfpack, in scripts/packages-test.txt)";
  }
  test::ScratchDir dir;
  const std::filesystem::path packed = dir.path() / "trumpet_cc.glb";
  ASSERT_EQ(gltfpack(std::filesystem::path(TUTTI_MODEL_TEST_ASSET_DIR) / "trumpet.glb", packed,
                     "-cc"),
            "");
  const std::string text = file_text(packed);
  std::vector<std::uint8_t> bytes(text.begin(), text.end());
  // Flip bytes through the BIN chunk: decoding fails or gives other numbers, never a crash.
  for (std::size_t at = bytes.size() / 2; at < bytes.size(); at += 97) {
    std::vector<std::uint8_t> damaged = bytes;
    damaged[at] ^= 0x5A;
    (void)test::load_bytes(damaged, "damaged.glb");
  }
  // The first compressed view's declared stride made one the decoder cannot take (+1: no longer a
  // multiple of 4), the JSON keeping its length.
  const std::size_t ext = text.find("\"EXT_meshopt_compression\":{\"buffer\"");
  ASSERT_NE(ext, std::string::npos);
  std::size_t digit = text.find("\"byteStride\":", ext);
  ASSERT_NE(digit, std::string::npos);
  digit += 13;
  while (digit + 1 < text.size() && text[digit + 1] >= '0' && text[digit + 1] <= '9') ++digit;
  std::string bad = text;
  ASSERT_LT(bad[digit], '9');
  ++bad[digit];
  auto asset = test::load_bytes({bad.begin(), bad.end()}, "stride.glb");
  ASSERT_FALSE(asset);
  EXPECT_NE(asset.error().message.find("EXT_meshopt_compression"), std::string::npos)
      << asset.error().message;
}

}  // namespace
}  // namespace tutti::model
