#pragma once

#include "phigs/vk/WindowSurface.h"

#include <cstdint>
#include <string>
#include <vector>

struct GLFWwindow;

namespace phigs {

/// A GLFW window: GLFW itself (the first window initialises it, the last terminates it), the
/// window, its size, its close request and its events, and the Vulkan surface factory a
/// vk::WindowTarget draws on. The only code besides GlfwInputSource that includes GLFW.
class GlfwWindow : public vk::WindowSurface {
public:
    /// The largest side of a window it opens (the Vulkan limit of the drivers here); a window its
    /// user makes larger shows no picture until it is made smaller again (vk::WindowTarget).
    static constexpr std::uint32_t kMaxSide = 16384;

    /// Opens a resizable window on `display` (an X display name; empty: $DISPLAY); throws
    /// std::runtime_error naming the reason when GLFW cannot start (no display) or the window
    /// cannot be made, std::invalid_argument for a second display in one process.
    GlfwWindow(std::uint32_t width, std::uint32_t height, const std::string& title,
               const std::string& display = {});
    ~GlfwWindow() override;
    GlfwWindow(const GlfwWindow&) = delete;
    GlfwWindow& operator=(const GlfwWindow&) = delete;

    std::vector<const char*> instanceExtensions() const override;
    VkSurfaceKHR createSurface(VkInstance instance) override;
    /// The framebuffer in pixels; 0 x 0 while the window is minimised (iconified), on every
    /// window system (X keeps an iconified window's size).
    VkExtent2D drawableSize() const override;
    /// drawableSize() as of the events processed so far (the resizes delivered in order with the
    /// clicks), where drawableSize() asks the window system now.
    VkExtent2D drawableSizeAsOfEvents() const;
    /// True while the window is minimised.
    bool iconified() const;

    /// True once the user (or requestClose) asked to close. Does not process events: the input
    /// source's wait does.
    bool shouldClose() const;
    void requestClose();
    /// Asks the window system for a new size (the drawable follows once the server agrees).
    void resize(std::uint32_t width, std::uint32_t height);
    /// Processes pending events without waiting.
    void pollEvents();
    /// Counts the times the picture was lost: resized, minimised, restored, exposed. A presenter draws
    /// again when it moves.
    std::uint64_t damage() const { return damage_; }
    GLFWwindow* handle() const { return window_; }

private:
    static void onDamage(GLFWwindow* window);
    static void onResize(GLFWwindow* window, int, int);
    static void onIconify(GLFWwindow* window, int);

    GLFWwindow* window_ = nullptr;
    std::uint64_t damage_ = 0;
    int eventWidth_ = 0, eventHeight_ = 0;  // the framebuffer as the last resize event gave it
};

}  // namespace phigs
