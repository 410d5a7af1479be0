#pragma once

// Private to geom: a point's distance from a segment, in the plane or in space.

#include <glm/geometric.hpp>

#include <algorithm>

namespace geom::detail {

/// The distance from p to the segment [a, b] (to a where the segment has no length).
template <class Vec>
double segmentDistance(const Vec& p, const Vec& a, const Vec& b) {
    const Vec ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

}  // namespace geom::detail
