#pragma once

#include "phigs/image/Image.h"
#include "phigs/traverse/DrawList.h"
#include "phigs/vk/Context.h"
#include "phigs/vk/OffscreenTarget.h"
#include "phigs/vk/Renderer.h"

#include <cstdint>
#include <filesystem>
#include <optional>

namespace phigs::vk {

/// The offscreen image target: draws a DrawList into an offscreen image and reads it back.
class ImageTarget {
public:
    ImageTarget(Context& context, std::uint32_t width, std::uint32_t height);
    ~ImageTarget();
    ImageTarget(const ImageTarget&) = delete;
    ImageTarget& operator=(const ImageTarget&) = delete;

    /// Draws the list and returns the picture (rows top to bottom).
    Image draw(const DrawList& list);
    /// Draws the list into `picture`, reusing its room (a workstation redraws into one image).
    void draw(const DrawList& list, Image& picture);
    /// Draws the list and writes the picture as a PNG file.
    void drawToPng(const DrawList& list, const std::filesystem::path& file);
    /// Frees the colour, depth and readback images (the renderer keeps its pipelines and
    /// buffers); the next draw makes them again.
    void releaseImages();

    Renderer& renderer() { return renderer_; }
    std::uint32_t width() const { return width_; }
    std::uint32_t height() const { return height_; }

private:
    void makeImages();

    Context& context_;
    std::uint32_t width_, height_;
    Renderer renderer_;
    std::optional<OffscreenTarget> target_;  ///< empty while released
    VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
};

}  // namespace phigs::vk
