#pragma once

#include "phigs/input/InputAction.h"

#include <glm/vec2.hpp>

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace phigs {

/// What a window reports, in device pixels from the top left (y down), free of any toolkit.
namespace window_event {
enum class Button { Left, Right, Middle };
struct ButtonPress {
    Button button = Button::Left;
    glm::dvec2 position{0.0};
    bool shift = false;
};
struct ButtonRelease {
    Button button = Button::Left;
    glm::dvec2 position{0.0};
};
struct CursorMove {
    glm::dvec2 position{0.0};
};
enum class Key { Enter, Backspace, Escape, Function };
struct KeyPress {
    Key key = Key::Enter;
    int function = 0;  ///< 1 for F1, ... (Key::Function)
};
struct Character {
    char32_t codepoint = 0;
};
}  // namespace window_event

using WindowEvent = std::variant<window_event::ButtonPress, window_event::ButtonRelease,
                                 window_event::CursorMove, window_event::KeyPress, window_event::Character>;

/// Turns window events into operator actions, the same actions a session script holds:
/// left click: pick (and locator); right click: locator only; pointer motion: move (sample
/// locators follow it); shift + left drag: stroke;
/// typed characters then Enter: string (Backspace edits, Escape breaks a request);
/// F1..F12: choice 1..12 (until the toolkit draws choice panels).
class WindowEventMapper {
public:
    /// The action this event completes, if any.
    std::optional<InputAction> handle(const WindowEvent& event);

    const std::string& pendingText() const { return text_; }
    bool stroking() const { return stroking_; }
    /// Stroke points closer than this to the previous one are dropped (pixels).
    double strokeSpacing = 2.0;

private:
    std::string text_;
    bool stroking_ = false;
    std::vector<glm::dvec2> stroke_;
};

}  // namespace phigs
