#pragma once

#include "geom/Curve.h"
#include "geom/Surface.h"

#include <glm/vec3.hpp>

#include <limits>
#include <span>

namespace geom {

/// An axis-aligned box; empty when lo > hi in any coordinate.
struct BoundingBox {
    glm::dvec3 lo{std::numeric_limits<double>::infinity()};
    glm::dvec3 hi{-std::numeric_limits<double>::infinity()};

    void add(const glm::dvec3& p);
    void add(const BoundingBox& b);
    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    bool contains(const glm::dvec3& p, double tolerance = 0.0) const;
    glm::dvec3 center() const { return 0.5 * (lo + hi); }
    double diagonal() const;
    /// Euclidean distance from p to the box (0 inside).
    double distance(const glm::dvec3& p) const;
    /// True when the infinite line origin + t * direction meets the box grown by `margin`.
    bool hitByLine(const glm::dvec3& origin, const glm::dvec3& inverseDirection, double margin) const;
};

/// Box of a set of points.
BoundingBox boundingBox(std::span<const glm::dvec3> points);
/// Box of the control polygon: it holds the whole curve (convex hull property, weights > 0).
BoundingBox boundingBox(const Curve& curve);
/// Box of the control net: it holds the whole surface.
BoundingBox boundingBox(const Surface& surface);

}  // namespace geom
