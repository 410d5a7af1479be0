#pragma once

#include "acsynt/session/CurveMapping.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace acsynt {

/// The marker of DEFINE POINT: the reference point on the picked patch.
struct ReferencePoint {
    int component = -1;
    int patch = 0;
    double u = 0, w = 0;
};

/// One MAP CURVE: which curve on which component, and what came out.
struct MappingRecord {
    std::string model, component, curveFile;
    ReferencePoint reference;
    std::size_t parts = 0, loops = 0, boundaryWalks = 0;
    std::vector<std::size_t> loopsPerPart;
    std::vector<std::vector<glm::dvec3>> polylines;    ///< the mapped loops in model coordinates
    std::vector<std::vector<glm::dvec2>> uvPolylines;  ///< the same loops in the component's (u, w)
    std::vector<PartReport> partReports;               ///< every part: mapped, clipped or lost, and why
};

}  // namespace acsynt
