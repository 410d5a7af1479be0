#pragma once

#include "phigs/input/EchoLayout.h"
#include "phigs/input/InputAction.h"
#include "phigs/input/InputSource.h"

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
/// The wheel turned at the pointer: `delta` notches, positive away from the user.
struct Scroll {
    glm::dvec2 position{0.0};
    double delta = 0.0;
};
enum class Key { Enter, Backspace, Escape, Function, Letter };
struct KeyPress {
    Key key = Key::Enter;
    int function = 0;  ///< 1 for F1, ... (Key::Function)
    char letter = 0;   ///< 'A'..'Z' (Key::Letter: reported only with Control held)
    bool control = false;
};
struct Character {
    char32_t codepoint = 0;
};
}  // namespace window_event

using WindowEvent =
    std::variant<window_event::ButtonPress, window_event::ButtonRelease, window_event::CursorMove,
                 window_event::KeyPress, window_event::Character, window_event::Scroll>;

/// Turns window events into operator actions, the same actions a session script holds:
/// left click: pick (and locator); right click: locator only; pointer motion: move (sample
/// locators follow it); shift + left drag: stroke;
/// typed characters then Enter: string (Backspace edits, Escape breaks a request);
/// F1..F12: choice 1..12; the wheel and Control + letter make no action (an application's
/// event filter may take them, see GlfwInputSource::setEventFilter). A left press in a valuator slider of the
/// echo layout starts a drag that sets the value at the press, at every motion that changes it and at the
/// release (a click in a choice panel is a pick, which WorkstationInput turns into the choice). The text
/// being typed is the string device's echo (stringEcho()).
class WindowEventMapper {
public:
    /// The action this event completes, if any.
    std::optional<InputAction> handle(const WindowEvent& event);

    /// Replaces the panels and sliders (a slider drag under way is dropped).
    void setLayout(EchoLayout layout) {
        layout_ = std::move(layout);
        dragging_ = nullptr;
    }
    const EchoLayout& layout() const { return layout_; }
    const std::string& pendingText() const { return echo_.text; }
    /// What the string echo area shows: the text typed so far, or that Escape cancelled it.
    const StringEcho& stringEcho() const { return echo_; }
    /// The text typed starts over as `text` (a string device's initial string, to be edited).
    void startString(std::string text) { edit(std::move(text), false); }
    bool stroking() const { return stroking_; }
    /// Stroke points closer than this to the previous one are dropped (pixels).
    double strokeSpacing = 2.0;

private:
    EchoLayout layout_;
    std::optional<InputAction> dragTo(glm::dvec2 position);
    void edit(std::string text, bool cancelled);

    const ValuatorSlider* dragging_ = nullptr;
    double dragValue_ = 0.0;
    StringEcho echo_;
    bool stroking_ = false;
    std::vector<glm::dvec2> stroke_;
};

}  // namespace phigs
