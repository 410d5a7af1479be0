#pragma once

#include <vulkan/vulkan.h>

#include <vector>

namespace phigs::vk {

/// The seam between a window system and the window target: what phigs/window (GLFW) hands to
/// vk, so that no Vulkan code includes a window system's header. The window owns its events,
/// size and lifetime; the target asks it for a surface once and for the drawable size at
/// every frame. The window must outlive the target and the Context made for it.
class WindowSurface {
public:
    virtual ~WindowSurface() = default;
    /// The instance extensions a surface of this window system needs (names that stay valid
    /// while the window lives).
    virtual std::vector<const char*> instanceExtensions() const = 0;
    /// A new surface of the window on `instance`; the caller destroys it.
    virtual VkSurfaceKHR createSurface(VkInstance instance) = 0;
    /// The drawable in pixels now (0 x 0 while minimised).
    virtual VkExtent2D drawableSize() const = 0;
};

}  // namespace phigs::vk
