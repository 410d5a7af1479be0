#include "phigs/vk/OffscreenTarget.h"

#include <cstring>

namespace phigs::vk {

OffscreenTarget::OffscreenTarget(Context& context, std::uint32_t width, std::uint32_t height)
    : context_(context), width_(width), height_(height) {
    try {
        color_ = createAttachment(kColorFormat,
                                  VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                  VK_IMAGE_ASPECT_COLOR_BIT);
        depth_ = createAttachment(kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                  VK_IMAGE_ASPECT_DEPTH_BIT);

        VkBufferCreateInfo bufferInfo{};
        bufferInfo.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
        bufferInfo.size = VkDeviceSize{width} * height * 4;
        bufferInfo.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        bufferInfo.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
        check(vkCreateBuffer(context_.device(), &bufferInfo, nullptr, &readback_),
              "vkCreateBuffer (readback)");
        VkMemoryRequirements req{};
        vkGetBufferMemoryRequirements(context_.device(), readback_, &req);
        VkMemoryAllocateInfo alloc{};
        alloc.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex = context_.memoryType(
            req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        check(vkAllocateMemory(context_.device(), &alloc, nullptr, &readbackMemory_),
              "vkAllocateMemory (readback)");
        check(vkBindBufferMemory(context_.device(), readback_, readbackMemory_, 0), "vkBindBufferMemory");
    } catch (...) {
        release();
        throw;
    }
}

OffscreenTarget::~OffscreenTarget() {
    release();
}

void OffscreenTarget::release() {
    VkDevice device = context_.device();
    if (readback_) vkDestroyBuffer(device, readback_, nullptr);
    if (readbackMemory_) vkFreeMemory(device, readbackMemory_, nullptr);
    readback_ = VK_NULL_HANDLE;
    readbackMemory_ = VK_NULL_HANDLE;
    destroyAttachment(depth_);
    destroyAttachment(color_);
}

OffscreenTarget::Attachment OffscreenTarget::createAttachment(VkFormat format, VkImageUsageFlags usage,
                                                              VkImageAspectFlags aspect) {
    VkDevice device = context_.device();
    Attachment a;
    VkImageCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {width_, height_, 1};
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
        alloc.memoryTypeIndex = context_.memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
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
        destroyAttachment(a);
        throw;
    }
    return a;
}

void OffscreenTarget::destroyAttachment(Attachment& a) {
    VkDevice device = context_.device();
    if (a.view) vkDestroyImageView(device, a.view, nullptr);
    if (a.image) vkDestroyImage(device, a.image, nullptr);
    if (a.memory) vkFreeMemory(device, a.memory, nullptr);
    a = Attachment{};
}

void OffscreenTarget::recordReadback(VkCommandBuffer cmd) const {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {width_, height_, 1};
    vkCmdCopyImageToBuffer(cmd, color_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_, 1, &region);
    VkBufferMemoryBarrier toHost{};
    toHost.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER;
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    toHost.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.buffer = readback_;
    toHost.size = VK_WHOLE_SIZE;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1,
                         &toHost, 0, nullptr);
}

Image OffscreenTarget::readbackPixels() const {
    Image image(width_, height_);
    void* mapped = nullptr;
    check(vkMapMemory(context_.device(), readbackMemory_, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
    std::memcpy(image.rgba.data(), mapped, image.rgba.size());
    vkUnmapMemory(context_.device(), readbackMemory_);
    return image;
}

}  // namespace phigs::vk
