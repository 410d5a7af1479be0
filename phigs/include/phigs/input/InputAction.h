#pragma once

#include <glm/vec2.hpp>

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace phigs {

/// What an operator does, as an input source reports it. Positions are in device coordinates
/// of the workstation (pixels, origin at the top left, y down).
namespace action {
struct Pick {  ///< a button press at a point: triggers pick and locator devices
    glm::dvec2 position{0.0};
    int device = 1;
    bool operator==(const Pick&) const = default;
};
struct Locate {  ///< a button press meant for the locator only
    glm::dvec2 position{0.0};
    int device = 1;
    bool operator==(const Locate&) const = default;
};
/// The pointer moved without a trigger: only locators in SAMPLE mode follow it.
struct Move {
    glm::dvec2 position{0.0};
    int device = 1;
    bool operator==(const Move&) const = default;
};
struct Stroke {
    std::vector<glm::dvec2> points;
    int device = 1;
    bool operator==(const Stroke&) const = default;
};
struct Valuator {
    int device = 1;
    double value = 0.0;
    bool operator==(const Valuator&) const = default;
};
struct Choice {
    int choice = 0;
    int device = 1;
    std::string name;  ///< chosen by the alternative's name (a menu entry) when not empty
    bool operator==(const Choice&) const = default;
};
struct String {
    std::string text;
    int device = 1;
    bool operator==(const String&) const = default;
};
struct Break {  ///< the operator breaks a pending request (status NONE)
    bool operator==(const Break&) const = default;
};
/// Nothing happens for one await period (an AWAIT EVENT times out). A window also ends the
/// wait this way when its picture was lost (resized, exposed), so the application can redraw
/// at once; that is no operator action and is not recorded.
struct Wait {
    bool surfaceChanged = false;
    bool operator==(const Wait&) const = default;
};
/// A line addressed to the application, not to a device (e.g. "snapshot front.png").
struct Directive {
    std::string name;
    std::vector<std::string> arguments;
    bool operator==(const Directive&) const = default;
};
}  // namespace action

/// One operator action and where it came from (a script line, or 0 for a window).
struct InputAction {
    std::variant<action::Pick, action::Locate, action::Move, action::Stroke, action::Valuator, action::Choice,
                 action::String, action::Break, action::Wait, action::Directive>
        what;
    int line = 0;
    std::string text;  ///< the action as written, for messages
    /// The drawable's size in pixels when the operator acted (a window), which the positions map
    /// through: a click taken off the queue after a resize belongs to the picture it was made on.
    /// Empty (a script): the size when the action is measured.
    std::optional<glm::uvec2> surface;
    /// An operator's action in a window: one no device can take (a function key past a choice
    /// device's alternatives) is ignored, and a pending request goes on waiting; a script's line
    /// that no device can take is an error.
    bool fromOperator = false;
};

}  // namespace phigs
