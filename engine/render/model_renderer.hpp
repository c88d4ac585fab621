// SPDX-License-Identifier: MIT
#pragma once
// ModelRenderer: draws posed glTF models (model::ModelAsset + model::ModelPose) into a
// FrameTarget with a shadowed key light, a fill light and hemisphere ambient, metallic-roughness
// materials with their textures (material_table.hpp; alpha mask and blend), GPU skinning and
// morph targets. Per frame it computes every node's world matrix and
// every joint matrix on the CPU, writes them (and the morph weights) into this frame's host-visible
// buffers, culls every primitive against the light's and the camera's frusta, picks each one's
// level of detail (mesh_lod.hpp), records the shadow pass, then the main pass.
//
//   auto renderer = ModelRenderer::create(ctx, target, models);   // uploads the geometry once
//   auto frame = target.begin_frame();
//   renderer->record(*frame, target, instances, camera, lighting, clear);
//   target.end_frame();
//
// Deterministic: the same instances, camera and lighting give the same pixels. The models and
// the target's formats and sample count are fixed at create(); the poses may change every frame.

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <span>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/model/model_asset.hpp>
#include <tutti/render/device_memory.hpp>
#include <tutti/render/frame_target.hpp>
#include <tutti/render/geometry_arena.hpp>
#include <tutti/render/material_table.hpp>
#include <tutti/render/mesh_lod.hpp>
#include <tutti/render/shadow_map.hpp>
#include <tutti/render/vulkan_context.hpp>

namespace tutti::render {

struct DirectionalLight {
  glm::vec3 direction{-0.4f, -1.0f, -0.5f};  // the way the light travels (normalised on use)
  glm::vec3 color{1.0f};                     // linear RGB
  float intensity = 3.0f;
};

struct Lighting {
  DirectionalLight key;  // casts the shadows
  DirectionalLight fill{{0.6f, -0.3f, -0.4f}, {0.8f, 0.85f, 1.0f}, 0.6f};
  glm::vec3 sky{0.35f, 0.38f, 0.45f};     // hemisphere ambient from above
  glm::vec3 ground{0.15f, 0.12f, 0.10f};  // and from below
  float exposure = 1.0f;
  // The sphere that casts and receives shadows (metres): fit it to the stage.
  glm::vec3 shadow_center{0.0f, 1.0f, 0.0f};
  float shadow_radius = 5.0f;
};

struct Camera {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};  // Vulkan clip space (y down, depth 0..1): see perspective_camera
  glm::vec3 position{0.0f};
};

// A look-at camera with a vertical field of view, y flipped for Vulkan's clip space.
Camera look_at_camera(const glm::vec3& position, const glm::vec3& target, float fov_y_deg,
                      float aspect, float near_m = 0.05f, float far_m = 100.0f);

struct ModelInstance {
  std::uint32_t model = 0;                 // index into the models given to create()
  const model::ModelPose* pose = nullptr;  // nullptr = the rest pose
  glm::mat4 root{1.0f};                    // model space → world
  bool casts_shadows = true;               // false: drawn in the main pass only
};

namespace detail {
// DrawConstants in shaders/frame_data.glsl (push constants, 80 bytes).
struct DrawConstants {
  std::uint32_t matrix_index = 0;
  std::uint32_t skinned = 0;
  std::uint32_t morph_count = 0;
  std::uint32_t morph_delta_base = 0;
  std::uint32_t morph_weight_base = 0;
  std::uint32_t vertex_base = 0;
  std::uint32_t vertex_count = 0;
  std::uint32_t flags = 0;
  glm::vec4 base_color{0.8f, 0.8f, 0.8f, 1.0f};
  glm::vec4 material{0.0f, 0.6f, 0.0f, 0.0f};
  glm::vec4 emissive{0.0f};
};
// One primitive of one instance this frame, before culling and the choice of detail level.
struct DrawCandidate {
  DrawConstants constants;
  const PrimitiveLods* lods = nullptr;
  std::uint32_t first_index = 0;  // the model's first index in the arena
  std::int32_t vertex_offset = 0;
  BoundingSphere bound;  // world space
  bool casts_shadows = true;
  VkDescriptorSet material = VK_NULL_HANDLE;  // MaterialTable::set
  // The lit pipeline: alpha mode (0 opaque, 1 mask, 2 blend) × 2 + textured.
  std::uint32_t pipeline = 0;
  bool blended() const { return pipeline >= 4; }
};
struct Draw {
  std::uint32_t candidate = 0;
  std::uint32_t index_count = 0;
  std::uint32_t first_index = 0;
};
}  // namespace detail

struct ModelRendererOptions {
  std::uint32_t shadow_map_size = 2048;
  // Shadow-map comparisons per shaded pixel: 1 (hard edges) or 4 (soft edges; on lavapipe
  // about a third of the main pass at 720p).
  std::uint32_t shadow_taps = 1;
  // Detail levels (mesh_lod.hpp): the coarsest level whose surface error stays under this many
  // output pixels (main pass) or shadow-map texels (shadow pass). 0 = always the full mesh.
  float lod_pixel_error = 1.0f;
};

// What the last record() drew (after culling and level choice), for benchmarks and tests.
struct RenderStats {
  std::uint32_t candidates = 0;  // primitives of all instances
  std::uint32_t main_draws = 0;
  std::uint32_t shadow_draws = 0;
  std::uint64_t main_triangles = 0;
  std::uint64_t shadow_triangles = 0;
};

class ModelRenderer {
 public:
  // `models` must outlive the renderer (their node lists are read every frame).
  static Result<std::unique_ptr<ModelRenderer>> create(
      VulkanContext& context, const FrameTarget& target,
      std::span<const model::ModelAsset* const> models, const ModelRendererOptions& options = {});
  ~ModelRenderer();
  ModelRenderer(const ModelRenderer&) = delete;
  ModelRenderer& operator=(const ModelRenderer&) = delete;

  // Hot reload: rebuilds both pipelines from SPIR-V compiled at run time (tutti::shader_compiler's
  // reload_lit_shaders) with the same interface as shaders/lit.vert, lit.frag and shadow.vert.
  // Waits for the device first. On error the previous pipelines stay in use.
  Status set_shaders(std::span<const std::uint32_t> lit_vert,
                     std::span<const std::uint32_t> lit_frag,
                     std::span<const std::uint32_t> shadow_vert);

  // Records the shadow pass and the main pass (begin_main_pass .. end_main_pass) of `frame`.
  // An error for an instance naming an unknown model or a pose of the wrong size.
  Status record(const RecordingFrame& frame, FrameTarget& target,
                std::span<const ModelInstance> instances, const Camera& camera,
                const Lighting& lighting, const ClearColor& clear);

  const RenderStats& last_stats() const { return stats_; }

 private:
  struct FrameSlot {
    DeviceBuffer uniforms;
    DeviceBuffer matrices;
    DeviceBuffer weights;
    VkDescriptorSet descriptors = VK_NULL_HANDLE;
  };

  explicit ModelRenderer(VulkanContext& context) : context_(context) {}
  Status build_pipelines(std::span<const std::uint32_t> lit_vert,
                         std::span<const std::uint32_t> lit_frag,
                         std::span<const std::uint32_t> shadow_vert);
  Status ensure_capacity(FrameSlot& slot, std::size_t matrices, std::size_t weights);
  void write_descriptors(FrameSlot& slot);
  enum class Pass { shadow, main };
  // pixels_per_metre: at 1 m from `eye` when `perspective`, else everywhere.
  void select_draws(Pass pass, const glm::mat4& view_projection, float pixels_per_metre,
                    bool perspective, const glm::vec3& eye, std::vector<detail::Draw>& draws) const;
  // The shadow pipeline when `shadow_pass`, else each draw's lit pipeline and material.
  void record_draws(VkCommandBuffer commands, const std::vector<detail::Draw>& draws,
                    bool shadow_pass) const;

  VulkanContext& context_;
  std::vector<const model::ModelAsset*> models_;
  std::unique_ptr<GeometryArena> geometry_;
  std::unique_ptr<ShadowMap> shadow_map_;
  std::unique_ptr<MaterialTable> materials_;
  DeviceHandle<VkDescriptorSetLayout> set_layout_;
  DeviceHandle<VkDescriptorPool> pool_;
  DeviceHandle<VkPipelineLayout> layout_;
  // Lit pipelines by DrawCandidate::pipeline; only the kinds the models use are built.
  std::array<DeviceHandle<VkPipeline>, 6> lit_pipelines_;
  std::array<bool, 6> lit_needed_{true, false, false, false, false, false};
  DeviceHandle<VkPipeline> shadow_pipeline_;
  VkFormat color_format_ = VK_FORMAT_UNDEFINED;
  VkFormat depth_format_ = VK_FORMAT_UNDEFINED;
  VkSampleCountFlagBits samples_ = VK_SAMPLE_COUNT_1_BIT;
  std::vector<FrameSlot> slots_;
  // Scratch reused every frame (grows, never shrinks): no allocation in steady state.
  std::vector<glm::mat4> matrices_;
  std::vector<float> weights_;
  std::vector<glm::mat4> world_;
  std::vector<detail::DrawCandidate> candidates_;
  std::vector<detail::Draw> main_draws_;
  std::vector<detail::Draw> blended_draws_;
  std::vector<detail::Draw> shadow_draws_;
  float lod_pixel_error_ = 1.0f;
  std::uint32_t shadow_taps_ = 1;
  RenderStats stats_;
};

}  // namespace tutti::render
