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

/// The echoes a workstation hands its output besides the picture (Workstation::echoState): the
/// string devices' echo areas. Choice panels and valuator sliders are structures the
/// application posts (buildChoicePanel, buildValuatorSlider).
struct EchoState {
    std::vector<StringEchoArea> strings;
    bool empty() const { return strings.empty(); }
    bool operator==(const EchoState&) const = default;
};

/// Appends the echoes to `picture` as items an output draws over it: per string echo area a
/// solid box, its outline and the shown line in stroke text, left aligned, placed through view 0
/// on the pixels of the area on the surface `mapping` describes. The items are not pickable.
void appendEchoes(DrawList& picture, const EchoState& echo, const WorkstationMapping& mapping,
                  const EchoStyle& style = {});

}  // namespace phigs
