#pragma once

#include "phigs/vk/Context.h"

#include <vulkan/vulkan.h>

#include <cstdint>

namespace phigs::vk {

/// A device-local 2D image with its memory and view: a render pass attachment.
struct ImageAttachment {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
};

/// Creates the image, its memory and its view; on failure frees what it made and throws.
ImageAttachment createImageAttachment(Context& context, std::uint32_t width, std::uint32_t height,
                                      VkFormat format, VkImageUsageFlags usage, VkImageAspectFlags aspect);
/// Frees whatever the attachment holds and empties it.
void destroyImageAttachment(Context& context, ImageAttachment& attachment);

/// A host-visible, coherent buffer that images are copied into to be read by the host.
struct ReadbackBuffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
};

/// Creates a readback buffer of `size` bytes; on failure frees what it made and throws.
ReadbackBuffer createReadbackBuffer(Context& context, VkDeviceSize size);
void destroyReadbackBuffer(Context& context, ReadbackBuffer& buffer);

}  // namespace phigs::vk
