#include "acsynt/session/ViewNavigation.h"

#include <cmath>
#include <type_traits>

namespace acsynt {

using namespace phigs::window_event;

ViewNavigation::ViewNavigation(Session& session, std::function<void(const phigs::WindowEvent&)> forward)
    : session_(session), forward_(std::move(forward)) {
}

bool ViewNavigation::inViews(glm::dvec2 p) const {
    return session_.layout().geometry.contains(p);
}

bool ViewNavigation::handle(const phigs::WindowEvent& event) {
    return std::visit(
        [&](const auto& e) -> bool {
            using T = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<T, ButtonPress>) {
                if (drag_ != Drag::None || !inViews(e.position)) return false;
                last_ = e.position;
                pressed_ = e;
                if (e.button == Button::Middle || (e.button == Button::Left && e.shift)) {
                    drag_ = Drag::Pan;
                    return true;
                }
                if (e.button != Button::Left) return false;
                drag_ = Drag::Pending;  // a click or the start of a rotating drag
                return true;
            } else if constexpr (std::is_same_v<T, CursorMove>) {
                if (drag_ == Drag::None) return false;
                if (drag_ == Drag::Pending) {
                    if (glm::length(e.position - pressed_.position) < dragThreshold) return true;
                    drag_ = Drag::Rotate;
                }
                const glm::dvec2 d = e.position - last_;
                last_ = e.position;
                if (drag_ == Drag::Rotate)
                    session_.rotateView(-d.x * degreesPerPixel, d.y * degreesPerPixel);
                else
                    session_.panView(d);
                return true;
            } else if constexpr (std::is_same_v<T, ButtonRelease>) {
                if (drag_ == Drag::None) return false;
                const bool click = drag_ == Drag::Pending;
                const bool ends = e.button == pressed_.button;
                if (!ends) return true;
                drag_ = Drag::None;
                if (click) {  // no drag: the press was a click, for the devices
                    forward_(pressed_);
                    forward_(e);
                }
                return true;
            } else if constexpr (std::is_same_v<T, Scroll>) {
                if (!inViews(e.position) || e.delta == 0) return false;
                session_.zoomView(std::pow(1.15, e.delta));
                return true;
            } else if constexpr (std::is_same_v<T, KeyPress>) {
                if (e.key == Key::Function && e.function == 1) {
                    session_.toggleHelp();
                    return true;
                }
                if (e.key == Key::Escape && session_.helpShown()) {
                    session_.toggleHelp();
                    return true;
                }
                if (e.key == Key::Letter && e.control && (e.letter == 'Z' || e.letter == 'Y')) {
                    session_.undoRedoKey(e.letter == 'Z');
                    return true;
                }
                return false;
            } else if constexpr (std::is_same_v<T, Character>) {
                // H opens the help when nothing is being typed (else it is text for a prompt).
                if ((e.codepoint == 'h' || e.codepoint == 'H') && !session_.typing()) {
                    session_.toggleHelp();
                    return true;
                }
                return false;
            } else {
                return false;
            }
        },
        event);
}

}  // namespace acsynt
