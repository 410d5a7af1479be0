#pragma once

#include "phigs/image/Image.h"
#include "phigs/traverse/DrawList.h"
#include "phigs/vk/Context.h"
#include "phigs/vk/ImageAttachment.h"
#include "phigs/vk/Renderer.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace phigs::vk {

/// A workstation in a GLFW window: surface, swapchain (recreated on resize), the shared Renderer.
/// Create its Context with WindowWorkstation::contextSettings() so the surface extensions are on.
class WindowWorkstation {
public:
    /// Settings for a window context: GLFW's instance extensions, VK_KHR_swapchain, and a real
    /// GPU preferred (PHIGS_VK_DEVICE overrides; tests force lavapipe).
    static ContextSettings contextSettings();
    /// The same over explicit base settings (tests pass lavapipe).
    static ContextSettings contextSettings(ContextSettings base);

    WindowWorkstation(Context& context, std::uint32_t width, std::uint32_t height, const std::string& title);
    ~WindowWorkstation();
    WindowWorkstation(const WindowWorkstation&) = delete;
    WindowWorkstation& operator=(const WindowWorkstation&) = delete;

    /// Draws and presents the list; with `readback`, also copies the presented image into it.
    /// Returns false when the window has been closed.
    bool draw(const DrawList& list, Image* readback = nullptr);
    /// Processes window events; true once the user (or requestClose) asked to close.
    bool shouldClose();
    void requestClose();
    /// Resizes the window (the swapchain follows on the next draw).
    void resize(std::uint32_t width, std::uint32_t height);
    VkExtent2D extent() const { return extent_; }
    GLFWwindow* window() const { return window_; }
    Renderer& renderer() { return *renderer_; }

private:
    void createSwapchain();
    void destroySwapchain();
    void release();

    Context& context_;
    GLFWwindow* window_ = nullptr;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    VkSurfaceFormatKHR format_{};
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkExtent2D extent_{};
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
    bool closed_ = false;
    bool canReadBack_ = false;
};

}  // namespace phigs::vk
