#include "EchoShapes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace phigs::detail {

std::vector<EchoShape> choicePanelShapes(const ChoicePanel& panel, int current,
                                         const WorkstationMapping& mapping, const EchoStyle& style) {
    std::vector<EchoShape> shapes;
    const double z = style.npcZ;
    for (int n = 1; n <= static_cast<int>(panel.alternatives.size()); ++n) {
        const auto [topLeft, bottomRight] = panel.row(n);
        // One pixel of gap between rows, so the boxes read as separate buttons.
        const glm::dvec3 a = mapping.pixelsToNpc(topLeft + glm::dvec2(1.0, 1.0), z);
        const glm::dvec3 b = mapping.pixelsToNpc(bottomRight - glm::dvec2(1.0, 1.0), z);
        const bool isCurrent = n == current;
        shapes.push_back({n, true, a, b, isCurrent ? style.current : style.box, 0.0, {}});
        shapes.push_back({n,
                          false,
                          (a + b) * 0.5,
                          {},
                          isCurrent ? style.currentText : style.text,
                          std::abs(a.y - b.y) * 0.45,
                          panel.alternatives[static_cast<std::size_t>(n - 1)]});
    }
    return shapes;
}

std::vector<EchoShape> valuatorSliderShapes(const ValuatorSlider& slider, double value,
                                            const std::string& label, const WorkstationMapping& mapping,
                                            const EchoStyle& style) {
    const EchoVolume& area = slider.area;
    const bool horizontal = area.xmax - area.xmin >= area.ymax - area.ymin;
    const double z = style.npcZ;
    std::vector<EchoShape> shapes;
    const glm::dvec3 lo = mapping.pixelsToNpc({area.xmin, area.ymax}, z);  // bottom left
    const glm::dvec3 hi = mapping.pixelsToNpc({area.xmax, area.ymin}, z);  // top right
    shapes.push_back({1, true, lo, hi, style.track, 0.0, {}});

    // The knob: a tenth of the long axis (at least 6 pixels) centred on the value.
    const double along = slider.knobAt(value);
    const double length = horizontal ? area.xmax - area.xmin : area.ymax - area.ymin;
    const double half = std::max(3.0, length * 0.05);
    const glm::dvec3 knobA = horizontal ? mapping.pixelsToNpc({along - half, area.ymax}, z)
                                        : mapping.pixelsToNpc({area.xmin, along + half}, z);
    const glm::dvec3 knobB = horizontal ? mapping.pixelsToNpc({along + half, area.ymin}, z)
                                        : mapping.pixelsToNpc({area.xmax, along - half}, z);
    shapes.push_back({2, true, knobA, knobB, style.current, 0.0, {}});

    char number[32];
    std::snprintf(number, sizeof number, "%.3g", value);
    const std::string text = label.empty() ? std::string(number) : label + ": " + number;
    const double thickness = horizontal ? hi.y - lo.y : hi.x - lo.x;
    const double height = std::abs(thickness) * 0.6;
    const glm::dvec3 at = horizontal ? glm::dvec3((lo.x + hi.x) * 0.5, hi.y + height, z)
                                     : glm::dvec3(hi.x + height * text.size() * 0.5, (lo.y + hi.y) * 0.5, z);
    shapes.push_back({3, false, at, {}, style.text, height, text});
    return shapes;
}

}  // namespace phigs::detail
