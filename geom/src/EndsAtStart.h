#pragma once

// Private to geom: when the last of a closed curve's data points is its first.

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace geom::detail {

/// Whether the last point is the first within rounding: 1e-9 of the points' own extent, plus
/// rounding's share of their distance from the origin. Scale-free: a model far smaller than a
/// unit is held to its own size, not to a unit's.
inline bool endsAtStart(const std::vector<glm::dvec3>& points) {
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    double far = 0.0;
    for (const glm::dvec3& p : points) {
        lo = glm::min(lo, p), hi = glm::max(hi, p);
        far = std::max(far, std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
    }
    return glm::length(points.back() - points.front()) <= 1e-9 * glm::length(hi - lo) + 1e-14 * far;
}

}  // namespace geom::detail
