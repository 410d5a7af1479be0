#include "acsynt/Component.h"

#include "geom/GlobalInterpolation.h"

namespace acsynt {

Component loftComponent(std::string name, ComponentKind kind, const glm::dvec3& colour,
                        SectionGrid sections) {
    Component c;
    c.name = std::move(name);
    c.kind = kind;
    c.colour = colour;
    c.closedU = false;
    c.closedW = sections.closedAround;
    const geom::Closure around = c.closedW ? geom::Closure::Periodic : geom::Closure::Open;
    const geom::GridParameters parameters = geom::chordLengthGridParameters(
        sections.points, sections.sectionCount, sections.pointsPerSection, geom::Closure::Open, around);
    c.surface = geom::interpolateSurface(sections.points, sections.sectionCount, sections.pointsPerSection,
                                         parameters, 3, 3, geom::Closure::Open, around);
    c.sectionParameters = parameters.u;
    c.pointParameters = parameters.v;
    c.sections = std::move(sections);
    c.updatePatches();
    return c;
}

}  // namespace acsynt
