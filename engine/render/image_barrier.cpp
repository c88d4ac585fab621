// SPDX-License-Identifier: MIT
#include <tutti/render/image_barrier.hpp>

#include <vector>

#include <tutti/render/vk_result.hpp>

namespace tutti::render {

VkImageMemoryBarrier2 image_barrier(VkImage image, VkImageAspectFlags aspect,
                                    VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                                    VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access,
                                    VkImageLayout old_layout, VkImageLayout new_layout) {
  VkImageMemoryBarrier2 barrier =
      vk_struct<VkImageMemoryBarrier2>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2);
  barrier.srcStageMask = src_stage;
  barrier.srcAccessMask = src_access;
  barrier.dstStageMask = dst_stage;
  barrier.dstAccessMask = dst_access;
  barrier.oldLayout = old_layout;
  barrier.newLayout = new_layout;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {aspect, 0, 1, 0, 1};
  return barrier;
}

void record_image_barriers(VkCommandBuffer commands,
                           std::initializer_list<VkImageMemoryBarrier2> barriers) {
  VkDependencyInfo dependency = vk_struct<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
  dependency.imageMemoryBarrierCount = static_cast<std::uint32_t>(barriers.size());
  dependency.pImageMemoryBarriers = barriers.begin();
  vkCmdPipelineBarrier2(commands, &dependency);
}

}  // namespace tutti::render
