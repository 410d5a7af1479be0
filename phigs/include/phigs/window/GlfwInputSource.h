#pragma once

#include "phigs/input/InputSource.h"
#include "phigs/input/WindowEventMapper.h"
#include "phigs/window/GlfwWindow.h"

#include <deque>
#include <functional>
#include <optional>

struct GLFWwindow;

namespace phigs {

/// An input source reading a GLFW window: its mouse and keyboard callbacks go through a
/// WindowEventMapper, and next() blocks in glfwWaitEventsTimeout (no polling: an idle window
/// costs no CPU). Positions are framebuffer pixels (window coordinates scaled on high-density
/// displays), y down. Given a GlfwWindow, a wait ends early with a `Wait{surfaceChanged}` when
/// the window was resized or exposed, so the application redraws at once; or, with a damage
/// handler, the handler repaints and the wait goes on.
class GlfwInputSource : public InputSource {
public:
    /// Installs the callbacks on `window` (GLFW must be initialised; one source per window).
    explicit GlfwInputSource(GLFWwindow* window);
    explicit GlfwInputSource(GlfwWindow& window);
    ~GlfwInputSource() override;
    GlfwInputSource(const GlfwInputSource&) = delete;
    GlfwInputSource& operator=(const GlfwInputSource&) = delete;

    std::optional<InputAction> next(std::chrono::milliseconds timeout) override;
    bool exhausted() const override { return false; }
    std::string position() const override { return "window"; }
    void setEchoLayout(const EchoLayout& layout) override { mapper_.setLayout(layout); }
    StringEcho stringEcho() const override { return mapper_.stringEcho(); }
    void startString(const std::string& text) override { mapper_.startString(text); }
    /// True once the window's user (or requestClose) asked to close it.
    bool closed() const override;
    bool live() const override { return true; }

    /// Delivers an event as the window's callbacks do: to the event filter, then (unless the
    /// filter took it) to the mapper.
    void post(const WindowEvent& event);
    /// Gives every window event first to `filter`, which returns true when it took the event
    /// (an application's own navigation: wheel, drags in its views, shortcut keys); events it
    /// leaves go to the mapper. An empty filter removes it.
    void setEventFilter(std::function<bool(const WindowEvent&)> filter) { filter_ = std::move(filter); }
    /// Delivers an event to the mapper alone (what a filter hands back after holding it).
    void deliver(const WindowEvent& event);
    const WindowEventMapper& mapper() const { return mapper_; }
    /// The pointer in framebuffer pixels as of the events processed so far (a click is where it
    /// was made, though the pointer has moved on since); asked of the window system before the
    /// first motion.
    glm::dvec2 pointerAsOfEvents() const;
    /// Records a motion event's position (window coordinates), as the cursor callback does.
    void pointerMoved(glm::dvec2 windowCoordinates) { pointer_ = windowCoordinates; }
    /// Called, instead of ending the wait, when the window was resized or exposed: a window whose
    /// picture the toolkit keeps (a workstation's own window) repaints it without the
    /// application. An empty handler restores the Wait{surfaceChanged}.
    void setDamageHandler(std::function<void()> handler) { damageHandler_ = std::move(handler); }

private:
    GLFWwindow* window_;
    const GlfwWindow* owner_ = nullptr;  ///< for its damage count, when given one
    std::uint64_t damageSeen_ = 0;
    WindowEventMapper mapper_;
    std::deque<InputAction> pending_;
    std::function<bool(const WindowEvent&)> filter_;
    std::function<void()> damageHandler_;
    std::optional<glm::dvec2> pointer_;  ///< window coordinates, from the last motion event
};

}  // namespace phigs
