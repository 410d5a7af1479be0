#pragma once

#include "phigs/image/Image.h"
#include "phigs/vk/Context.h"
#include "phigs/vk/ImageAttachment.h"

#include <vulkan/vulkan.h>

#include <cstdint>

namespace phigs::vk {

/// A colour image (RGBA8) and a depth image to render into without a window, plus the
/// host-visible buffer the colour image is read back through.
class OffscreenTarget {
public:
    static constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_UNORM;
    static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

    /// Throws std::invalid_argument for a size past the device's image and framebuffer limits.
    OffscreenTarget(Context& context, std::uint32_t width, std::uint32_t height);
    ~OffscreenTarget();
    OffscreenTarget(const OffscreenTarget&) = delete;
    OffscreenTarget& operator=(const OffscreenTarget&) = delete;

    std::uint32_t width() const { return width_; }
    std::uint32_t height() const { return height_; }
    VkImage colorImage() const { return color_.image; }
    VkImageView colorView() const { return color_.view; }
    VkImageView depthView() const { return depth_.view; }

    /// Records the copy of the colour image (which must be in TRANSFER_SRC_OPTIMAL layout) into
    /// the readback buffer, with the barrier that makes it visible to the host.
    void recordReadback(VkCommandBuffer cmd) const;
    /// The pixels last copied by recordReadback (after the submission has completed).
    Image readbackPixels() const;
    /// The same into `into`, reusing its pixels' room when the size is the same: no fresh pages to
    /// clear and fault in for every frame read back.
    void readbackPixels(Image& into) const;

private:
    void release();

    Context& context_;
    std::uint32_t width_;
    std::uint32_t height_;
    ImageAttachment color_;
    ImageAttachment depth_;
    ReadbackBuffer readback_;
};

}  // namespace phigs::vk
