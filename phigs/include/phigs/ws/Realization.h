#pragma once

#include "phigs/view/WorkstationTables.h"
#include "phigs/ws/PatternTable.h"
#include "phigs/ws/WorkstationType.h"

namespace phigs {

/// What a workstation described by `d` draws for a representation (the REALIZED values of
/// INQUIRE ... REPRESENTATION): widths and marker sizes within the description's range, text in
/// STROKE precision (every font is stroked), an undefined colour index as index 1, a direct
/// colour converted to RGB and clamped to [0, 1]; the PHIGS PLUS entries (shading, reflectance,
/// approximation) as set.
PolylineBundle realized(const PolylineBundle& b, const WorkstationDescription& d, const ColourTable& c);
PolymarkerBundle realized(const PolymarkerBundle& b, const WorkstationDescription& d, const ColourTable& c);
TextBundle realized(const TextBundle& b, const WorkstationDescription& d, const ColourTable& c);
InteriorBundle realized(const InteriorBundle& b, const WorkstationDescription& d, const ColourTable& c);
EdgeBundle realized(const EdgeBundle& b, const WorkstationDescription& d, const ColourTable& c);
PatternRepresentation realized(const PatternRepresentation& p, const ColourTable& c);

}  // namespace phigs
