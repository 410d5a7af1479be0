#pragma once

// Private: the boxes and labels of a choice panel or a valuator slider in NPC, in drawing order,
// made once for both ways of showing them: as the elements of a structure the application posts
// (buildChoicePanel, buildValuatorSlider) and as draw items over a picture (appendEchoes).

#include "phigs/ws/EchoStructures.h"

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace phigs::detail {

/// A solid box outlined in EchoStyle::outline (corners `a`, `b`), or a label centred on `a`.
struct EchoShape {
    int pickId = 0;
    bool box = true;
    glm::dvec3 a{0.0}, b{0.0};
    glm::dvec3 colour{0.0};  ///< the box's fill, the label's text
    double height = 0.0;     ///< the label's cap height (NPC)
    std::string text;
};

std::vector<EchoShape> choicePanelShapes(const ChoicePanel& panel, int current,
                                         const WorkstationMapping& mapping, const EchoStyle& style);
std::vector<EchoShape> valuatorSliderShapes(const ValuatorSlider& slider, double value,
                                            const std::string& label, const WorkstationMapping& mapping,
                                            const EchoStyle& style);

}  // namespace phigs::detail
