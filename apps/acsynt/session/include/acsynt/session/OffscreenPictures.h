#pragma once

#include "phigs/image/Image.h"
#include "phigs/traverse/DrawList.h"

#include <filesystem>
#include <memory>

namespace phigs::vk {
class Context;
class OffscreenWorkstation;
}  // namespace phigs::vk

namespace acsynt {

/// Draws the session workstation's picture headless (Vulkan offscreen, lavapipe unless
/// PHIGS_VK_DEVICE says otherwise) into images and PNG files. The session's workstation keeps
/// its viewport in pixels (as picking reads it); the renderer's device unit is the target's
/// shorter side, so the list is rescaled on the way (the one place the two conventions meet).
class OffscreenPictures {
public:
    OffscreenPictures(int width, int height);
    ~OffscreenPictures();
    OffscreenPictures(const OffscreenPictures&) = delete;
    OffscreenPictures& operator=(const OffscreenPictures&) = delete;

    phigs::Image draw(const phigs::DrawList& picture);
    void writePng(const phigs::DrawList& picture, const std::filesystem::path& file);

    /// The list with its viewport in the renderer's device units (pixels / shorter side).
    static phigs::DrawList forRenderer(const phigs::DrawList& picture, int width, int height);

private:
    int width_, height_;
    std::unique_ptr<phigs::vk::Context> context_;
    std::unique_ptr<phigs::vk::OffscreenWorkstation> workstation_;
};

}  // namespace acsynt
