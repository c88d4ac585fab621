// SPDX-License-Identifier: MIT
#pragma once
// One synchronization2 image layout transition, for the whole of a single-mip, single-layer image
// (every image tutti makes). Record several with record_image_barriers.

#include <vulkan/vulkan.h>

#include <initializer_list>

namespace tutti::render {

VkImageMemoryBarrier2 image_barrier(VkImage image, VkImageAspectFlags aspect,
                                    VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                                    VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access,
                                    VkImageLayout old_layout, VkImageLayout new_layout);

void record_image_barriers(VkCommandBuffer commands,
                           std::initializer_list<VkImageMemoryBarrier2> barriers);

}  // namespace tutti::render
