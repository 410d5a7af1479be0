#pragma once

// Private to geom: when the last of a closed curve's data points is its first.

#include "geom/BoundingBox.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <vector>

namespace geom::detail {

/// Whether the last point is the first within rounding: 1e-9 of the points' own extent, plus
/// rounding's share of their distance from the origin. Scale-free: a model far smaller than a
/// unit is held to its own size, not to a unit's.
inline bool endsAtStart(const std::vector<glm::dvec3>& points) {
    const BoundingBox box = boundingBox(points);
    const glm::dvec3 far = glm::max(glm::abs(box.lo), glm::abs(box.hi));
    return glm::length(points.back() - points.front()) <=
           1e-9 * box.diagonal() + 1e-14 * std::max({far.x, far.y, far.z});
}

}  // namespace geom::detail
