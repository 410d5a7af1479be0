#include "phigs/vk/ImageTarget.h"

namespace phigs::vk {

ImageTarget::ImageTarget(Context& context, std::uint32_t width, std::uint32_t height)
    : context_(context),
      target_(context, width, height),
      renderer_(context, OffscreenTarget::kColorFormat, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL) {
    VkImageView views[2] = {target_.colorView(), target_.depthView()};
    VkFramebufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
    info.renderPass = renderer_.renderPass();
    info.attachmentCount = 2;
    info.pAttachments = views;
    info.width = width;
    info.height = height;
    info.layers = 1;
    check(vkCreateFramebuffer(context_.device(), &info, nullptr, &framebuffer_), "vkCreateFramebuffer");
}

ImageTarget::~ImageTarget() {
    vkDeviceWaitIdle(context_.device());
    vkDestroyFramebuffer(context_.device(), framebuffer_, nullptr);
}

Image ImageTarget::draw(const DrawList& list) {
    const VkExtent2D extent{target_.width(), target_.height()};
    renderer_.prepare(list, extent);
    context_.submitAndWait([&](VkCommandBuffer cmd) {
        renderer_.record(cmd, framebuffer_, extent);
        target_.recordReadback(cmd);
    });
    return target_.readbackPixels();
}

void ImageTarget::drawToPng(const DrawList& list, const std::filesystem::path& file) {
    writePng(draw(list), file);
}

}  // namespace phigs::vk
