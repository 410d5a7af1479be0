#pragma once

#include "phigs/image/Image.h"
#include "phigs/traverse/DrawList.h"
#include "phigs/vk/Context.h"
#include "phigs/vk/ImageAttachment.h"
#include "phigs/vk/Renderer.h"
#include "phigs/vk/WindowSurface.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace phigs::vk {

/// The window target: a surface of a window (made by the window system through WindowSurface),
/// its swapchain (recreated when the drawable changes size) and the shared Renderer. Create its
/// Context with WindowTarget::contextSettings(window, ...) so the surface extensions are on.
class WindowTarget {
public:
    /// The window's instance extensions and VK_KHR_swapchain over `base` (a real GPU preferred
    /// unless `base` says otherwise; tests pass lavapipe).
    static ContextSettings contextSettings(const WindowSurface& window, ContextSettings base);

    WindowTarget(Context& context, WindowSurface& window);
    ~WindowTarget();
    WindowTarget(const WindowTarget&) = delete;
    WindowTarget& operator=(const WindowTarget&) = delete;

    /// Draws and presents the list at the drawable's current size; with `readback`, also
    /// copies the presented image into it. False when nothing could be shown (minimised).
    bool draw(const DrawList& list, Image* readback = nullptr);
    /// The swapchain's size (the drawable's at the last draw).
    VkExtent2D extent() const { return extent_; }
    /// The drawable's size now, as the window reports it.
    VkExtent2D drawableSize() const { return window_.drawableSize(); }
    Renderer& renderer() { return *renderer_; }

private:
    void createSwapchain();
    void destroySwapchain();
    void recreateSwapchain();
    void release();

    Context& context_;
    WindowSurface& window_;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    VkSurfaceFormatKHR format_{};
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkExtent2D extent_{};
    VkExtent2D drawableAtCreation_{};  // the window's drawable when the swapchain was made
    std::vector<VkImage> images_;
    std::vector<VkImageView> views_;
    std::vector<VkFramebuffer> framebuffers_;
    ImageAttachment depth_;
    std::unique_ptr<Renderer> renderer_;
    VkSemaphore acquired_ = VK_NULL_HANDLE;
    VkSemaphore rendered_ = VK_NULL_HANDLE;
    VkFence done_ = VK_NULL_HANDLE;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    ReadbackBuffer readback_;
    bool canReadBack_ = false;
};

}  // namespace phigs::vk
