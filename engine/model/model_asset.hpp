// SPDX-License-Identifier: MIT
#pragma once
// ModelAsset: a glTF 2.0 model (node hierarchy, meshes, metallic-roughness materials, skins,
// morph targets) flattened into plain arrays the renderer uploads as they are, and that the pose
// code and the exporter (issue 9) read. No Vulkan here: loading, posing and the skinning maths
// are testable on any machine.
//
// Units and axes are glTF's: metres, +Y up, right-handed. Baked glTF animations are ignored:
// tutti's systems drive the nodes and morph weights every frame (ModelPose).
//
// Vertex data of every primitive is in one array (`vertices`), indices in another (`indices`,
// relative to the primitive's `first_vertex`), morph deltas in a third; a primitive says where
// its slices start. Ownership: plain values, no handles; copy or move freely.

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <tutti/core/result.hpp>

namespace tutti::model {

// What the vertex shader reads, interleaved (72 bytes).
struct Vertex {
  glm::vec3 position{0.0f};  // mesh space, metres
  glm::vec3 normal{0.0f, 1.0f, 0.0f};
  glm::uvec4 joints{0};     // indices into the skin's joint list (JOINTS_0); 0 when unskinned
  glm::vec4 weights{0.0f};  // WEIGHTS_0, normalised to sum 1; all 0 when unskinned
  glm::vec2 uv0{0.0f};      // TEXCOORD_0 (0 when absent)
  glm::vec2 uv1{0.0f};      // TEXCOORD_1
};

// One morph target's change to one vertex (POSITION and NORMAL deltas; 0 where absent).
struct MorphDelta {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f};
};

struct Primitive {
  std::uint32_t first_vertex = 0;  // into ModelAsset::vertices
  std::uint32_t vertex_count = 0;
  std::uint32_t first_index = 0;  // into ModelAsset::indices (values are relative to first_vertex)
  std::uint32_t index_count = 0;  // a multiple of 3 (triangle lists only)
  int material = -1;              // into ModelAsset::materials; -1 = the default material
  // Target k's delta for vertex v (0-based inside the primitive) is
  // morph_deltas[first_morph_delta + k * vertex_count + v]; k < the mesh's target count.
  std::uint32_t first_morph_delta = 0;
};

struct Mesh {
  std::string name;
  std::vector<Primitive> primitives;
  std::vector<std::string> target_names;  // mesh.extras.targetNames, else "target_0", ...
  std::vector<float> default_weights;     // mesh.weights, else 0; size = target count
};

// An image as the file holds it (PNG, JPEG or WebP bytes) and decoded to 8-bit RGBA, rows top
// to bottom.
struct Image {
  std::string name;
  std::string mime_type;  // "image/png", "image/jpeg", "image/webp"
  std::vector<std::uint8_t> encoded;
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> rgba;
};

// A texture: its image and how it is sampled (glTF sampler enums; 0 = unset).
struct Texture {
  int image = -1;  // into ModelAsset::images (EXT_texture_webp's source when it has one)
  int mag_filter = 0, min_filter = 0;
  int wrap_s = 10497, wrap_t = 10497;  // REPEAT
};

// A material's use of a texture: which one, which UV set, and KHR_texture_transform.
struct TextureRef {
  int texture = -1;  // into ModelAsset::textures; -1 = none
  int texcoord = 0;  // TEXCOORD_0 or _1
  glm::vec2 offset{0.0f};
  float rotation = 0.0f;  // radians
  glm::vec2 scale{1.0f};
  bool transformed = false;  // KHR_texture_transform present
  // normalTexture.scale, occlusionTexture.strength; 1 otherwise.
  float amount = 1.0f;
  bool present() const { return texture >= 0; }
};

enum class AlphaMode { opaque, mask, blend };

struct Material {
  std::string name;
  glm::vec4 base_color{1.0f};  // linear RGBA (baseColorFactor)
  float metallic = 1.0f;
  float roughness = 1.0f;
  glm::vec3 emissive{0.0f};
  bool double_sided = false;
  AlphaMode alpha_mode = AlphaMode::opaque;
  float alpha_cutoff = 0.5f;
  TextureRef base_color_texture;          // sRGB
  TextureRef metallic_roughness_texture;  // linear: G roughness, B metallic
  TextureRef normal_texture;              // tangent space (amount = scale)
  TextureRef occlusion_texture;           // R (amount = strength)
  TextureRef emissive_texture;            // sRGB
};

struct NodeTransform {
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // glm: (w, x, y, z)
  glm::vec3 scale{1.0f};
};

struct Node {
  std::string name;
  int parent = -1;  // -1 = a root
  std::vector<int> children;
  NodeTransform rest;  // the file's TRS (a `matrix` is decomposed; non-TRS matrices are errors)
  int mesh = -1;       // into ModelAsset::meshes
  int skin = -1;       // into ModelAsset::skins
  // The node's `extras` members that are numbers (a valve's travel_mm, a bell's profile), by name.
  std::vector<std::pair<std::string, double>> numbers;
  double number(std::string_view key, double fallback) const {
    for (const auto& [member, value] : numbers) {
      if (member == key) return value;
    }
    return fallback;
  }
};

struct Skin {
  std::string name;
  std::vector<int> joints;              // node indices
  std::vector<glm::mat4> inverse_bind;  // one per joint (identity when the file has none)
};

struct ModelAsset {
  std::string source;  // file name, for messages
  // Parents always come before their children (the loader reorders and remaps if the file
  // does not), so one forward pass computes world matrices.
  std::vector<Node> nodes;
  std::vector<int> roots;  // the default scene's root nodes (all parentless nodes if none)
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<Image> images;
  std::vector<Skin> skins;
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;
  std::vector<MorphDelta> morph_deltas;
  // Primitives whose vertices had eight influences (JOINTS_1 / WEIGHTS_1), cut to the four
  // largest and renormalised: tools print a note when this is not 0.
  std::size_t primitives_over_four_weights = 0;
  // A VRM file's humanoid bone table: (VRM bone name, node), and "VRM 0.x" / "VRM 1.0"; empty
  // for other files (engine/humanoid recognises those by their bone names and hierarchy).
  std::vector<std::pair<std::string, int>> humanoid_table;
  std::string humanoid_table_source;

  // Index of the first node with this exact name, -1 if none.
  int find_node(std::string_view name) const;
  // Total morph target count over all meshes (the length of a pose's morph_weights).
  std::size_t morph_weight_count() const;
};

// Reads a .glb or .gltf file (external buffers and images next to a .gltf are allowed; data:
// URIs too); PNG, JPEG and WebP images are decoded (gltf_images.hpp). Every index, accessor range, joint, parent link and count is checked:
// a hostile or truncated file is an Error "FILE: reason", never a crash. Caps: 1,000,000
// vertices, 65,536 nodes, 256 joints per skin.
Result<ModelAsset> load_model(const std::filesystem::path& path);
// The same from bytes already in memory (`name` is used in messages and to tell .glb by magic).
Result<ModelAsset> load_model_from_memory(std::span<const std::uint8_t> bytes,
                                          const std::string& name);

// What the systems write every frame for one instance of a model: each node's local transform
// and every morph weight. Starts as the rest pose.
struct ModelPose {
  std::vector<NodeTransform> local;               // one per node
  std::vector<float> morph_weights;               // all meshes' targets, mesh after mesh
  std::vector<std::uint32_t> first_morph_weight;  // per mesh: its first entry in morph_weights
};

ModelPose rest_pose(const ModelAsset& asset);

// Local TRS → matrix (T * R * S).
glm::mat4 to_matrix(const NodeTransform& transform);

// World matrix of every node: root_world * parent chain * local. `world` has nodes.size() entries.
void compute_world_matrices(const ModelAsset& asset, const ModelPose& pose,
                            const glm::mat4& root_world, std::span<glm::mat4> world);

// glTF skinning: joint_matrices[j] = world[joints[j]] * inverse_bind[j]. A skinned mesh's own
// node transform is ignored (as the glTF spec says), so skinned vertices go straight to world.
void compute_joint_matrices(const ModelAsset& asset, int skin, std::span<const glm::mat4> world,
                            std::span<glm::mat4> joint_matrices);

// CPU reference of what the vertex shader does (tests, bounds, export): the world-space
// position and normal of vertex v (0-based) of `primitive` of mesh `mesh` drawn by node `node`.
struct SkinnedVertex {
  glm::vec3 position;
  glm::vec3 normal;
};
SkinnedVertex deform_vertex(const ModelAsset& asset, const ModelPose& pose,
                            std::span<const glm::mat4> world, int node, int primitive,
                            std::uint32_t vertex);

}  // namespace tutti::model
