#include "phigs/input/EchoLayout.h"

#include <algorithm>
#include <cmath>

namespace phigs {
namespace {

bool inside(const EchoVolume& a, glm::dvec2 p) {
    return p.x >= a.xmin && p.x <= a.xmax && p.y >= a.ymin && p.y <= a.ymax;
}

bool horizontal(const EchoVolume& a) {
    return a.xmax - a.xmin >= a.ymax - a.ymin;
}

}  // namespace

std::optional<int> ChoicePanel::choiceAt(glm::dvec2 pixel) const {
    if (alternatives.empty() || !inside(area, pixel)) return std::nullopt;
    const double rowHeight = (area.ymax - area.ymin) / static_cast<double>(alternatives.size());
    const int row = static_cast<int>(std::floor((pixel.y - area.ymin) / rowHeight));
    return std::clamp(row, 0, static_cast<int>(alternatives.size()) - 1) + 1;
}

std::pair<glm::dvec2, glm::dvec2> ChoicePanel::row(int choice) const {
    const double rowHeight =
        (area.ymax - area.ymin) / static_cast<double>(std::max<std::size_t>(alternatives.size(), 1));
    const double top = area.ymin + rowHeight * (choice - 1);
    return {{area.xmin, top}, {area.xmax, top + rowHeight}};
}

bool ValuatorSlider::contains(glm::dvec2 pixel) const {
    return inside(area, pixel);
}

double ValuatorSlider::valueAt(glm::dvec2 pixel) const {
    // Horizontal: low at the left; vertical: low at the bottom (y grows downwards).
    const double f = horizontal(area) ? (pixel.x - area.xmin) / (area.xmax - area.xmin)
                                      : (area.ymax - pixel.y) / (area.ymax - area.ymin);
    return low + std::clamp(f, 0.0, 1.0) * (high - low);
}

double ValuatorSlider::knobAt(double value) const {
    const double f = std::clamp((value - low) / (high - low), 0.0, 1.0);
    return horizontal(area) ? area.xmin + f * (area.xmax - area.xmin)
                            : area.ymax - f * (area.ymax - area.ymin);
}

DeviceInitialisation choicePanelInitialisation(std::vector<std::string> alternatives, EchoVolume area,
                                               int initial) {
    DeviceInitialisation d;
    d.initial = ChoiceMeasure{InputStatus::Ok, initial};
    d.promptEchoType = 3;
    d.echoVolume = area;
    d.choiceStrings = std::move(alternatives);
    return d;
}

DeviceInitialisation valuatorSliderInitialisation(double low, double high, double initial, EchoVolume area) {
    DeviceInitialisation d;
    d.initial = ValuatorMeasure{initial};
    d.promptEchoType = 2;
    d.echoVolume = area;
    d.valuatorLow = low;
    d.valuatorHigh = high;
    return d;
}

}  // namespace phigs
