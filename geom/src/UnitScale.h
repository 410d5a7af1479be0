#pragma once

// Private to geom: measuring in coordinates divided by a net's extent, so that squared distances
// neither overflow (coordinates past about 1e154) nor underflow (below about 1e-154).

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <span>

namespace geom::detail {

/// The largest absolute coordinate of `p`.
inline double largestCoordinate(const glm::dvec3& p) {
    return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
}

/// The power of two that brings `extent` (a largest coordinate) into [1, 2) (1 for zero).
/// Multiplying by a power of two is exact, so a result computed on the scaled points and divided
/// by this scale again is the one computed on the points themselves, where that one neither
/// overflows nor underflows.
inline double unitScaleOf(double extent) {
    if (!(extent > 0.0) || !std::isfinite(extent)) return 1.0;
    // Clamped so that the scale of a subnormal extent stays finite.
    return std::ldexp(1.0, -std::max(std::ilogb(extent), -1020));
}

/// unitScaleOf the largest coordinate of `points`.
inline double unitScale(std::span<const glm::dvec3> points) {
    double extent = 0.0;
    for (const glm::dvec3& p : points) extent = std::max(extent, largestCoordinate(p));
    return unitScaleOf(extent);
}

}  // namespace geom::detail
