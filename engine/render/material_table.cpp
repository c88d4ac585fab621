// SPDX-License-Identifier: MIT
#include <tutti/render/material_table.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <tuple>

#include <tutti/render/buffer_upload.hpp>
#include <tutti/render/vk_result.hpp>

namespace tutti::render {
namespace {

// std140 MaterialData in shaders/material.glsl.
struct MaterialUniforms {
  // Per slot two rows of its UV transform (KHR_texture_transform as a 2x3 matrix): xyz the row,
  // w of the first the UV set (0 or 1).
  std::array<glm::vec4, 2 * MaterialTable::kSlots> uv{};
  glm::vec4 params{0.0f};  // x normal scale (0: no normal map), y occlusion strength, z alpha
                           // cutoff, w alpha mode (0 opaque, 1 mask, 2 blend)
};
static_assert(sizeof(MaterialUniforms) == 176);

constexpr VkFormat kTextureFormat = VK_FORMAT_R8G8B8A8_UNORM;

// The image and its mip chain (2x2 box filter; an odd edge repeats its last texel), level after
// level in one array.
std::vector<std::uint8_t> mip_chain(const std::uint8_t* rgba, std::uint32_t width,
                                    std::uint32_t height,
                                    std::vector<std::pair<VkExtent2D, std::size_t>>& levels) {
  std::vector<std::uint8_t> out(rgba, rgba + std::size_t{4} * width * height);
  levels = {{{width, height}, 0}};
  std::uint32_t w = width, h = height;
  std::size_t at = 0;
  while (w > 1 || h > 1) {
    const std::uint32_t nw = std::max(1u, w / 2), nh = std::max(1u, h / 2);
    const std::size_t next = out.size();
    out.resize(next + std::size_t{4} * nw * nh);
    for (std::uint32_t y = 0; y < nh; ++y) {
      for (std::uint32_t x = 0; x < nw; ++x) {
        for (std::uint32_t c = 0; c < 4; ++c) {
          std::uint32_t sum = 0;
          for (std::uint32_t dy = 0; dy < 2; ++dy) {
            for (std::uint32_t dx = 0; dx < 2; ++dx) {
              const std::uint32_t sx = std::min(w - 1, 2 * x + dx), sy = std::min(h - 1, 2 * y + dy);
              sum += out[at + (std::size_t{sy} * w + sx) * 4 + c];
            }
          }
          out[next + (std::size_t{y} * nw + x) * 4 + c] = static_cast<std::uint8_t>((sum + 2) / 4);
        }
      }
    }
    levels.push_back({{nw, nh}, next});
    at = next;
    w = nw;
    h = nh;
  }
  return out;
}

VkFilter filter_of(int gl) { return gl == 9728 || gl == 9984 || gl == 9986 ? VK_FILTER_NEAREST : VK_FILTER_LINEAR; }

VkSamplerAddressMode wrap_of(int gl) {
  if (gl == 33071) return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  if (gl == 33648) return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
  return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}

// KHR_texture_transform: translation · rotation · scale, as two rows.
void uv_rows(const model::TextureRef& ref, glm::vec4& first, glm::vec4& second) {
  const float c = std::cos(ref.rotation), s = std::sin(ref.rotation);
  first = {c * ref.scale.x, s * ref.scale.y, ref.offset.x, static_cast<float>(ref.texcoord)};
  second = {-s * ref.scale.x, c * ref.scale.y, ref.offset.y, 0.0f};
}

}  // namespace

MaterialTable::~MaterialTable() = default;

Result<std::unique_ptr<MaterialTable>> MaterialTable::create(
    VulkanContext& context, std::span<const model::ModelAsset* const> models) {
  std::unique_ptr<MaterialTable> table(new MaterialTable());
  const VkDevice device = context.device();

  // Textures: the two neutral ones, then every model's images.
  const auto upload = [&](const std::uint8_t* rgba, std::uint32_t width,
                          std::uint32_t height) -> Status {
    std::vector<std::pair<VkExtent2D, std::size_t>> levels;
    const std::vector<std::uint8_t> chain = mip_chain(rgba, width, height, levels);
    const auto level_count = static_cast<std::uint32_t>(levels.size());
    VkImageCreateInfo info = vk_struct<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = kTextureFormat;
    info.extent = {width, height, 1};
    info.mipLevels = level_count;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImage image = VK_NULL_HANDLE;
    if (VkResult r = vkCreateImage(device, &info, nullptr, &image); r != VK_SUCCESS) {
      return vk_error("vkCreateImage", r);
    }
    Texture texture;
    texture.image = DeviceHandle<VkImage>(device, image, vkDestroyImage);
    VkMemoryRequirements needs;
    vkGetImageMemoryRequirements(device, image, &needs);
    Result<std::uint32_t> type = find_memory_type(context.physical_device(), needs.memoryTypeBits,
                                                  VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (!type) return type.error();
    VkMemoryAllocateInfo allocate = vk_struct<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
    allocate.allocationSize = needs.size;
    allocate.memoryTypeIndex = *type;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    if (VkResult r = vkAllocateMemory(device, &allocate, nullptr, &memory); r != VK_SUCCESS) {
      return vk_error("vkAllocateMemory", r);
    }
    texture.memory = DeviceHandle<VkDeviceMemory>(device, memory, vkFreeMemory);
    if (VkResult r = vkBindImageMemory(device, image, memory, 0); r != VK_SUCCESS) {
      return vk_error("vkBindImageMemory", r);
    }
    VkImageViewCreateInfo view_info = vk_struct<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
    view_info.image = image;
    view_info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view_info.format = kTextureFormat;
    view_info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, level_count, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    if (VkResult r = vkCreateImageView(device, &view_info, nullptr, &view); r != VK_SUCCESS) {
      return vk_error("vkCreateImageView", r);
    }
    texture.view = DeviceHandle<VkImageView>(device, view, vkDestroyImageView);

    Result<DeviceBuffer> staging = create_frame_buffer(context, chain.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    if (!staging) return staging.error();
    std::memcpy(staging->mapped, chain.data(), chain.size());
    if (Status s = flush_for_device_read(device, *staging); !s) return s;
    const Status uploaded = submit_once(context, [&](VkCommandBuffer commands) {
      const auto transition = [&](VkImageLayout from, VkImageLayout to, VkPipelineStageFlags2 src_stage,
                                  VkAccessFlags2 src_access, VkPipelineStageFlags2 dst_stage,
                                  VkAccessFlags2 dst_access) {
        VkImageMemoryBarrier2 barrier = vk_struct<VkImageMemoryBarrier2>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2);
        barrier.srcStageMask = src_stage;
        barrier.srcAccessMask = src_access;
        barrier.dstStageMask = dst_stage;
        barrier.dstAccessMask = dst_access;
        barrier.oldLayout = from;
        barrier.newLayout = to;
        barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.image = image;
        barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, level_count, 0, 1};
        VkDependencyInfo dependency = vk_struct<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
        dependency.imageMemoryBarrierCount = 1;
        dependency.pImageMemoryBarriers = &barrier;
        vkCmdPipelineBarrier2(commands, &dependency);
      };
      transition(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT,
                 VK_ACCESS_2_TRANSFER_WRITE_BIT);
      std::vector<VkBufferImageCopy> regions;
      for (std::uint32_t level = 0; level < level_count; ++level) {
        VkBufferImageCopy region{};
        region.bufferOffset = levels[level].second;
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
        region.imageExtent = {levels[level].first.width, levels[level].first.height, 1};
        regions.push_back(region);
      }
      vkCmdCopyBufferToImage(commands, staging->buffer.get(), image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                             level_count, regions.data());
      transition(VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                 VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                 VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    });
    if (!uploaded) return uploaded;
    table->textures_.push_back(std::move(texture));
    return Status::success();
  };
  const std::uint8_t white[4] = {255, 255, 255, 255};
  const std::uint8_t flat_normal[4] = {128, 128, 255, 255};
  if (Status s = upload(white, 1, 1); !s) return s.error();
  if (Status s = upload(flat_normal, 1, 1); !s) return s.error();
  std::vector<std::size_t> first_image;  // per model: its image 0's texture
  for (const model::ModelAsset* asset : models) {
    first_image.push_back(table->textures_.size());
    for (const model::Image& image : asset->images) {
      if (image.rgba.empty()) {
        if (Status s = upload(white, 1, 1); !s) return s.error();  // keeps the indices aligned
      } else if (Status s = upload(image.rgba.data(), image.width, image.height); !s) {
        return s.error();
      }
    }
  }

  // Samplers, one per distinct glTF sampler state.
  std::map<std::tuple<int, int, int, int>, std::size_t> sampler_index;
  const auto sampler_for = [&](const model::Texture* texture) -> Result<VkSampler> {
    const std::tuple<int, int, int, int> key =
        texture == nullptr ? std::tuple<int, int, int, int>{0, 0, 10497, 10497}
                           : std::tuple<int, int, int, int>{texture->mag_filter, texture->min_filter,
                                                            texture->wrap_s, texture->wrap_t};
    if (const auto found = sampler_index.find(key); found != sampler_index.end()) {
      return table->samplers_[found->second].get();
    }
    const auto [mag, min, wrap_s, wrap_t] = key;
    VkSamplerCreateInfo info = vk_struct<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
    info.magFilter = mag == 0 ? VK_FILTER_LINEAR : filter_of(mag);
    info.minFilter = min == 0 ? VK_FILTER_LINEAR : filter_of(min);
    info.mipmapMode = min == 9984 || min == 9985 ? VK_SAMPLER_MIPMAP_MODE_NEAREST
                                                 : VK_SAMPLER_MIPMAP_MODE_LINEAR;
    info.addressModeU = wrap_of(wrap_s);
    info.addressModeV = wrap_of(wrap_t);
    info.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    // NEAREST / LINEAR minification: the base level only.
    info.maxLod = min == 9728 || min == 9729 ? 0.0f : VK_LOD_CLAMP_NONE;
    VkSampler sampler = VK_NULL_HANDLE;
    if (VkResult r = vkCreateSampler(device, &info, nullptr, &sampler); r != VK_SUCCESS) {
      return vk_error("vkCreateSampler", r);
    }
    sampler_index[key] = table->samplers_.size();
    table->samplers_.emplace_back(device, sampler, vkDestroySampler);
    return sampler;
  };

  // The uniform blocks: the default material's, then every model's materials'.
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(context.physical_device(), &properties);
  const VkDeviceSize align = std::max<VkDeviceSize>(properties.limits.minUniformBufferOffsetAlignment, 16);
  const VkDeviceSize stride = (sizeof(MaterialUniforms) + align - 1) / align * align;
  std::size_t material_count = 1;
  for (const model::ModelAsset* asset : models) material_count += asset->materials.size();
  std::vector<std::byte> blocks(static_cast<std::size_t>(stride) * material_count);
  const auto block_of = [&](const model::Material* m) {
    MaterialUniforms u;
    if (m == nullptr) {
      for (std::uint32_t slot = 0; slot < kSlots; ++slot) {
        u.uv[2 * slot] = {1, 0, 0, 0};
        u.uv[2 * slot + 1] = {0, 1, 0, 0};
      }
      u.params = {0.0f, 1.0f, 0.5f, 0.0f};
      return u;
    }
    const model::TextureRef* refs[kSlots] = {&m->base_color_texture, &m->metallic_roughness_texture,
                                             &m->normal_texture, &m->occlusion_texture,
                                             &m->emissive_texture};
    for (std::uint32_t slot = 0; slot < kSlots; ++slot) uv_rows(*refs[slot], u.uv[2 * slot], u.uv[2 * slot + 1]);
    u.params = {m->normal_texture.present() ? m->normal_texture.amount : 0.0f,
                m->occlusion_texture.present() ? m->occlusion_texture.amount : 0.0f,
                m->alpha_cutoff,
                m->alpha_mode == model::AlphaMode::mask    ? 1.0f
                : m->alpha_mode == model::AlphaMode::blend ? 2.0f
                                                           : 0.0f};
    return u;
  };
  {
    std::size_t k = 0;
    const MaterialUniforms fallback = block_of(nullptr);
    std::memcpy(blocks.data(), &fallback, sizeof fallback);
    for (const model::ModelAsset* asset : models) {
      for (const model::Material& m : asset->materials) {
        const MaterialUniforms u = block_of(&m);
        std::memcpy(blocks.data() + static_cast<std::size_t>(stride) * ++k, &u, sizeof u);
      }
    }
  }
  Result<DeviceBuffer> uniforms = create_device_buffer_with_data(context, blocks, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  if (!uniforms) return uniforms.error();
  table->uniforms_ = std::move(*uniforms);

  // The set layout and one set per material.
  std::array<VkDescriptorSetLayoutBinding, kSlots + 1> bindings{};
  for (std::uint32_t b = 0; b < kSlots; ++b) {
    bindings[b] = {b, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
  }
  bindings[kSlots] = {kSlots, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
  VkDescriptorSetLayoutCreateInfo set_info = vk_struct<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
  set_info.bindingCount = static_cast<std::uint32_t>(bindings.size());
  set_info.pBindings = bindings.data();
  VkDescriptorSetLayout layout = VK_NULL_HANDLE;
  if (VkResult r = vkCreateDescriptorSetLayout(device, &set_info, nullptr, &layout); r != VK_SUCCESS) {
    return vk_error("vkCreateDescriptorSetLayout", r);
  }
  table->layout_ = DeviceHandle<VkDescriptorSetLayout>(device, layout, vkDestroyDescriptorSetLayout);
  const auto sets = static_cast<std::uint32_t>(material_count);
  const VkDescriptorPoolSize pool_sizes[] = {
      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kSlots * sets},
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, sets},
  };
  VkDescriptorPoolCreateInfo pool_info = vk_struct<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  pool_info.maxSets = sets;
  pool_info.poolSizeCount = 2;
  pool_info.pPoolSizes = pool_sizes;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  if (VkResult r = vkCreateDescriptorPool(device, &pool_info, nullptr, &pool); r != VK_SUCCESS) {
    return vk_error("vkCreateDescriptorPool", r);
  }
  table->pool_ = DeviceHandle<VkDescriptorPool>(device, pool, vkDestroyDescriptorPool);

  std::size_t block = 0;
  const auto make_set = [&](const model::ModelAsset* asset, std::size_t model_index,
                            const model::Material* m) -> Result<VkDescriptorSet> {
    VkDescriptorSetAllocateInfo allocate = vk_struct<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
    allocate.descriptorPool = pool;
    allocate.descriptorSetCount = 1;
    allocate.pSetLayouts = &layout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    if (VkResult r = vkAllocateDescriptorSets(device, &allocate, &set); r != VK_SUCCESS) {
      return vk_error("vkAllocateDescriptorSets", r);
    }
    const model::TextureRef* refs[kSlots] = {nullptr, nullptr, nullptr, nullptr, nullptr};
    if (m != nullptr) {
      refs[0] = &m->base_color_texture;
      refs[1] = &m->metallic_roughness_texture;
      refs[2] = &m->normal_texture;
      refs[3] = &m->occlusion_texture;
      refs[4] = &m->emissive_texture;
    }
    std::array<VkDescriptorImageInfo, kSlots> images{};
    for (std::uint32_t slot = 0; slot < kSlots; ++slot) {
      const model::Texture* texture = nullptr;
      std::size_t view = slot == 2 ? 1 : 0;  // neutral: white; the normal map's: flat
      if (refs[slot] != nullptr && refs[slot]->present() && asset != nullptr) {
        texture = &asset->textures[static_cast<std::size_t>(refs[slot]->texture)];
        view = first_image[model_index] + static_cast<std::size_t>(texture->image);
      }
      Result<VkSampler> sampler = sampler_for(texture);
      if (!sampler) return sampler.error();
      images[slot] = {*sampler, table->textures_[view].view.get(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    }
    const VkDescriptorBufferInfo buffer{table->uniforms_.buffer.get(), stride * block++, sizeof(MaterialUniforms)};
    std::array<VkWriteDescriptorSet, kSlots + 1> writes{};
    for (std::uint32_t b = 0; b <= kSlots; ++b) {
      writes[b] = vk_struct<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
      writes[b].dstSet = set;
      writes[b].dstBinding = b;
      writes[b].descriptorCount = 1;
      writes[b].descriptorType = b < kSlots ? VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER : VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
      if (b < kSlots) {
        writes[b].pImageInfo = &images[b];
      } else {
        writes[b].pBufferInfo = &buffer;
      }
    }
    vkUpdateDescriptorSets(device, static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);
    return set;
  };
  Result<VkDescriptorSet> fallback = make_set(nullptr, 0, nullptr);
  if (!fallback) return fallback.error();
  table->default_set_ = *fallback;
  for (std::size_t i = 0; i < models.size(); ++i) {
    table->sets_.emplace_back();
    for (const model::Material& m : models[i]->materials) {
      Result<VkDescriptorSet> set = make_set(models[i], i, &m);
      if (!set) return set.error();
      table->sets_.back().push_back(*set);
    }
  }
  return table;
}

VkDescriptorSet MaterialTable::set(std::size_t model, int material) const {
  if (model >= sets_.size() || material < 0 ||
      static_cast<std::size_t>(material) >= sets_[model].size()) {
    return default_set_;
  }
  return sets_[model][static_cast<std::size_t>(material)];
}

}  // namespace tutti::render
