#pragma once

#include "acsynt/AircraftDescription.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace acsynt {

/// The cross-section points a component is lofted through, in aircraft axes (x aft, y to the
/// right, z up): sectionCount sections of pointsPerSection points, section-major. Sections run
/// nose to tail (fuselage, nacelle) or root to tip (wings, tails); the points of a section run so
/// that (d/d section) x (d/d point) points out of the body.
struct SectionGrid {
    std::size_t sectionCount = 0;
    std::size_t pointsPerSection = 0;
    bool closedAround = false;  ///< true: the section is periodic (its first point is not repeated)
    std::vector<glm::dvec3> points;

    const glm::dvec3& at(std::size_t section, std::size_t point) const {
        return points[section * pointsPerSection + point];
    }
};

/// Sections of a component as described. Fuselage and nacelle sections start at the bottom
/// centre line and go round through -y, so the seam lies in the plane of symmetry. Wing
/// sections go from the sharp trailing edge over the upper surface to the leading edge and back
/// under the lower one, the trailing edge appearing first and last.
SectionGrid componentSections(const ComponentDescription& component);

/// The mirror image about y = 0, with the point order reversed so outward stays outward.
SectionGrid mirrored(const SectionGrid& grid);

}  // namespace acsynt
