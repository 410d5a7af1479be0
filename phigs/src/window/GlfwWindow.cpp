// GLFW with its Vulkan declarations: the window makes the surface the vk target draws on.
#include "phigs/window/GlfwWindow.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

namespace phigs {
namespace {

// GLFW is process-global: the first window initialises it, the last one terminates it.
std::mutex glfwMutex;
int glfwUsers = 0;

/// X11 reads the display from DISPLAY when GLFW starts; one display for the whole process.
/// Answers the DISPLAY to restore when GLFW then fails to start (none: nothing to restore).
std::optional<std::string> chooseDisplay(const std::string& display) {
    if (display.empty()) return std::nullopt;
    const char* current = std::getenv("DISPLAY");
    const std::string was = current ? current : "";
    if (glfwUsers > 0 && display != was)
        throw std::invalid_argument("GLFW: windows are open on display '" + was +
                                    "'; one process uses one display, not also '" + display + "'");
    setenv("DISPLAY", display.c_str(), 1);
    return was;
}

void acquireGlfw(const std::string& display) {
    std::lock_guard lock(glfwMutex);
    const std::optional<std::string> previous = chooseDisplay(display);
    if (glfwUsers == 0 && !glfwInit()) {
        const char* reason = nullptr;
        glfwGetError(&reason);
        const std::string why = reason ? reason : "unknown reason";
        if (previous) setenv("DISPLAY", previous->c_str(), 1);
        throw std::runtime_error("GLFW: cannot initialise (no display" +
                                 (display.empty() ? std::string() : " '" + display + "'") + "?): " + why);
    }
    ++glfwUsers;
}

void releaseGlfw() {
    std::lock_guard lock(glfwMutex);
    if (--glfwUsers == 0) glfwTerminate();
}

}  // namespace

GlfwWindow::GlfwWindow(std::uint32_t width, std::uint32_t height, const std::string& title,
                       const std::string& display) {
    if (width == 0 || height == 0 || width > kMaxSide || height > kMaxSide)
        throw std::invalid_argument("GlfwWindow: a window of " + std::to_string(width) + " x " +
                                    std::to_string(height) + " pixels (1.." + std::to_string(kMaxSide) +
                                    " each)");
    acquireGlfw(display);
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    window_ = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
    if (!window_) {
        releaseGlfw();
        throw std::runtime_error("GLFW: cannot create the window '" + title + "'");
    }
    glfwSetWindowUserPointer(window_, this);
    glfwGetFramebufferSize(window_, &eventWidth_, &eventHeight_);
    glfwSetFramebufferSizeCallback(window_, onResize);
    glfwSetWindowRefreshCallback(window_, onDamage);
    glfwSetWindowIconifyCallback(window_, onIconify);
}

GlfwWindow::~GlfwWindow() {
    glfwDestroyWindow(window_);
    releaseGlfw();
}

void GlfwWindow::onDamage(GLFWwindow* window) {
    if (auto* self = static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window))) ++self->damage_;
}

void GlfwWindow::onResize(GLFWwindow* window, int width, int height) {
    if (auto* self = static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window)))
        self->eventWidth_ = width, self->eventHeight_ = height;
    onDamage(window);
}

void GlfwWindow::onIconify(GLFWwindow* window, int) {
    onDamage(window);
}

std::vector<const char*> GlfwWindow::instanceExtensions() const {
    std::uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names) throw std::runtime_error("GLFW: Vulkan surfaces are not supported on this display");
    return {names, names + count};
}

VkSurfaceKHR GlfwWindow::createSurface(VkInstance instance) {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    if (const VkResult r = glfwCreateWindowSurface(instance, window_, nullptr, &surface); r != VK_SUCCESS)
        throw std::runtime_error("glfwCreateWindowSurface failed (VkResult " + std::to_string(int(r)) + ")");
    return surface;
}

bool GlfwWindow::iconified() const {
    return glfwGetWindowAttrib(window_, GLFW_ICONIFIED) == GLFW_TRUE;
}

VkExtent2D GlfwWindow::drawableSize() const {
    if (iconified()) return {0, 0};
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return {std::uint32_t(std::max(w, 0)), std::uint32_t(std::max(h, 0))};
}

VkExtent2D GlfwWindow::drawableSizeAsOfEvents() const {
    if (iconified()) return {0, 0};
    return {std::uint32_t(std::max(eventWidth_, 0)), std::uint32_t(std::max(eventHeight_, 0))};
}

bool GlfwWindow::shouldClose() const {
    return glfwWindowShouldClose(window_);
}

void GlfwWindow::requestClose() {
    glfwSetWindowShouldClose(window_, GLFW_TRUE);
}

void GlfwWindow::resize(std::uint32_t width, std::uint32_t height) {
    glfwSetWindowSize(window_, int(width), int(height));
}

void GlfwWindow::pollEvents() {
    glfwPollEvents();
}

}  // namespace phigs
