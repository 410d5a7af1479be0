#pragma once

#include "phigs/input/InputDevice.h"
#include "phigs/input/InputTypes.h"

#include <glm/vec2.hpp>

#include <optional>
#include <string>
#include <vector>

namespace phigs {

/// An on-screen menu of a choice device (prompt/echo type 3): its alternatives stacked top to
/// bottom in equal rows filling the echo area.
struct ChoicePanel {
    int device = 1;
    EchoVolume area;  ///< pixels from the top left, y down
    std::vector<std::string> alternatives;

    /// The 1-based alternative under the pixel, or nullopt outside the panel.
    std::optional<int> choiceAt(glm::dvec2 pixel) const;
    /// Top-left and bottom-right pixel corners of alternative `choice` (1-based), for drawing.
    std::pair<glm::dvec2, glm::dvec2> row(int choice) const;
    bool operator==(const ChoicePanel&) const = default;
};

/// An on-screen slider of a valuator device (prompt/echo type 2): low at the left (or bottom)
/// end of the echo area, high at the other, horizontal when the area is wider than high.
struct ValuatorSlider {
    int device = 1;
    EchoVolume area;
    double low = 0.0, high = 1.0;

    bool contains(glm::dvec2 pixel) const;
    /// The value at the pixel, clamped into [low, high].
    double valueAt(glm::dvec2 pixel) const;
    /// Where the slider's knob sits for `value` (pixel along the slider's long axis).
    double knobAt(double value) const;
    bool operator==(const ValuatorSlider&) const = default;
};

/// The panels and sliders a workstation's devices put on the screen, for a window source to
/// turn clicks into choices and drags into values (a script source ignores it).
struct EchoLayout {
    std::vector<ChoicePanel> panels;
    std::vector<ValuatorSlider> sliders;
    bool empty() const { return panels.empty() && sliders.empty(); }
};

/// The initialisation of a choice device shown as a menu panel (prompt/echo type 3) over
/// `area` (pixels, y down) with the named alternatives, `initial` current (1-based).
DeviceInitialisation choicePanelInitialisation(std::vector<std::string> alternatives, EchoVolume area,
                                               int initial = 1);
/// The initialisation of a valuator shown as a slider (prompt/echo type 2) over `area`.
DeviceInitialisation valuatorSliderInitialisation(double low, double high, double initial, EchoVolume area);

}  // namespace phigs
