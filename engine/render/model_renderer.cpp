// SPDX-License-Identifier: MIT
#include <tutti/render/model_renderer.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include <tutti/render/buffer_upload.hpp>
#include <tutti/render/pipeline_builder.hpp>
#include <tutti/render/shaders.hpp>
#include <tutti/render/vk_result.hpp>

namespace tutti::render {
namespace {

// std140 layout of FrameUniforms in shaders/frame_data.glsl.
struct FrameUniforms {
  glm::mat4 view_projection;
  glm::mat4 light_view_projection;
  glm::vec4 camera_position;
  glm::vec4 key_direction;  // w: depth bias in shadow clip units
  glm::vec4 key_color;      // w: shadow texel size in metres
  glm::vec4 fill_direction;
  glm::vec4 fill_color;
  glm::vec4 sky_color;  // w: exposure
  glm::vec4 ground_color;
};

using detail::DrawConstants;
static_assert(sizeof(DrawConstants) == 80);

constexpr VkShaderStageFlags kDrawStages =
    VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
constexpr std::size_t kInitialMatrices = 1024;
constexpr std::size_t kInitialWeights = 256;

std::vector<VkVertexInputAttributeDescription> vertex_attributes() {
  return {
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT,
       static_cast<std::uint32_t>(offsetof(model::Vertex, position))},
      {1, 0, VK_FORMAT_R32G32B32_SFLOAT,
       static_cast<std::uint32_t>(offsetof(model::Vertex, normal))},
      {2, 0, VK_FORMAT_R32G32B32A32_UINT,
       static_cast<std::uint32_t>(offsetof(model::Vertex, joints))},
      {3, 0, VK_FORMAT_R32G32B32A32_SFLOAT,
       static_cast<std::uint32_t>(offsetof(model::Vertex, weights))},
      {4, 0, VK_FORMAT_R32G32_SFLOAT, static_cast<std::uint32_t>(offsetof(model::Vertex, uv0))},
      {5, 0, VK_FORMAT_R32G32_SFLOAT, static_cast<std::uint32_t>(offsetof(model::Vertex, uv1))},
  };
}

// The lit pipeline a material is drawn with (DrawCandidate::pipeline).
std::uint32_t pipeline_kind(const model::Material& m) {
  const std::uint32_t alpha = m.alpha_mode == model::AlphaMode::mask    ? 1u
                              : m.alpha_mode == model::AlphaMode::blend ? 2u
                                                                        : 0u;
  const bool textured = m.base_color_texture.present() || m.metallic_roughness_texture.present() ||
                        m.normal_texture.present() || m.occlusion_texture.present() ||
                        m.emissive_texture.present();
  return alpha * 2 + (textured ? 1u : 0u);
}

// Closer than this, a primitive is judged as if this close (its sphere may hold the eye).
constexpr float kNearestLodDistance = 0.05f;

// How far the nearest point of the candidate's sphere can be from the eye.
float nearest_distance(const detail::DrawCandidate& candidate, const glm::vec3& eye) {
  return std::max(glm::length(candidate.bound.center - eye) - candidate.bound.radius,
                  kNearestLodDistance);
}

// Planes (xyz normal, w offset; inside when dot >= 0) of clip space x, y in [-w, w], z in [0, w].
using FrustumPlanes = std::array<glm::vec4, 6>;
FrustumPlanes frustum_planes(const glm::mat4& m) {
  const glm::mat4 t = glm::transpose(m);  // rows of m
  FrustumPlanes planes = {t[3] + t[0], t[3] - t[0], t[3] + t[1], t[3] - t[1], t[2], t[3] - t[2]};
  for (glm::vec4& plane : planes) plane /= glm::length(glm::vec3(plane));
  return planes;
}

bool sphere_in_frustum(const FrustumPlanes& planes, const glm::vec3& center, float radius) {
  for (const glm::vec4& plane : planes) {
    if (glm::dot(glm::vec3(plane), center) + plane.w < -radius) return false;
  }
  return true;
}

}  // namespace

Camera look_at_camera(const glm::vec3& position, const glm::vec3& target, float fov_y_deg,
                      float aspect, float near_m, float far_m) {
  Camera camera;
  camera.position = position;
  camera.view = glm::lookAt(position, target, glm::vec3(0.0f, 1.0f, 0.0f));
  camera.projection = glm::perspective(glm::radians(fov_y_deg), aspect, near_m, far_m);
  camera.projection[1][1] *= -1.0f;  // Vulkan's clip space has y down
  return camera;
}

Result<std::unique_ptr<ModelRenderer>> ModelRenderer::create(
    VulkanContext& context, const FrameTarget& target,
    std::span<const model::ModelAsset* const> models, const ModelRendererOptions& options) {
  std::unique_ptr<ModelRenderer> renderer(new ModelRenderer(context));
  const VkDevice device = context.device();
  renderer->models_.assign(models.begin(), models.end());
  renderer->lod_pixel_error_ = options.lod_pixel_error;
  if (options.shadow_taps != 1 && options.shadow_taps != 4) {
    return Error{"model renderer: shadow_taps must be 1 or 4, not " +
                 std::to_string(options.shadow_taps)};
  }
  renderer->shadow_taps_ = options.shadow_taps;

  Result<std::unique_ptr<GeometryArena>> geometry = GeometryArena::create(context, models);
  if (!geometry) return geometry.error();
  renderer->geometry_ = std::move(*geometry);
  Result<std::unique_ptr<ShadowMap>> shadow = ShadowMap::create(context, options.shadow_map_size);
  if (!shadow) return shadow.error();
  renderer->shadow_map_ = std::move(*shadow);
  Result<std::unique_ptr<MaterialTable>> materials = MaterialTable::create(context, models);
  if (!materials) return materials.error();
  renderer->materials_ = std::move(*materials);

  const VkDescriptorSetLayoutBinding bindings[] = {
      {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, kDrawStages, nullptr},
      {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
      {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
      {3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
      {4, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
  };
  VkDescriptorSetLayoutCreateInfo set_info = vk_struct<VkDescriptorSetLayoutCreateInfo>(
      VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
  set_info.bindingCount = 5;
  set_info.pBindings = bindings;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  if (VkResult r = vkCreateDescriptorSetLayout(device, &set_info, nullptr, &set_layout);
      r != VK_SUCCESS) {
    return vk_error("vkCreateDescriptorSetLayout", r);
  }
  renderer->set_layout_ =
      DeviceHandle<VkDescriptorSetLayout>(device, set_layout, vkDestroyDescriptorSetLayout);

  const std::uint32_t slot_count = std::max<std::uint32_t>(1, target.frames_in_flight());
  const VkDescriptorPoolSize pool_sizes[] = {
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, slot_count},
      {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 3 * slot_count},
      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, slot_count},
  };
  VkDescriptorPoolCreateInfo pool_info =
      vk_struct<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  pool_info.maxSets = slot_count;
  pool_info.poolSizeCount = 3;
  pool_info.pPoolSizes = pool_sizes;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  if (VkResult r = vkCreateDescriptorPool(device, &pool_info, nullptr, &pool); r != VK_SUCCESS) {
    return vk_error("vkCreateDescriptorPool", r);
  }
  renderer->pool_ = DeviceHandle<VkDescriptorPool>(device, pool, vkDestroyDescriptorPool);

  const VkPushConstantRange push{kDrawStages, 0, sizeof(DrawConstants)};
  VkPipelineLayoutCreateInfo layout_info =
      vk_struct<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
  const VkDescriptorSetLayout set_layouts[] = {set_layout, renderer->materials_->layout()};
  layout_info.setLayoutCount = 2;
  layout_info.pSetLayouts = set_layouts;
  layout_info.pushConstantRangeCount = 1;
  layout_info.pPushConstantRanges = &push;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  if (VkResult r = vkCreatePipelineLayout(device, &layout_info, nullptr, &layout);
      r != VK_SUCCESS) {
    return vk_error("vkCreatePipelineLayout", r);
  }
  renderer->layout_ = DeviceHandle<VkPipelineLayout>(device, layout, vkDestroyPipelineLayout);

  for (const model::ModelAsset* asset : models) {
    for (const model::Material& m : asset->materials) renderer->lit_needed_[pipeline_kind(m)] = true;
  }
  renderer->color_format_ = target.color_format();
  renderer->depth_format_ = target.depth_format();
  renderer->samples_ = target.samples();
  if (Status s = renderer->build_pipelines(shaders::lit_vert(), shaders::lit_frag(),
                                           shaders::shadow_vert());
      !s) {
    return s.error();
  }

  renderer->slots_.resize(slot_count);
  for (FrameSlot& slot : renderer->slots_) {
    Result<DeviceBuffer> uniforms =
        create_frame_buffer(context, sizeof(FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    if (!uniforms) return uniforms.error();
    slot.uniforms = std::move(*uniforms);
    VkDescriptorSetAllocateInfo allocate =
        vk_struct<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
    allocate.descriptorPool = pool;
    allocate.descriptorSetCount = 1;
    allocate.pSetLayouts = &set_layout;
    if (VkResult r = vkAllocateDescriptorSets(device, &allocate, &slot.descriptors);
        r != VK_SUCCESS) {
      return vk_error("vkAllocateDescriptorSets", r);
    }
    if (Status s = renderer->ensure_capacity(slot, kInitialMatrices, kInitialWeights); !s) {
      return s.error();
    }
  }
  return renderer;
}

// Frames still in flight use the pipelines, buffers and descriptor sets (a render that stops on
// an error returns with its last frame submitted): they finish before anything is destroyed.
ModelRenderer::~ModelRenderer() { (void)context_.wait_idle(); }

Status ModelRenderer::build_pipelines(std::span<const std::uint32_t> lit_vert,
                                      std::span<const std::uint32_t> lit_frag,
                                      std::span<const std::uint32_t> shadow_vert) {
  const VkDevice device = context_.device();
  PipelineDescription lit;
  lit.vertex_spirv = lit_vert;
  lit.fragment_spirv = lit_frag;
  lit.bindings = {{0, sizeof(model::Vertex), VK_VERTEX_INPUT_RATE_VERTEX}};
  lit.attributes = vertex_attributes();
  lit.color_format = color_format_;
  lit.depth_format = depth_format_;
  lit.samples = samples_;
  lit.layout = layout_.get();
  std::array<DeviceHandle<VkPipeline>, 6> lit_pipelines;
  for (std::uint32_t kind = 0; kind < lit_pipelines.size(); ++kind) {
    if (!lit_needed_[kind]) continue;
    PipelineDescription variant = lit;
    variant.fragment_constants = {shadow_taps_, kind / 2, kind % 2};
    variant.alpha_blend = kind / 2 == 2;
    Result<DeviceHandle<VkPipeline>> pipeline = create_graphics_pipeline(device, variant);
    if (!pipeline) return pipeline.error();
    lit_pipelines[kind] = std::move(*pipeline);
  }

  PipelineDescription shadow_pass = lit;
  shadow_pass.vertex_spirv = shadow_vert;
  shadow_pass.attributes.resize(4);  // shadow.vert reads no UVs
  shadow_pass.fragment_spirv = {};
  shadow_pass.fragment_constants = {};
  shadow_pass.color_format = VK_FORMAT_UNDEFINED;
  shadow_pass.depth_format = ShadowMap::kFormat;
  shadow_pass.samples = VK_SAMPLE_COUNT_1_BIT;
  shadow_pass.depth_bias = true;
  Result<DeviceHandle<VkPipeline>> shadow_pipeline = create_graphics_pipeline(device, shadow_pass);
  if (!shadow_pipeline) return shadow_pipeline.error();
  lit_pipelines_ = std::move(lit_pipelines);
  shadow_pipeline_ = std::move(*shadow_pipeline);
  return Status::success();
}

Status ModelRenderer::set_shaders(std::span<const std::uint32_t> lit_vert,
                                  std::span<const std::uint32_t> lit_frag,
                                  std::span<const std::uint32_t> shadow_vert) {
  if (Status s = context_.wait_idle(); !s) return s;
  return build_pipelines(lit_vert, lit_frag, shadow_vert);
}

Status ModelRenderer::ensure_capacity(FrameSlot& slot, std::size_t matrices, std::size_t weights) {
  bool changed = false;
  if (slot.matrices.size_bytes < matrices * sizeof(glm::mat4)) {
    // This slot's previous frame has finished (FrameTarget::frames_in_flight), so its buffer
    // can go.
    Result<DeviceBuffer> buffer =
        create_frame_buffer(context_, std::max(matrices, kInitialMatrices) * 2 * sizeof(glm::mat4),
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    if (!buffer) return buffer.error();
    slot.matrices = std::move(*buffer);
    changed = true;
  }
  if (slot.weights.size_bytes < weights * sizeof(float)) {
    Result<DeviceBuffer> buffer =
        create_frame_buffer(context_, std::max(weights, kInitialWeights) * 2 * sizeof(float),
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    if (!buffer) return buffer.error();
    slot.weights = std::move(*buffer);
    changed = true;
  }
  if (changed) write_descriptors(slot);
  return Status::success();
}

void ModelRenderer::write_descriptors(FrameSlot& slot) {
  const VkDescriptorBufferInfo uniforms{slot.uniforms.buffer.get(), 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo matrices{slot.matrices.buffer.get(), 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo weights{slot.weights.buffer.get(), 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo deltas{geometry_->morph_deltas(), 0, VK_WHOLE_SIZE};
  const VkDescriptorImageInfo shadow{shadow_map_->sampler(), shadow_map_->view(),
                                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  VkWriteDescriptorSet writes[5];
  for (std::uint32_t i = 0; i < 5; ++i) {
    writes[i] = vk_struct<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    writes[i].dstSet = slot.descriptors;
    writes[i].dstBinding = i;
    writes[i].descriptorCount = 1;
    writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  }
  writes[0].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  writes[0].pBufferInfo = &uniforms;
  writes[1].pBufferInfo = &matrices;
  writes[2].pBufferInfo = &weights;
  writes[3].pBufferInfo = &deltas;
  writes[4].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  writes[4].pImageInfo = &shadow;
  vkUpdateDescriptorSets(context_.device(), 5, writes, 0, nullptr);
}

Status ModelRenderer::record(const RecordingFrame& frame, FrameTarget& target,
                             std::span<const ModelInstance> instances, const Camera& camera,
                             const Lighting& lighting, const ClearColor& clear) {
  if (frame.id == 0) return Error{"model renderer: frame has no id (not begun)"};
  matrices_.clear();
  weights_.clear();
  candidates_.clear();
  for (const ModelInstance& instance : instances) {
    if (instance.model >= models_.size()) {
      return Error{"model renderer: instance of model " + std::to_string(instance.model) +
                   ", but only " + std::to_string(models_.size()) + " models were loaded"};
    }
    const model::ModelAsset& asset = *models_[instance.model];
    const GeometryArena::ModelRange& range = geometry_->range(instance.model);
    model::ModelPose rest;
    const model::ModelPose* pose = instance.pose;
    if (pose == nullptr) {
      rest = model::rest_pose(asset);
      pose = &rest;
    }
    if (pose->local.size() != asset.nodes.size() ||
        pose->morph_weights.size() != asset.morph_weight_count() ||
        pose->first_morph_weight.size() != asset.meshes.size()) {
      return Error{"model renderer: the pose given for " + asset.source + " does not fit it (" +
                   std::to_string(pose->local.size()) + " nodes, model has " +
                   std::to_string(asset.nodes.size()) + ")"};
    }
    world_.resize(asset.nodes.size());
    model::compute_world_matrices(asset, *pose, instance.root, world_);
    const auto weight_base = static_cast<std::uint32_t>(weights_.size());
    weights_.insert(weights_.end(), pose->morph_weights.begin(), pose->morph_weights.end());
    const auto node_base = static_cast<std::uint32_t>(matrices_.size());
    matrices_.insert(matrices_.end(), world_.begin(), world_.end());

    const MeshLods& lods = geometry_->lods(instance.model);
    for (std::size_t n = 0; n < asset.nodes.size(); ++n) {
      const model::Node& node = asset.nodes[n];
      if (node.mesh < 0) continue;
      const auto mesh_index = static_cast<std::size_t>(node.mesh);
      const model::Mesh& mesh = asset.meshes[mesh_index];
      std::uint32_t matrix_index = node_base + static_cast<std::uint32_t>(n);
      const model::Skin* skin = nullptr;
      if (node.skin >= 0) {
        skin = &asset.skins[static_cast<std::size_t>(node.skin)];
        matrix_index = static_cast<std::uint32_t>(matrices_.size());
        matrices_.resize(matrices_.size() + skin->joints.size());
        model::compute_joint_matrices(
            asset, node.skin, world_,
            std::span<glm::mat4>(matrices_).subspan(matrix_index, skin->joints.size()));
      }
      for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const model::Primitive& primitive = mesh.primitives[p];
        const PrimitiveLods& primitive_lods = lods.primitives[lods.first_primitive[mesh_index] + p];
        if (primitive_lods.level_count == 0) continue;
        detail::DrawCandidate draw;
        DrawConstants& c = draw.constants;
        c.matrix_index = matrix_index;
        c.skinned = skin != nullptr ? 1 : 0;
        c.morph_count = static_cast<std::uint32_t>(mesh.target_names.size());
        c.morph_delta_base = 2 * (range.first_morph_delta + primitive.first_morph_delta);
        c.morph_weight_base = weight_base + pose->first_morph_weight[mesh_index];
        c.vertex_base = range.first_vertex + primitive.first_vertex;
        c.vertex_count = primitive.vertex_count;
        if (primitive.material >= 0) {
          const model::Material& m = asset.materials[static_cast<std::size_t>(primitive.material)];
          c.base_color = m.base_color;
          c.material = {m.metallic, m.roughness, 0.0f, 0.0f};
          c.emissive = glm::vec4(m.emissive, 0.0f);
          c.flags = m.double_sided ? 1u : 0u;
          draw.pipeline = pipeline_kind(m);
        }
        draw.material = materials_->set(instance.model, primitive.material);
        draw.lods = &primitive_lods;
        draw.casts_shadows = instance.casts_shadows;
        draw.first_index = range.first_index;
        draw.vertex_offset = static_cast<std::int32_t>(c.vertex_base);
        draw.bound =
            skin != nullptr
                ? skinned_world_bound(primitive_lods, *skin, world_,
                                      std::span<const glm::mat4>(matrices_).subspan(matrix_index))
                : rigid_world_bound(primitive_lods, world_[n]);
        candidates_.push_back(draw);
      }
    }
  }

  FrameSlot& slot = slots_[(frame.id - 1) % slots_.size()];
  if (Status s = ensure_capacity(slot, matrices_.size(), weights_.size()); !s) return s;
  std::memcpy(slot.matrices.mapped, matrices_.data(), matrices_.size() * sizeof(glm::mat4));
  if (!weights_.empty()) {
    std::memcpy(slot.weights.mapped, weights_.data(), weights_.size() * sizeof(float));
  }
  FrameUniforms uniforms{};
  uniforms.view_projection = camera.projection * camera.view;
  const glm::vec3 key_direction = glm::normalize(lighting.key.direction);
  uniforms.light_view_projection =
      fit_directional_shadow(key_direction, lighting.shadow_center, lighting.shadow_radius);
  uniforms.camera_position = glm::vec4(camera.position, 1.0f);
  uniforms.key_direction = glm::vec4(key_direction, 0.0004f);
  uniforms.key_color =
      glm::vec4(lighting.key.color * lighting.key.intensity,
                2.0f * lighting.shadow_radius / static_cast<float>(shadow_map_->size()));
  uniforms.fill_direction = glm::vec4(glm::normalize(lighting.fill.direction), 0.0f);
  uniforms.fill_color = glm::vec4(lighting.fill.color * lighting.fill.intensity, 0.0f);
  uniforms.sky_color = glm::vec4(lighting.sky, lighting.exposure);
  uniforms.ground_color = glm::vec4(lighting.ground, 0.0f);
  std::memcpy(slot.uniforms.mapped, &uniforms, sizeof uniforms);
  for (const DeviceBuffer* buffer : {&slot.matrices, &slot.weights, &slot.uniforms}) {
    if (Status s = flush_for_device_read(context_.device(), *buffer); !s) return s;
  }

  const VkCommandBuffer commands = frame.commands;
  const VkBuffer vertex_buffer = geometry_->vertices();
  const VkDeviceSize zero = 0;
  vkCmdBindVertexBuffers(commands, 0, 1, &vertex_buffer, &zero);
  vkCmdBindIndexBuffer(commands, geometry_->indices(), 0, VK_INDEX_TYPE_UINT32);
  vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.get(), 0, 1,
                          &slot.descriptors, 0, nullptr);

  const glm::mat4 view_projection = camera.projection * camera.view;
  const VkExtent2D extent = target.extent();
  select_draws(Pass::main, view_projection,
               std::abs(camera.projection[1][1]) * 0.5f * static_cast<float>(extent.height),
               camera.projection[2][3] != 0.0f, camera.position, main_draws_);
  // One shadow texel is 2 r / size metres wide, everywhere (orthographic).
  select_draws(Pass::shadow, uniforms.light_view_projection,
               static_cast<float>(shadow_map_->size()) / (2.0f * lighting.shadow_radius), false,
               glm::vec3(0.0f), shadow_draws_);
  stats_ = {};
  stats_.candidates = static_cast<std::uint32_t>(candidates_.size());
  stats_.main_draws = static_cast<std::uint32_t>(main_draws_.size());
  stats_.shadow_draws = static_cast<std::uint32_t>(shadow_draws_.size());
  for (const detail::Draw& d : main_draws_) stats_.main_triangles += d.index_count / 3;
  for (const detail::Draw& d : shadow_draws_) stats_.shadow_triangles += d.index_count / 3;

  // Blended primitives after everything else, the farthest first.
  blended_draws_.clear();
  const auto opaque_end = std::stable_partition(
      main_draws_.begin(), main_draws_.end(),
      [&](const detail::Draw& d) { return !candidates_[d.candidate].blended(); });
  blended_draws_.assign(opaque_end, main_draws_.end());
  main_draws_.erase(opaque_end, main_draws_.end());
  std::stable_sort(blended_draws_.begin(), blended_draws_.end(),
                   [&](const detail::Draw& a, const detail::Draw& b) {
                     return glm::distance(candidates_[a.candidate].bound.center, camera.position) >
                            glm::distance(candidates_[b.candidate].bound.center, camera.position);
                   });

  shadow_map_->begin(commands);
  record_draws(commands, shadow_draws_, true);
  shadow_map_->end(commands);

  target.begin_main_pass(clear);
  record_draws(commands, main_draws_, false);
  record_draws(commands, blended_draws_, false);
  target.end_main_pass();
  return Status::success();
}

void ModelRenderer::select_draws(Pass pass, const glm::mat4& view_projection,
                                 float pixels_per_metre, bool perspective, const glm::vec3& eye,
                                 std::vector<detail::Draw>& draws) const {
  const FrustumPlanes planes = frustum_planes(view_projection);
  const float error_budget = lod_pixel_error_;
  draws.clear();
  for (std::size_t i = 0; i < candidates_.size(); ++i) {
    const detail::DrawCandidate& candidate = candidates_[i];
    if (pass == Pass::shadow && !candidate.casts_shadows) continue;
    if (!sphere_in_frustum(planes, candidate.bound.center, candidate.bound.radius)) continue;
    float pixels = pixels_per_metre;
    if (perspective) pixels /= nearest_distance(candidate, eye);
    const PrimitiveLods& lods = *candidate.lods;
    std::uint32_t level = 0;
    if (error_budget > 0.0f) {
      while (level + 1 < lods.level_count &&
             lods.levels[level + 1].error * candidate.bound.scale * pixels <= error_budget) {
        ++level;
      }
    }
    const LodLevel& chosen = lods.levels[level];
    draws.push_back({static_cast<std::uint32_t>(i), chosen.index_count,
                     candidate.first_index + chosen.first_index});
  }
}

void ModelRenderer::record_draws(VkCommandBuffer commands, const std::vector<detail::Draw>& draws,
                                 bool shadow_pass) const {
  if (shadow_pass) vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, shadow_pipeline_.get());
  VkDescriptorSet bound = VK_NULL_HANDLE;
  std::uint32_t pipeline = 6;  // none yet
  for (const detail::Draw& draw : draws) {
    const detail::DrawCandidate& candidate = candidates_[draw.candidate];
    if (!shadow_pass && candidate.pipeline != pipeline) {
      pipeline = candidate.pipeline;
      vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, lit_pipelines_[pipeline].get());
    }
    if (!shadow_pass && candidate.material != bound) {
      bound = candidate.material;
      vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.get(), 1, 1,
                              &bound, 0, nullptr);
    }
    vkCmdPushConstants(commands, layout_.get(), kDrawStages, 0, sizeof(DrawConstants),
                       &candidate.constants);
    vkCmdDrawIndexed(commands, draw.index_count, 1, draw.first_index, candidate.vertex_offset, 0);
  }
}

}  // namespace tutti::render
