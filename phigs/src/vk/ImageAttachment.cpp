#include "phigs/vk/ImageAttachment.h"

namespace phigs::vk {

ImageAttachment createImageAttachment(Context& context, std::uint32_t width, std::uint32_t height,
                                      VkFormat format, VkImageUsageFlags usage, VkImageAspectFlags aspect) {
    VkDevice device = context.device();
    ImageAttachment a;
    VkImageCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {width, height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    check(vkCreateImage(device, &info, nullptr, &a.image), "vkCreateImage");
    try {
        VkMemoryRequirements req{};
        vkGetImageMemoryRequirements(device, a.image, &req);
        VkMemoryAllocateInfo alloc{};
        alloc.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex = context.memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        check(vkAllocateMemory(device, &alloc, nullptr, &a.memory), "vkAllocateMemory (image)");
        check(vkBindImageMemory(device, a.image, a.memory, 0), "vkBindImageMemory");
        VkImageViewCreateInfo viewInfo{};
        viewInfo.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
        viewInfo.image = a.image;
        viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
        viewInfo.format = format;
        viewInfo.subresourceRange = {aspect, 0, 1, 0, 1};
        check(vkCreateImageView(device, &viewInfo, nullptr, &a.view), "vkCreateImageView");
    } catch (...) {
        destroyImageAttachment(context, a);
        throw;
    }
    return a;
}

void destroyImageAttachment(Context& context, ImageAttachment& a) {
    VkDevice device = context.device();
    if (a.view) vkDestroyImageView(device, a.view, nullptr);
    if (a.image) vkDestroyImage(device, a.image, nullptr);
    if (a.memory) vkFreeMemory(device, a.memory, nullptr);
    a = ImageAttachment{};
}

ReadbackBuffer createReadbackBuffer(Context& context, VkDeviceSize size) {
    VkDevice device = context.device();
    ReadbackBuffer b;
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = size;
    info.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    check(vkCreateBuffer(device, &info, nullptr, &b.buffer), "vkCreateBuffer (readback)");
    try {
        VkMemoryRequirements req{};
        vkGetBufferMemoryRequirements(device, b.buffer, &req);
        VkMemoryAllocateInfo alloc{};
        alloc.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex = context.memoryType(
            req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        check(vkAllocateMemory(device, &alloc, nullptr, &b.memory), "vkAllocateMemory (readback)");
        check(vkBindBufferMemory(device, b.buffer, b.memory, 0), "vkBindBufferMemory");
    } catch (...) {
        destroyReadbackBuffer(context, b);
        throw;
    }
    b.size = size;
    return b;
}

void destroyReadbackBuffer(Context& context, ReadbackBuffer& b) {
    VkDevice device = context.device();
    if (b.buffer) vkDestroyBuffer(device, b.buffer, nullptr);
    if (b.memory) vkFreeMemory(device, b.memory, nullptr);
    b = ReadbackBuffer{};
}

}  // namespace phigs::vk
