// SPDX-License-Identifier: MIT
// Hostile and broken files: each is one line "NAME: reason", never a crash, hang or huge
// allocation (the asan build runs these under AddressSanitizer + UBSan).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <random>

#include "gltf_test_builder.hpp"
#include <tutti/model/model_asset.hpp>
#include "testdata.hpp"

namespace tutti::model {
namespace {

using test::GltfBuilder;
using test::kFloat;
using test::kUnsignedByte;
using test::kUnsignedShort;

// The error for `bytes`, checked to be one line that starts with the file name.
std::string error_for(const std::vector<std::uint8_t>& bytes, const std::string& name) {
  auto asset = load_model_from_memory(bytes, name);
  if (asset.ok()) {
    ADD_FAILURE() << name << " loaded, expected an error";
    return {};
  }
  const std::string& message = asset.error().message;
  EXPECT_EQ(message.rfind(name + ": ", 0), 0u) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_EQ(message.find('\r'), std::string::npos) << message;
  EXPECT_LT(message.size(), 500u) << message;
  return message;
}

void expect_error(const GltfBuilder& b, const std::string& name, const std::string& reason) {
  for (const bool binary : {true, false}) {
    const std::string file = name + (binary ? ".glb" : ".gltf");
    const std::string message = error_for(binary ? b.glb() : b.gltf_bytes(), file);
    EXPECT_EQ(message, file + ": " + reason);
  }
}

GltfBuilder strip() { return test::two_bone_strip(); }

TEST(HostileModel, JointsOutOfRangeNameTheMeshAndSkin) {
  GltfBuilder b;
  const std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<std::uint8_t> joints = {0, 0, 0, 0, 31, 0, 0, 0, 11, 0, 0, 0};
  const std::vector<float> weights(12, 0.25f);
  b.add_mesh({{"name", "palm"},
              {"primitives",
               {{{"attributes",
                  {{"POSITION", b.add_vec3s(positions)},
                   {"NORMAL", b.add_vec3s({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}})},
                   {"JOINTS_0", b.add_data(joints, kUnsignedByte, "VEC4")},
                   {"WEIGHTS_0", b.add_data(weights, kFloat, "VEC4")}}}}}}});
  std::vector<int> joint_nodes;
  for (int i = 0; i < 12; ++i)
    joint_nodes.push_back(b.add_node({{"name", "j" + std::to_string(i)}}));
  b.json["skins"] = nlohmann::json::array({{{"name", "hand"}, {"joints", joint_nodes}}});
  b.add_node({{"name", "palm"}, {"mesh", 0}, {"skin", 0}});
  const std::string message = error_for(b.glb(), "hand.glb");
  EXPECT_EQ(message,
            "hand.glb: mesh \"palm\" primitive 0: JOINTS_0 value 31 is not a joint of skin "
            "\"hand\" (12 joints)");
}

TEST(HostileModel, TruncatedGlbAtEveryInterestingLength) {
  const std::vector<std::uint8_t> whole = strip().glb();
  ASSERT_TRUE(load_model_from_memory(whole, "strip.glb").ok());
  std::vector<std::size_t> lengths = {1,
                                      3,
                                      4,
                                      8,
                                      11,
                                      12,
                                      16,
                                      19,
                                      20,
                                      21,
                                      27,
                                      28,
                                      100,
                                      whole.size() / 2,
                                      whole.size() - 8,
                                      whole.size() - 4,
                                      whole.size() - 1};
  for (std::size_t n = 0; n < whole.size(); n += 37) lengths.push_back(n == 0 ? 2 : n);
  for (const std::size_t n : lengths) {
    const std::vector<std::uint8_t> part(whole.begin(),
                                         whole.begin() + static_cast<std::ptrdiff_t>(n));
    error_for(part, "strip.glb");
  }
  EXPECT_EQ(error_for({whole.begin(), whole.begin() + 19}, "strip.glb"),
            "strip.glb: truncated .glb (19 bytes, the header alone is 20)");
  EXPECT_EQ(error_for({whole.begin(), whole.end() - 1}, "strip.glb"),
            "strip.glb: truncated .glb: header says " + std::to_string(whole.size()) +
                " bytes, file has " + std::to_string(whole.size() - 1));
}

TEST(HostileModel, GlbChunkLengthsThatLie) {
  std::vector<std::uint8_t> glb = strip().glb();
  auto put_u32 = [](std::vector<std::uint8_t>& bytes, std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i)
      bytes[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v >> (8 * i));
  };
  std::uint32_t json_length = 0;
  std::memcpy(&json_length, glb.data() + 12, 4);
  // BIN chunk claiming to reach the very end of the file (tinygltf alone would read 8 bytes past).
  std::vector<std::uint8_t> bin_lies = glb;
  put_u32(bin_lies, 20 + json_length, static_cast<std::uint32_t>(glb.size() - 20 - json_length));
  EXPECT_NE(error_for(bin_lies, "lies.glb").find("BIN chunk"), std::string::npos);
  std::vector<std::uint8_t> json_lies = glb;
  put_u32(json_lies, 12, 0xFFFFFFF0u);
  error_for(json_lies, "lies.glb");
  std::vector<std::uint8_t> version = glb;
  put_u32(version, 4, 1);
  EXPECT_EQ(error_for(version, "v1.glb"), "v1.glb: .glb version 1, only 2 is read");
}

TEST(HostileModel, AccessorPastTheEndOfItsBufferView) {
  GltfBuilder b = strip();
  b.json["accessors"][0]["count"] = 7;  // POSITION: 6 vec3 in a 72-byte view
  expect_error(b, "past_end",
               "mesh \"strip\" primitive 0: POSITION accessor 0: 7 elements of 12 bytes (stride "
               "12) from byte 0 run past the end of buffer view 0 (72 bytes)");
  GltfBuilder offset = strip();
  offset.json["accessors"][0]["byteOffset"] = 4;
  error_for(offset.glb(), "offset.glb");
}

TEST(HostileModel, BufferViewPastTheEndOfItsBuffer) {
  GltfBuilder b = strip();
  b.json["bufferViews"][0]["byteLength"] = 100000;
  b.json["accessors"][0]["count"] = 8000;
  expect_error(b, "view_past_end",
               "mesh \"strip\" primitive 0: POSITION buffer view 0: bytes 0 + 100000 run past "
               "the end of buffer 0 (" +
                   std::to_string(b.bin.size()) + " bytes)");
  GltfBuilder huge_offset = strip();
  huge_offset.json["bufferViews"][0]["byteOffset"] = std::uint64_t{18446744073709551000u};
  EXPECT_NE(error_for(huge_offset.glb(), "overflow.glb").find("run past the end of buffer 0"),
            std::string::npos);
  GltfBuilder huge_accessor_offset = strip();
  huge_accessor_offset.json["accessors"][0]["byteOffset"] = std::uint64_t{18446744073709551000u};
  EXPECT_NE(error_for(huge_accessor_offset.glb(), "overflow.glb").find("is past the end of"),
            std::string::npos);
  GltfBuilder huge_count = strip();
  huge_count.json["accessors"][1]["count"] = std::uint64_t{18446744073709551615u};  // NORMAL
  error_for(huge_count.glb(), "overflow.glb");
}

TEST(HostileModel, AHugeAccessorCountIsRefusedBeforeAllocating) {
  GltfBuilder b = strip();
  b.json["accessors"][0]["count"] = 1000000000;
  expect_error(b, "billion",
               "mesh \"strip\" primitive 0: POSITION accessor 0: count 1000000000 is over the "
               "limit of 1000000");
  GltfBuilder indices = strip();
  indices.json["accessors"][4]["count"] = 1000000000;  // the index accessor
  error_for(indices.glb(), "billion_indices.glb");
  // Without a buffer view an accessor is zeros: the cap still applies first.
  GltfBuilder zeros = strip();
  zeros.json["accessors"][0].erase("bufferView");
  zeros.json["accessors"][0]["count"] = 999999999;
  error_for(zeros.glb(), "zeros.glb");
}

TEST(HostileModel, IndexOutOfRange) {
  GltfBuilder b;
  test::add_triangle_mesh(b, "tri", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 3});
  expect_error(b, "index",
               "mesh \"tri\" primitive 0: index 3 is past the last vertex (3 vertices)");
  GltfBuilder partial;
  test::add_triangle_mesh(partial, "tri", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2, 0});
  expect_error(partial, "partial",
               "mesh \"tri\" primitive 0: 4 indices, not a whole number of triangles");
}

TEST(HostileModel, CyclesAndTwoParents) {
  GltfBuilder cycle;
  cycle.add_node({{"name", "a"}, {"children", {1}}});
  cycle.add_node({{"name", "b"}, {"children", {2}}});
  cycle.add_node({{"name", "c"}, {"children", {1}}});
  expect_error(cycle, "cycle", "node 1 \"b\" has two parents (node 0 \"a\" and node 2 \"c\")");
  GltfBuilder ring;
  ring.add_node({{"name", "a"}, {"children", {1}}});
  ring.add_node({{"name", "b"}, {"children", {0}}});
  ring.add_node({{"name", "free"}});
  expect_error(ring, "ring", "node 0 \"a\" is its own ancestor (a cycle in the node tree)");
  GltfBuilder self;
  self.add_node({{"children", {0}}});
  expect_error(self, "self", "node 0 is its own child");
  GltfBuilder twice;
  twice.add_node({{"children", {1, 1}}});
  twice.add_node({{"name", "leaf"}});
  expect_error(twice, "twice", "node 1 \"leaf\" is listed twice as a child of node 0");
  GltfBuilder missing;
  missing.add_node({{"children", {7}}});
  expect_error(missing, "missing", "node 0: child 7 does not exist (the file has 1 nodes)");
}

TEST(HostileModel, WrongComponentTypesAndTypes) {
  GltfBuilder b = strip();
  // KHR_mesh_quantization allows byte and short positions; 32-bit integers never.
  b.json["accessors"][0]["componentType"] = test::kUnsignedInt;
  b.json["accessors"][0]["count"] = 1;
  expect_error(b, "component",
               "mesh \"strip\" primitive 0: POSITION accessor 0: component type unsigned int "
               "is not allowed here");
  GltfBuilder type = strip();
  type.json["accessors"][0]["type"] = "VEC2";
  expect_error(type, "type",
               "mesh \"strip\" primitive 0: POSITION accessor 0: type VEC2, expected VEC3");
  GltfBuilder joints = strip();
  joints.json["accessors"][2]["componentType"] = kFloat;  // JOINTS_0 as float
  joints.json["accessors"][2]["count"] = 1;
  error_for(joints.glb(), "joints.glb");
  GltfBuilder weights = strip();
  weights.json["accessors"][3]["componentType"] = kUnsignedByte;  // not normalized
  error_for(weights.glb(), "weights.glb");
}

TEST(HostileModel, NonTriangleModesNameTheMesh) {
  GltfBuilder b = strip();
  b.json["meshes"][0]["primitives"][0]["mode"] = 1;
  expect_error(b, "lines",
               "mesh \"strip\" primitive 0: mode 1 (lines) is not supported, only triangles");
  b.json["meshes"][0]["primitives"][0]["mode"] = 5;
  expect_error(b, "strips",
               "mesh \"strip\" primitive 0: mode 5 (triangle strip) is not supported, only "
               "triangles");
}

TEST(HostileModel, SkinProblems) {
  GltfBuilder range = strip();
  range.json["skins"][0]["joints"] = {0, 9};
  expect_error(range, "range", "skin \"strip_skin\": joint 9 is not a node (the file has 3)");
  GltfBuilder few = strip();
  few.json["skins"][0]["joints"] = {0, 1, 2};
  expect_error(few, "few",
               "skin \"strip_skin\": inverseBindMatrices accessor 5: 2 matrices, 3 needed");
  GltfBuilder many;
  std::vector<int> joints;
  for (int i = 0; i < 257; ++i) joints.push_back(many.add_node(nlohmann::json::object()));
  many.json["skins"] = nlohmann::json::array({{{"joints", joints}}});
  expect_error(many, "many", "skin 0: 257 joints, at most 256");
  GltfBuilder no_weights = strip();
  no_weights.json["meshes"][0]["primitives"][0]["attributes"].erase("JOINTS_0");
  no_weights.json["meshes"][0]["primitives"][0]["attributes"].erase("WEIGHTS_0");
  expect_error(no_weights, "unweighted",
               "mesh \"strip\" primitive 0: no JOINTS_0/WEIGHTS_0, but node 2 \"strip\" draws "
               "it with skin \"strip_skin\"");
}

TEST(HostileModel, MatricesThatAreNotTrs) {
  GltfBuilder shear;
  shear.add_node({{"matrix", {1, 0, 0, 0, 0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}});
  expect_error(shear, "shear", "node 0: matrix has shear (not a translation, rotation and scale)");
  GltfBuilder projective;
  projective.add_node({{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0.1, 0, 0, 0, 1}}});
  expect_error(projective, "projective", "node 0: matrix is not affine (last row is not 0 0 0 1)");
  GltfBuilder zero_quat;
  zero_quat.add_node({{"rotation", {0, 0, 0, 0}}});
  expect_error(zero_quat, "zero_quat", "node 0: rotation quaternion is zero");
}

TEST(HostileModel, MorphTargetMismatches) {
  GltfBuilder b = strip();
  const int delta = b.add_vec3s(std::vector<glm::vec3>(5, {0, 0, 1}));
  b.json["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", delta}}};
  expect_error(b, "short_target",
               "mesh \"strip\" primitive 0 morph target 0: POSITION has 5 elements, POSITION "
               "has 6");
  GltfBuilder counts = strip();
  counts.json["meshes"][0]["primitives"].push_back(counts.json["meshes"][0]["primitives"][0]);
  counts.json["meshes"][0]["primitives"][1]["targets"] = {{{"POSITION", 0}}};
  expect_error(counts, "target_counts",
               "mesh \"strip\" primitive 1: 1 morph targets, primitive 0 has 0");
}

TEST(HostileModel, SparseAccessorsAndBadReferences) {
  // Sparse accessors are read (pipeline_gltf_test.cpp); their indices are checked: here the
  // strip's index data (values up to 5) as sparse indices into a 2-element accessor.
  GltfBuilder sparse = strip();
  sparse.json["accessors"][1]["count"] = 2;
  sparse.json["accessors"][1]["sparse"] = {
      {"count", 2},
      {"indices", {{"bufferView", 4}, {"byteOffset", 2}, {"componentType", kUnsignedShort}}},
      {"values", {{"bufferView", 0}}}};
  EXPECT_NE(error_for(sparse.glb(), "sparse.glb").find("sparse index"), std::string::npos);
  GltfBuilder too_many = strip();
  too_many.json["accessors"][0]["sparse"] = {
      {"count", 7},
      {"indices", {{"bufferView", 4}, {"componentType", kUnsignedShort}}},
      {"values", {{"bufferView", 0}}}};
  EXPECT_NE(error_for(too_many.glb(), "too_many.glb").find("7 sparse values for 6 elements"),
            std::string::npos);
  GltfBuilder material = strip();
  material.json["meshes"][0]["primitives"][0]["material"] = 3;
  expect_error(material, "material",
               "mesh \"strip\" primitive 0: material 3 does not exist (the file has 0)");
  GltfBuilder mesh = strip();
  mesh.json["nodes"][2]["mesh"] = 5;
  expect_error(mesh, "mesh", "node 2 \"strip\": mesh 5 does not exist (the file has 1)");
  GltfBuilder scene = strip();
  scene.json["scene"] = 4;
  error_for(scene.glb(), "scene.glb");
  GltfBuilder child_root = strip();
  child_root.set_scene({1});
  expect_error(child_root, "child_root",
               "scene 0: node 1 \"tip_joint\" is a root but has a parent");
  GltfBuilder stride = strip();
  stride.json["bufferViews"][0]["byteStride"] = 8;
  error_for(stride.glb(), "stride.glb");
}

TEST(HostileModel, HostileJson) {
  const std::vector<std::string> texts = {
      "",
      "{",
      "[]",
      "null",
      "{\"asset\":{\"version\":\"2.0\"},\"nodes\":{}}",
      "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{\"children\":[-1]}]}",
      "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{\"mesh\":1e300}]}",
      "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":4,\"uri\":\"/dev/zero\"}]}",
      "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":4,\"uri\":\"data:,AAAA\"}]}",
      "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":99,"
      "\"uri\":\"data:application/octet-stream;base64,AAAA\"}]}",
  };
  for (const std::string& text : texts) {
    const std::vector<std::uint8_t> bytes(text.begin(), text.end());
    auto asset = load_model_from_memory(bytes, "bad.gltf");
    if (asset.ok()) continue;  // a few of these are valid (empty) models for tinygltf
    const std::string& message = asset.error().message;
    EXPECT_EQ(message.rfind("bad.gltf: ", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  // Deep nesting in extras (tinygltf converts extras recursively) is refused up front.
  std::string deep = "{\"asset\":{\"version\":\"2.0\"},\"extras\":";
  deep += std::string(100000, '[') + std::string(100000, ']') + "}";
  EXPECT_EQ(error_for({deep.begin(), deep.end()}, "deep.gltf"),
            "deep.gltf: JSON nested deeper than 64 levels, refused");
  EXPECT_EQ(error_for({'{', '"', 'a'}, "cut.gltf"), "cut.gltf: invalid JSON at byte 4");
}

TEST(HostileModel, RandomBytesNeverCrash) {
  std::mt19937 random(20261122);
  const std::vector<std::uint8_t> valid_glb = strip().glb();
  const std::vector<std::uint8_t> valid_gltf = strip().gltf_bytes();
  for (int round = 0; round < 300; ++round) {
    std::vector<std::uint8_t> bytes;
    const int kind = round % 3;
    if (kind == 0) {
      bytes.resize(random() % 2000 + 1);
      for (auto& b : bytes) b = static_cast<std::uint8_t>(random());
      if (round % 2 == 0 && bytes.size() >= 4) std::memcpy(bytes.data(), "glTF", 4);
    } else {
      // Flip a few bytes of a valid file.
      bytes = kind == 1 ? valid_glb : valid_gltf;
      for (int i = 0; i < 1 + round % 8; ++i) {
        bytes[random() % bytes.size()] = static_cast<std::uint8_t>(random());
      }
    }
    auto asset = load_model_from_memory(bytes, "random.glb");
    if (!asset.ok()) {
      EXPECT_EQ(asset.error().message.rfind("random.glb: ", 0), 0u) << asset.error().message;
      EXPECT_EQ(asset.error().message.find('\n'), std::string::npos);
    }
  }
}

TEST(HostileModel, MissingAndEmptyFiles) {
  const std::filesystem::path dir = test::unique_temp_path("files");
  std::filesystem::create_directories(dir);
  auto missing = load_model(dir / "nope.glb");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().message, (dir / "nope.glb").string() + ": no such file");
  { std::ofstream empty(dir / "empty.glb"); }
  auto empty = load_model(dir / "empty.glb");
  ASSERT_FALSE(empty.ok());
  EXPECT_EQ(empty.error().message, (dir / "empty.glb").string() + ": empty file");
  auto directory = load_model(dir);
  ASSERT_FALSE(directory.ok());
  EXPECT_EQ(directory.error().message.rfind(dir.string() + ": ", 0), 0u);
  EXPECT_EQ(error_for({}, "empty.gltf"), "empty.gltf: empty file");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tutti::model
