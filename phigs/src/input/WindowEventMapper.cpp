#include "phigs/input/WindowEventMapper.h"

#include <glm/geometric.hpp>

#include <type_traits>

namespace phigs {
namespace {

void appendUtf8(std::string& out, char32_t c) {
    if (c < 0x80) {
        out += static_cast<char>(c);
    } else if (c < 0x800) {
        out += static_cast<char>(0xC0 | (c >> 6));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
        out += static_cast<char>(0xE0 | (c >> 12));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x110000) {
        out += static_cast<char>(0xF0 | (c >> 18));
        out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    }
}

void popUtf8(std::string& s) {
    while (!s.empty()) {
        const unsigned char c = static_cast<unsigned char>(s.back());
        s.pop_back();
        if ((c & 0xC0) != 0x80) return;  // removed a lead or single byte
    }
}

InputAction make(auto what, std::string text) {
    InputAction a;
    a.what = std::move(what);
    a.text = std::move(text);
    return a;
}

}  // namespace

std::optional<InputAction> WindowEventMapper::handle(const WindowEvent& event) {
    using namespace window_event;
    return std::visit(
        [&](const auto& e) -> std::optional<InputAction> {
            using T = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<T, ButtonPress>) {
                // A click in a choice panel stays a pick: WorkstationInput turns it into the
                // choice, for this source and a script alike. A slider needs the drag, here.
                if (e.button == Button::Left && !e.shift) {
                    for (const ValuatorSlider& s : layout_.sliders)
                        if (s.contains(e.position)) {
                            dragging_ = &s;
                            dragValue_ = s.valueAt(e.position);
                            return make(action::Valuator{s.device, dragValue_}, "slider");
                        }
                }
                if (e.button == Button::Left && e.shift) {
                    stroking_ = true;
                    stroke_ = {e.position};
                    return std::nullopt;
                }
                if (e.button == Button::Left) return make(action::Pick{e.position, 1}, "left click");
                if (e.button == Button::Right) return make(action::Locate{e.position, 1}, "right click");
                return std::nullopt;
            } else if constexpr (std::is_same_v<T, CursorMove>) {
                if (dragging_) return dragTo(e.position);
                if (!stroking_) return make(action::Move{e.position, 1}, "pointer move");
                if (glm::distance(stroke_.back(), e.position) >= strokeSpacing) stroke_.push_back(e.position);
                return std::nullopt;
            } else if constexpr (std::is_same_v<T, ButtonRelease>) {
                if (dragging_ && e.button == Button::Left) {
                    auto last = dragTo(e.position);
                    dragging_ = nullptr;
                    return last;
                }
                if (!stroking_ || e.button != Button::Left) return std::nullopt;
                stroking_ = false;
                if (stroke_.back() != e.position) stroke_.push_back(e.position);
                return make(action::Stroke{std::move(stroke_), 1}, "stroke drag");
            } else if constexpr (std::is_same_v<T, Scroll>) {
                return std::nullopt;
            } else if constexpr (std::is_same_v<T, Character>) {
                std::string text = echo_.text;
                appendUtf8(text, e.codepoint);
                edit(std::move(text), false);
                return std::nullopt;
            } else {
                switch (e.key) {
                    case Key::Enter: {
                        std::string done = echo_.text;
                        edit({}, false);
                        return make(action::String{done, 1}, "typed '" + done + "'");
                    }
                    case Key::Backspace: {
                        std::string text = echo_.text;
                        popUtf8(text);
                        edit(std::move(text), false);
                        return std::nullopt;
                    }
                    case Key::Escape:
                        edit({}, true);
                        stroking_ = false;
                        dragging_ = nullptr;
                        return make(action::Break{}, "escape");
                    case Key::Letter:
                        return std::nullopt;
                    case Key::Function:
                        if (e.function < 1) return std::nullopt;
                        return make(action::Choice{e.function, 1, {}}, "F" + std::to_string(e.function));
                }
                return std::nullopt;
            }
        },
        event);
}

std::optional<InputAction> WindowEventMapper::dragTo(glm::dvec2 position) {
    const double value = dragging_->valueAt(position);
    if (value == dragValue_) return std::nullopt;  // motion along the knob's axis only
    dragValue_ = value;
    return make(action::Valuator{dragging_->device, value}, "slider");
}

void WindowEventMapper::edit(std::string text, bool cancelled) {
    echo_.text = std::move(text);
    echo_.cancelled = cancelled;
    ++echo_.edits;
}

}  // namespace phigs
