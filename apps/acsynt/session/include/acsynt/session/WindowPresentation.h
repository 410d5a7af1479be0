#pragma once

#ifdef ACSYNT_HAVE_WINDOW

#include "acsynt/session/Session.h"
#include "phigs/vk/WorkstationDisplay.h"
#include "phigs/window/GlfwWindow.h"

#include <chrono>
#include <cstdint>

namespace acsynt {

/// The interactive session's loop body: one session step (blocking in the window's event wait,
/// so an idle window costs no CPU), then the layout follows the window's drawable and the
/// picture is presented only when the workstation's picture changed or the window lost it.
/// The program and the window tests run the same steps.
class WindowPresentation {
public:
    /// The display shows `session`'s workstation in `window`; all three outlive this.
    WindowPresentation(Session& session, phigs::GlfwWindow& window, phigs::vk::WorkstationDisplay& display);

    /// One step waiting at most `timeout` for input; false once the session is over or the
    /// window was asked to close.
    bool step(std::chrono::milliseconds timeout);
    /// Follows the drawable's size and presents when needed, without waiting for input.
    void present();
    /// Pictures presented so far.
    std::uint64_t frames() const { return frames_; }

private:
    Session& session_;
    phigs::GlfwWindow& window_;
    phigs::vk::WorkstationDisplay& display_;
    std::uint64_t shownPicture_ = ~std::uint64_t{0};
    std::uint64_t shownDamage_ = ~std::uint64_t{0};
    std::uint64_t frames_ = 0;
};

}  // namespace acsynt

#endif
