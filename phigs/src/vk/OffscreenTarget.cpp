#include "phigs/vk/OffscreenTarget.h"

#include <cstring>
#include <stdexcept>
#include <string>

namespace phigs::vk {

OffscreenTarget::OffscreenTarget(Context& context, std::uint32_t width, std::uint32_t height)
    : context_(context), width_(width), height_(height) {
    // Past the device's limits Vulkan's behaviour is undefined (validation errors, or a failed
    // allocation that names no cause): refused here, naming the limit.
    const VkExtent2D largest = context_.largestDrawable();
    if (width < 1 || height < 1 || width > largest.width || height > largest.height)
        throw std::invalid_argument("an offscreen image of " + std::to_string(width) + " x " +
                                    std::to_string(height) + " pixels: the device draws 1 x 1 to " +
                                    std::to_string(largest.width) + " x " + std::to_string(largest.height));
    try {
        color_ = createImageAttachment(context_, width, height, kColorFormat,
                                       VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                       VK_IMAGE_ASPECT_COLOR_BIT);
        depth_ =
            createImageAttachment(context_, width, height, kDepthFormat,
                                  VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT);
        readback_ = createReadbackBuffer(context_, VkDeviceSize{width} * height * 4);
    } catch (...) {
        release();
        throw;
    }
}

OffscreenTarget::~OffscreenTarget() {
    release();
}

void OffscreenTarget::release() {
    destroyReadbackBuffer(context_, readback_);
    destroyImageAttachment(context_, depth_);
    destroyImageAttachment(context_, color_);
}

void OffscreenTarget::recordReadback(VkCommandBuffer cmd) const {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {width_, height_, 1};
    vkCmdCopyImageToBuffer(cmd, color_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.buffer, 1,
                           &region);
    VkBufferMemoryBarrier toHost{};
    toHost.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER;
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    toHost.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.buffer = readback_.buffer;
    toHost.size = VK_WHOLE_SIZE;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1,
                         &toHost, 0, nullptr);
}

Image OffscreenTarget::readbackPixels() const {
    Image image;
    readbackPixels(image);
    return image;
}

void OffscreenTarget::readbackPixels(Image& into) const {
    // The size changes only with the pixels: a failure leaves `into` as it was.
    void* mapped = nullptr;
    check(vkMapMemory(context_.device(), readback_.memory, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
    try {
        into.rgba.resize(std::size_t{width_} * height_ * 4);
    } catch (...) {
        vkUnmapMemory(context_.device(), readback_.memory);
        throw;
    }
    std::memcpy(into.rgba.data(), mapped, into.rgba.size());
    vkUnmapMemory(context_.device(), readback_.memory);
    into.width = width_;
    into.height = height_;
}

}  // namespace phigs::vk
