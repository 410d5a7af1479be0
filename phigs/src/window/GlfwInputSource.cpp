// GLFW for input: the window callbacks feed the event mapper.
#include "phigs/window/GlfwInputSource.h"

#include <GLFW/glfw3.h>

#include <map>
#include <mutex>
#include <stdexcept>

namespace phigs {
namespace {

std::mutex registryMutex;
std::map<GLFWwindow*, GlfwInputSource*>& registry() {
    static std::map<GLFWwindow*, GlfwInputSource*> sources;
    return sources;
}

GlfwInputSource* sourceOf(GLFWwindow* window) {
    std::lock_guard lock(registryMutex);
    const auto it = registry().find(window);
    return it == registry().end() ? nullptr : it->second;
}

/// Window coordinates to framebuffer pixels.
glm::dvec2 pixels(GLFWwindow* window, double x, double y) {
    int ww = 0, wh = 0, fw = 0, fh = 0;
    glfwGetWindowSize(window, &ww, &wh);
    glfwGetFramebufferSize(window, &fw, &fh);
    const double sx = ww > 0 ? static_cast<double>(fw) / ww : 1.0;
    const double sy = wh > 0 ? static_cast<double>(fh) / wh : 1.0;
    return {x * sx, y * sy};
}

void onButton(GLFWwindow* window, int button, int action, int mods) {
    GlfwInputSource* source = sourceOf(window);
    if (!source) return;
    window_event::Button b = window_event::Button::Left;
    if (button == GLFW_MOUSE_BUTTON_RIGHT) b = window_event::Button::Right;
    if (button == GLFW_MOUSE_BUTTON_MIDDLE) b = window_event::Button::Middle;
    const glm::dvec2 at = source->pointerAsOfEvents();
    if (action == GLFW_PRESS)
        source->post(window_event::ButtonPress{b, at, (mods & GLFW_MOD_SHIFT) != 0});
    else if (action == GLFW_RELEASE)
        source->post(window_event::ButtonRelease{b, at});
}

void onCursor(GLFWwindow* window, double x, double y) {
    if (GlfwInputSource* source = sourceOf(window)) {
        source->pointerMoved({x, y});
        source->post(window_event::CursorMove{pixels(window, x, y)});
    }
}

void onKey(GLFWwindow* window, int key, int, int action, int mods) {
    GlfwInputSource* source = sourceOf(window);
    if (!source || action == GLFW_RELEASE) return;
    using window_event::Key;
    if ((mods & GLFW_MOD_CONTROL) && key >= GLFW_KEY_A && key <= GLFW_KEY_Z && action == GLFW_PRESS)
        source->post(window_event::KeyPress{Key::Letter, 0, char('A' + (key - GLFW_KEY_A)), true});
    if (key == GLFW_KEY_ENTER || key == GLFW_KEY_KP_ENTER) source->post(window_event::KeyPress{Key::Enter});
    if (key == GLFW_KEY_BACKSPACE) source->post(window_event::KeyPress{Key::Backspace});
    if (key == GLFW_KEY_ESCAPE && action == GLFW_PRESS) source->post(window_event::KeyPress{Key::Escape});
    if (key >= GLFW_KEY_F1 && key <= GLFW_KEY_F12 && action == GLFW_PRESS)
        source->post(window_event::KeyPress{Key::Function, key - GLFW_KEY_F1 + 1});
}

void onScroll(GLFWwindow* window, double, double y) {
    if (GlfwInputSource* source = sourceOf(window))
        source->post(window_event::Scroll{source->pointerAsOfEvents(), y});
}

void onCharacter(GLFWwindow* window, unsigned int codepoint) {
    if (GlfwInputSource* source = sourceOf(window)) source->post(window_event::Character{codepoint});
}

}  // namespace

GlfwInputSource::GlfwInputSource(GLFWwindow* window) : window_(window) {
    if (!window_) throw std::invalid_argument("GlfwInputSource: no window");
    {
        std::lock_guard lock(registryMutex);
        if (!registry().emplace(window_, this).second)
            throw std::invalid_argument("GlfwInputSource: the window already has an input source");
    }
    glfwSetMouseButtonCallback(window_, onButton);
    glfwSetCursorPosCallback(window_, onCursor);
    glfwSetKeyCallback(window_, onKey);
    glfwSetCharCallback(window_, onCharacter);
    glfwSetScrollCallback(window_, onScroll);
}

GlfwInputSource::GlfwInputSource(GlfwWindow& window) : GlfwInputSource(window.handle()) {
    owner_ = &window;
    damageSeen_ = window.damage();
}

GlfwInputSource::~GlfwInputSource() {
    glfwSetMouseButtonCallback(window_, nullptr);
    glfwSetCursorPosCallback(window_, nullptr);
    glfwSetKeyCallback(window_, nullptr);
    glfwSetCharCallback(window_, nullptr);
    glfwSetScrollCallback(window_, nullptr);
    std::lock_guard lock(registryMutex);
    registry().erase(window_);
}

void GlfwInputSource::post(const WindowEvent& event) {
    if (filter_ && filter_(event)) return;
    deliver(event);
}

void GlfwInputSource::deliver(const WindowEvent& event) {
    if (auto a = mapper_.handle(event)) {
        a->fromOperator = true;
        // The picture the operator acted on: its size as the resize events so far left it.
        if (owner_) {
            const VkExtent2D size = owner_->drawableSizeAsOfEvents();
            if (size.width > 0 && size.height > 0) a->surface = glm::uvec2(size.width, size.height);
        }
        pending_.push_back(std::move(*a));
    }
}

glm::dvec2 GlfwInputSource::pointerAsOfEvents() const {
    if (pointer_) return pixels(window_, pointer_->x, pointer_->y);
    double x = 0, y = 0;
    glfwGetCursorPos(window_, &x, &y);
    return pixels(window_, x, y);
}

bool GlfwInputSource::closed() const {
    return glfwWindowShouldClose(window_) == GLFW_TRUE;
}

std::optional<InputAction> GlfwInputSource::next(std::chrono::milliseconds timeout) {
    if (pending_.empty()) {
        if (timeout.count() > 0)
            glfwWaitEventsTimeout(static_cast<double>(timeout.count()) / 1000.0);
        else
            glfwPollEvents();
    }
    if (pending_.empty() && owner_ && owner_->damage() != damageSeen_) {
        damageSeen_ = owner_->damage();
        if (damageHandler_) {
            damageHandler_();
            return pending_.empty() ? std::nullopt : next(std::chrono::milliseconds(0));
        }
        InputAction wake;
        wake.what = action::Wait{true};
        wake.text = "window resized or exposed";
        return wake;
    }
    if (pending_.empty()) return std::nullopt;
    InputAction a = std::move(pending_.front());
    pending_.pop_front();
    return a;
}

}  // namespace phigs
