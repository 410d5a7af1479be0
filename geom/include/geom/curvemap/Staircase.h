#pragma once

#include <glm/vec2.hpp>

#include <vector>

namespace geom::curvemap {

/// The iso-parametric ("step-size") approximation of a closed (u, w) loop (proposed in the ACSYNT
/// curve-mapping thesis, §6.4): a closed rectilinear polygon, every edge at constant u or constant w, that
/// stays within `tolerance` (parameter units) of the loop, both ways. The longest run of loop points that one
/// step (two iso-parametric segments through a junction point) follows within the tolerance is joined by that
/// step, greedily along the loop. The loop repeats its first point at the end; so does the result. Throws
/// GeometryError for fewer than 3 distinct points or a bad tolerance.
std::vector<glm::dvec2> staircaseApproximation(const std::vector<glm::dvec2>& loop, double tolerance);

}  // namespace geom::curvemap
