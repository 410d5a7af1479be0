#pragma once

#include "acsynt/AircraftDescription.h"
#include "acsynt/Patch.h"
#include "acsynt/Sections.h"

#include "geom/Surface.h"

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace acsynt {

/// One aircraft component as the application works on it: its cross sections, the bicubic
/// B-spline surface lofted through them (u across the sections, w round each section; the
/// surface's v is w) and the surface's patch list.
struct Component {
    std::string name;
    ComponentKind kind = ComponentKind::Fuselage;
    glm::dvec3 colour{1.0};
    bool closedU = false;  ///< ACSYNT's open[0] == 1: periodic in u (never, for the shipped kinds)
    bool closedW = false;  ///< periodic round the section (fuselage, nacelle)
    SectionGrid sections;
    std::vector<double> sectionParameters;  ///< u of each section
    std::vector<double> pointParameters;    ///< w of each section point (closed: plus the closing 1)
    geom::Surface surface;
    PatchList patches;

    /// Rebuilds the patch list after the surface was changed (knot removal, knot insertion).
    void updatePatches() { patches = buildPatches(surface); }
};

/// Lofts a component through its sections: chord-length parameters averaged over the grid,
/// bicubic global interpolation, periodic round closed sections. Throws geom::GeometryError when
/// the sections cannot be interpolated (coincident sections).
Component loftComponent(std::string name, ComponentKind kind, const glm::dvec3& colour, SectionGrid sections);

}  // namespace acsynt
