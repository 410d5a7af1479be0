#pragma once

#include <glm/vec2.hpp>

#include <vector>

namespace phigs::hardcopy {

/// The outline of a union of counter-clockwise contours as closed loops: every edge that another
/// contour runs the other way between the same two points (exactly) cancels with it, and what
/// is left is chained into loops. The loops' non-zero winding covers the union, as the contours
/// filled one by one by that rule do, and each point of the union's boundary lies on a loop, so
/// stroking the loops reaches as far out as stroking every contour. A mesh's facets of one colour
/// then paint as a few long loops instead of a path per facet.
std::vector<std::vector<glm::dvec2>> unionOutline(
    const std::vector<const std::vector<glm::dvec2>*>& contours);

}  // namespace phigs::hardcopy
