#pragma once

#include "acsynt/session/Session.h"
#include "phigs/input/WindowEventMapper.h"

#include <functional>

namespace acsynt {

/// Mouse and key navigation of the session's views in a window, on the window's own events
/// before they become PHIGS input: a left drag in a view rotates the 3D view (trackball:
/// across turns the azimuth, up and down the elevation), the wheel zooms, a middle or
/// Shift + left drag pans; F1 or H (no prompt open) shows and hides the help overlay; Ctrl+Z and
/// Ctrl+Y undo and redo. A left press in a view that does not become a drag is handed back as
/// a click (a pick); everything else outside the views goes on to the input devices.
class ViewNavigation {
public:
    /// `forward` delivers an event to the window's input mapping (GlfwInputSource::deliver).
    ViewNavigation(Session& session, std::function<void(const phigs::WindowEvent&)> forward);

    /// Offers a window event; true when navigation took it.
    bool handle(const phigs::WindowEvent& event);

    /// Pixels a left press must move before it is a drag rather than a click.
    double dragThreshold = 4.0;
    /// Degrees per pixel of a rotating drag.
    double degreesPerPixel = 0.4;

private:
    enum class Drag { None, Pending, Rotate, Pan };
    bool inViews(glm::dvec2 p) const;

    Session& session_;
    std::function<void(const phigs::WindowEvent&)> forward_;
    Drag drag_ = Drag::None;
    phigs::window_event::ButtonPress pressed_;
    glm::dvec2 last_{0.0};
};

}  // namespace acsynt
