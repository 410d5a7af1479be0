#pragma once

#include "phigs/input/InputSource.h"
#include "phigs/input/WindowEventMapper.h"

#include <deque>

struct GLFWwindow;

namespace phigs {

/// An input source reading a GLFW window: its mouse and keyboard callbacks go through a
/// WindowEventMapper, and next() waits in glfwWaitEventsTimeout. Positions are framebuffer
/// pixels (window coordinates scaled on high-density displays), y down.
class GlfwInputSource : public InputSource {
public:
    /// Installs the callbacks on `window` (GLFW must be initialised; one source per window).
    explicit GlfwInputSource(GLFWwindow* window);
    ~GlfwInputSource() override;
    GlfwInputSource(const GlfwInputSource&) = delete;
    GlfwInputSource& operator=(const GlfwInputSource&) = delete;

    std::optional<InputAction> next(std::chrono::milliseconds timeout) override;
    bool exhausted() const override { return false; }
    std::string position() const override { return "window"; }
    void setEchoLayout(const EchoLayout& layout) override { mapper_.setLayout(layout); }

    /// Delivers an event as the window's callbacks do.
    void post(const WindowEvent& event);
    const WindowEventMapper& mapper() const { return mapper_; }

private:
    GLFWwindow* window_;
    WindowEventMapper mapper_;
    std::deque<InputAction> pending_;
};

}  // namespace phigs
