#pragma once

#include "phigs/input/InputTypes.h"
#include "phigs/traverse/DrawList.h"
#include "phigs/traverse/WorkstationMapping.h"
#include "phigs/ws/EchoStructures.h"

#include <string>
#include <vector>

namespace phigs {

/// What one string device's echo area shows (prompt/echo type 1) while it is active: the text
/// typed so far with a cursor, or "cancelled" after Escape, until the next character.
struct StringEchoArea {
    int device = 1;
    EchoVolume area;  ///< pixels from the top left, y down
    std::string text;
    bool cancelled = false;
    /// The line drawn in the area.
    std::string shown() const { return cancelled ? "cancelled" : text + "_"; }
    bool operator==(const StringEchoArea& o) const {
        return device == o.device && text == o.text && cancelled == o.cancelled && area.xmin == o.area.xmin &&
               area.xmax == o.area.xmax && area.ymin == o.area.ymin && area.ymax == o.area.ymax;
    }
};

/// A choice device's menu panel (prompt/echo type 3) while the device is active with echo on;
/// `current` is the alternative its measure holds (0: none).
struct ChoiceEcho {
    ChoicePanel panel;
    int current = 0;
    bool operator==(const ChoiceEcho&) const = default;
};

/// A valuator's slider (prompt/echo type 2) while the device is active with echo on, its knob
/// at the measure's value.
struct ValuatorEcho {
    ValuatorSlider slider;
    double value = 0.0;
    bool operator==(const ValuatorEcho&) const = default;
};

/// The echoes a workstation hands its output besides the picture (Workstation::echoState): the
/// string devices' echo areas, and for an output that draws device echoes
/// (WorkstationOutput::drawsDeviceEchoes, the workstation's own window) the choice panels,
/// valuator sliders and the pick echo of the devices active with echo on. An application that
/// lays out its own window posts panels and sliders as structures instead (buildChoicePanel,
/// buildValuatorSlider).
struct EchoState {
    std::vector<StringEchoArea> strings;
    std::vector<ChoiceEcho> choices;
    std::vector<ValuatorEcho> valuators;
    /// The draw paths of the items the last pick of an active pick device echoes (highlighted).
    std::vector<std::vector<DrawPathLevel>> picked;
    bool empty() const { return strings.empty() && choices.empty() && valuators.empty() && picked.empty(); }
    bool operator==(const EchoState&) const = default;
};

/// Appends the echoes to `picture` as items an output draws over it: per string echo area a
/// solid box, its outline and the shown line in stroke text, left aligned; the choice panels
/// and valuator sliders as buildChoicePanel and buildValuatorSlider draw them; placed through
/// view 0 on the pixels of their areas on the surface `mapping` describes, not pickable. The
/// picture's items on the `picked` paths are marked highlighted.
void appendEchoes(DrawList& picture, const EchoState& echo, const WorkstationMapping& mapping,
                  const EchoStyle& style = {});

}  // namespace phigs
