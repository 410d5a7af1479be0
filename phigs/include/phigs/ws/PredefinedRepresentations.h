#pragma once

#include "phigs/view/WorkstationTables.h"
#include "phigs/ws/PatternTable.h"
#include "phigs/ws/WorkstationType.h"

#include <vector>

namespace phigs {

/// The representations a workstation type's description table predefines, which every
/// workstation of the type starts with (INQUIRE PREDEFINED ... REPRESENTATION): bundles and
/// patterns from index 1, colours and views from index 0.
struct PredefinedRepresentations {
    std::vector<PolylineBundle> polylines;
    std::vector<PolymarkerBundle> polymarkers;
    std::vector<TextBundle> texts;
    std::vector<InteriorBundle> interiors;
    std::vector<EdgeBundle> edges;
    std::vector<PatternRepresentation> patterns;
    std::vector<glm::dvec3> colours;
    std::vector<ViewRepresentation> views;
};

/// The predefined representations of `type` (the same for every type this implementation has).
const PredefinedRepresentations& predefinedRepresentations(WorkstationType type);

}  // namespace phigs
