#include "phigs/vk/ImageTarget.h"

namespace phigs::vk {

ImageTarget::ImageTarget(Context& context, std::uint32_t width, std::uint32_t height)
    : context_(context),
      width_(width),
      height_(height),
      renderer_(context, OffscreenTarget::kColorFormat, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL) {
    makeImages();
}

ImageTarget::~ImageTarget() {
    releaseImages();
}

void ImageTarget::makeImages() {
    target_.emplace(context_, width_, height_);
    VkImageView views[2] = {target_->colorView(), target_->depthView()};
    VkFramebufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
    info.renderPass = renderer_.renderPass();
    info.attachmentCount = 2;
    info.pAttachments = views;
    info.width = width_;
    info.height = height_;
    info.layers = 1;
    try {
        check(vkCreateFramebuffer(context_.device(), &info, nullptr, &framebuffer_), "vkCreateFramebuffer");
    } catch (...) {
        target_.reset();
        throw;
    }
}

void ImageTarget::releaseImages() {
    if (!target_) return;
    vkDeviceWaitIdle(context_.device());
    vkDestroyFramebuffer(context_.device(), framebuffer_, nullptr);
    framebuffer_ = VK_NULL_HANDLE;
    target_.reset();
}

Image ImageTarget::draw(const DrawList& list) {
    Image picture;
    draw(list, picture);
    return picture;
}

void ImageTarget::draw(const DrawList& list, Image& picture) {
    if (!target_) makeImages();
    const VkExtent2D extent{width_, height_};
    renderer_.prepare(list, extent);
    context_.submitAndWait([&](VkCommandBuffer cmd) {
        renderer_.record(cmd, framebuffer_, extent);
        target_->recordReadback(cmd);
    });
    target_->readbackPixels(picture);
}

void ImageTarget::drawToPng(const DrawList& list, const std::filesystem::path& file) {
    writePng(draw(list), file);
}

}  // namespace phigs::vk
