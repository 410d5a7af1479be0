#pragma once

// Test doubles for the input tests: a measurer with fixed, checkable answers and a source
// that behaves like an idle window (nothing within the timeout).

#include "phigs/input/InputMeasurer.h"
#include "phigs/input/InputSource.h"

#include <deque>

namespace phigs::test {

/// Locator: world = (x, y, 0) of the pixel; pick: path {(1, x, y)} when x >= 0, else NONE.
class FakeMeasurer : public InputMeasurer {
public:
    LocatorMeasure locate(glm::dvec2 p) const override { return {0, glm::dvec3(p, 0.0)}; }
    StrokeMeasure stroke(const std::vector<glm::dvec2>& points) const override {
        StrokeMeasure m;
        for (const auto& p : points) m.points.emplace_back(p, 0.0);
        return m;
    }
    PickMeasure pick(glm::dvec2 p, const InputDevice& device) const override {
        PickMeasure m;
        if (p.x < 0) return m;
        m.status = InputStatus::Ok;
        m.path = {{device.number, static_cast<int>(p.x), static_cast<int>(p.y)}};
        return m;
    }
};

/// A source with queued actions that, once empty, reports nothing within any timeout; isLive
/// makes it a window's (InputSource::live).
class IdleSource : public InputSource {
public:
    std::deque<InputAction> actions;
    bool isLive = false;
    int polls = 0;
    std::optional<InputAction> next(std::chrono::milliseconds) override {
        ++polls;
        if (actions.empty()) return std::nullopt;
        InputAction a = actions.front();
        actions.pop_front();
        return a;
    }
    bool live() const override { return isLive; }
    bool exhausted() const override { return false; }
    std::string position() const override { return "idle window"; }
    void setEchoLayout(const EchoLayout& l) override { layout = l; }
    EchoLayout layout;
};

}  // namespace phigs::test
