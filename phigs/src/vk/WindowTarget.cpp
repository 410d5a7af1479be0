#include "phigs/vk/WindowTarget.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace phigs::vk {

ContextSettings WindowTarget::contextSettings(const WindowSurface& window, ContextSettings base) {
    for (const char* name : window.instanceExtensions()) base.instanceExtensions.push_back(name);
    base.deviceExtensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    return base;
}

WindowTarget::WindowTarget(Context& context, WindowSurface& window) : context_(context), window_(window) {
    try {
        surface_ = window_.createSurface(context_.instance());
        VkBool32 supported = VK_FALSE;
        vkGetPhysicalDeviceSurfaceSupportKHR(context_.physicalDevice(), context_.queueFamily(), surface_,
                                             &supported);
        if (!supported) throw std::runtime_error("Vulkan: the chosen queue cannot present to the window");
        std::uint32_t count = 0;
        vkGetPhysicalDeviceSurfaceFormatsKHR(context_.physicalDevice(), surface_, &count, nullptr);
        std::vector<VkSurfaceFormatKHR> formats(count);
        vkGetPhysicalDeviceSurfaceFormatsKHR(context_.physicalDevice(), surface_, &count, formats.data());
        if (formats.empty()) throw std::runtime_error("Vulkan: the window surface offers no format");
        format_ = formats.front();
        // UNORM formats keep colours as the offscreen target has them (PHIGS colours are not sRGB).
        for (const auto& f : formats)
            if (f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) {
                format_ = f;
                break;
            }
        renderer_ = std::make_unique<Renderer>(context_, format_.format, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR);

        VkSemaphoreCreateInfo semaphoreInfo{};
        semaphoreInfo.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO;
        check(vkCreateSemaphore(context_.device(), &semaphoreInfo, nullptr, &acquired_), "vkCreateSemaphore");
        check(vkCreateSemaphore(context_.device(), &semaphoreInfo, nullptr, &rendered_), "vkCreateSemaphore");
        VkFenceCreateInfo fenceInfo{};
        fenceInfo.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
        check(vkCreateFence(context_.device(), &fenceInfo, nullptr, &done_), "vkCreateFence");
        VkCommandBufferAllocateInfo alloc{};
        alloc.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
        alloc.commandPool = context_.commandPool();
        alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        alloc.commandBufferCount = 1;
        check(vkAllocateCommandBuffers(context_.device(), &alloc, &cmd_), "vkAllocateCommandBuffers");
        createSwapchain();
    } catch (...) {
        release();
        throw;
    }
}

WindowTarget::~WindowTarget() {
    release();
}

void WindowTarget::release() {
    VkDevice device = context_.device();
    vkDeviceWaitIdle(device);
    destroySwapchain();
    renderer_.reset();
    destroyReadbackBuffer(context_, readback_);
    if (cmd_) vkFreeCommandBuffers(device, context_.commandPool(), 1, &cmd_);
    if (done_) vkDestroyFence(device, done_, nullptr);
    if (rendered_) vkDestroySemaphore(device, rendered_, nullptr);
    if (acquired_) vkDestroySemaphore(device, acquired_, nullptr);
    cmd_ = VK_NULL_HANDLE;
    done_ = VK_NULL_HANDLE;
    rendered_ = acquired_ = VK_NULL_HANDLE;
    if (surface_) vkDestroySurfaceKHR(context_.instance(), surface_, nullptr);
    surface_ = VK_NULL_HANDLE;
}

void WindowTarget::createSwapchain() {
    VkDevice device = context_.device();
    VkSurfaceCapabilitiesKHR caps{};
    check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context_.physicalDevice(), surface_, &caps),
          "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
    drawableAtCreation_ = window_.drawableSize();
    const VkExtent2D size = caps.currentExtent.width != UINT32_MAX ? caps.currentExtent : drawableAtCreation_;
    extent_ = {std::clamp(size.width, caps.minImageExtent.width, caps.maxImageExtent.width),
               std::clamp(size.height, caps.minImageExtent.height, caps.maxImageExtent.height)};
    // A window its user made larger than the device can draw (X surfaces want exactly the
    // window's size): no swapchain, as while minimised, until it is made smaller again.
    const VkExtent2D largest = context_.largestDrawable();
    if (extent_.width > largest.width || extent_.height > largest.height) extent_ = {0, 0};
    if (extent_.width == 0 || extent_.height == 0) return;  // minimised: wait for a size
    VkSwapchainCreateInfoKHR info{};
    info.sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR;
    info.surface = surface_;
    info.minImageCount =
        caps.maxImageCount ? std::min(caps.minImageCount + 1, caps.maxImageCount) : caps.minImageCount + 1;
    info.imageFormat = format_.format;
    info.imageColorSpace = format_.colorSpace;
    info.imageExtent = extent_;
    info.imageArrayLayers = 1;
    info.imageUsage =
        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    canReadBack_ = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    if (!(caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR))
        info.compositeAlpha = VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR;
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR;
    info.clipped = VK_TRUE;
    check(vkCreateSwapchainKHR(device, &info, nullptr, &swapchain_), "vkCreateSwapchainKHR");
    std::uint32_t count = 0;
    vkGetSwapchainImagesKHR(device, swapchain_, &count, nullptr);
    images_.resize(count);
    vkGetSwapchainImagesKHR(device, swapchain_, &count, images_.data());

    // One depth image for all framebuffers: frames are drawn one at a time.
    depth_ = createImageAttachment(context_, extent_.width, extent_.height, Renderer::kDepthFormat,
                                   VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT);

    for (VkImage image : images_) {
        VkImageViewCreateInfo colourInfo{};
        colourInfo.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
        colourInfo.image = image;
        colourInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
        colourInfo.format = format_.format;
        colourInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkImageView view = VK_NULL_HANDLE;
        check(vkCreateImageView(device, &colourInfo, nullptr, &view), "vkCreateImageView (swapchain)");
        views_.push_back(view);
        VkImageView attachments[2] = {view, depth_.view};
        VkFramebufferCreateInfo fbInfo{};
        fbInfo.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
        fbInfo.renderPass = renderer_->renderPass();
        fbInfo.attachmentCount = 2;
        fbInfo.pAttachments = attachments;
        fbInfo.width = extent_.width;
        fbInfo.height = extent_.height;
        fbInfo.layers = 1;
        VkFramebuffer framebuffer = VK_NULL_HANDLE;
        check(vkCreateFramebuffer(device, &fbInfo, nullptr, &framebuffer), "vkCreateFramebuffer (swapchain)");
        framebuffers_.push_back(framebuffer);
    }
}

void WindowTarget::destroySwapchain() {
    VkDevice device = context_.device();
    for (VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(device, f, nullptr);
    for (VkImageView v : views_) vkDestroyImageView(device, v, nullptr);
    framebuffers_.clear();
    views_.clear();
    images_.clear();
    destroyImageAttachment(context_, depth_);
    if (swapchain_) vkDestroySwapchainKHR(device, swapchain_, nullptr);
    swapchain_ = VK_NULL_HANDLE;
}

void WindowTarget::recreateSwapchain() {
    vkDeviceWaitIdle(context_.device());
    destroySwapchain();
    createSwapchain();
}

bool WindowTarget::draw(const DrawList& list, Image* readback) {
    if (readback && swapchain_ && !canReadBack_)
        throw std::runtime_error("WindowTarget::draw: this surface's swapchain images cannot be read back");
    VkDevice device = context_.device();
    const VkExtent2D drawable = window_.drawableSize();
    if (drawable.width == 0 || drawable.height == 0) return false;  // minimised: nothing to show
    if (!swapchain_ || drawable.width != drawableAtCreation_.width ||
        drawable.height != drawableAtCreation_.height) {
        recreateSwapchain();
        if (!swapchain_) return false;
    }
    std::uint32_t index = 0;
    VkResult result =
        vkAcquireNextImageKHR(device, swapchain_, UINT64_MAX, acquired_, VK_NULL_HANDLE, &index);
    if (result == VK_ERROR_OUT_OF_DATE_KHR) {
        recreateSwapchain();  // the drawable changed under us: draw again on the new swapchain
        if (!swapchain_) return false;
        result = vkAcquireNextImageKHR(device, swapchain_, UINT64_MAX, acquired_, VK_NULL_HANDLE, &index);
    }
    if (result != VK_SUBOPTIMAL_KHR) check(result, "vkAcquireNextImageKHR");

    renderer_->prepare(list, extent_);
    // Checked before acquiring too; here it covers a swapchain created by this very call.
    const bool copy = readback != nullptr && canReadBack_;
    if (copy) {
        const VkDeviceSize size = VkDeviceSize{extent_.width} * extent_.height * 4;
        if (size > readback_.size) {
            destroyReadbackBuffer(context_, readback_);
            readback_ = createReadbackBuffer(context_, size);
        }
    }
    check(vkResetCommandBuffer(cmd_, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(cmd_, &begin), "vkBeginCommandBuffer");
    renderer_->record(cmd_, framebuffers_[index], extent_);
    if (copy) {
        auto barrier = [&](VkImageLayout from, VkImageLayout to, VkAccessFlags src, VkAccessFlags dst) {
            VkImageMemoryBarrier b{};
            b.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
            b.srcAccessMask = src;
            b.dstAccessMask = dst;
            b.oldLayout = from;
            b.newLayout = to;
            b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            b.image = images_[index];
            b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
            vkCmdPipelineBarrier(
                cmd_, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0, 0, nullptr, 0,
                nullptr, 1, &b);
        };
        barrier(VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {extent_.width, extent_.height, 1};
        vkCmdCopyImageToBuffer(cmd_, images_[index], VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.buffer,
                               1, &region);
        barrier(VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                VK_ACCESS_TRANSFER_READ_BIT, 0);
    }
    check(vkEndCommandBuffer(cmd_), "vkEndCommandBuffer");

    const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &acquired_;
    submit.pWaitDstStageMask = &waitStage;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd_;
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &rendered_;
    check(vkResetFences(device, 1, &done_), "vkResetFences");
    check(vkQueueSubmit(context_.queue(), 1, &submit, done_), "vkQueueSubmit");
    VkPresentInfoKHR present{};
    present.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR;
    present.waitSemaphoreCount = 1;
    present.pWaitSemaphores = &rendered_;
    present.swapchainCount = 1;
    present.pSwapchains = &swapchain_;
    present.pImageIndices = &index;
    result = vkQueuePresentKHR(context_.queue(), &present);
    // Frames are drawn one at a time, so the renderer may change its buffers in the next prepare().
    check(vkWaitForFences(device, 1, &done_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR) {
        recreateSwapchain();
    } else {
        check(result, "vkQueuePresentKHR");
    }
    if (copy) {
        Image image(extent_.width, extent_.height);
        void* mapped = nullptr;
        check(vkMapMemory(device, readback_.memory, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
        std::memcpy(image.rgba.data(), mapped, image.rgba.size());
        vkUnmapMemory(device, readback_.memory);
        const bool bgra =
            format_.format == VK_FORMAT_B8G8R8A8_UNORM || format_.format == VK_FORMAT_B8G8R8A8_SRGB;
        for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
            if (bgra) std::swap(image.rgba[i], image.rgba[i + 2]);
            image.rgba[i + 3] = 255;
        }
        *readback = std::move(image);
    }
    return true;
}

}  // namespace phigs::vk
