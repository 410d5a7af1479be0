#pragma once

#include "geom/Surface.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace geom {

/// One crossing of a line with a surface: point = origin + t * direction, uv the surface
/// parameters there, piece the Bézier patch index in extractBezier(surface) order.
struct LineSurfaceHit {
    double t = 0.0;
    glm::dvec2 uv{0.0};
    glm::dvec3 point{0.0};
    std::size_t piece = 0;
};

/// Every intersection of the infinite line origin + t * direction with the surface, sorted by
/// t. Each hit lies on the surface within 1e-9 of the surface's size; tangent contacts count
/// once, and so does a pole the line passes through (an edge collapsed to one point), a patch
/// collapsed to one point, or a patch edge it runs along (one hit, at the edge's middle). Two
/// smooth sheets crossing at one point of the line (a self-intersection) are two hits there.
/// Where the line's origin or the surface lies far from (0, 0, 0) for the surface's size, the
/// bound is the rounding of those coordinates instead (about 1e-14 of them). A line that grazes
/// the surface within the bound over a stretch (nearly tangent) may give several hits along it.
/// For many lines against one surface, build a SurfaceIntersector once instead.
std::vector<LineSurfaceHit> intersectLine(const Surface& surface, const glm::dvec3& origin,
                                          const glm::dvec3& direction);

/// The hits of intersectLine with t >= 0 (a ray from origin).
std::vector<LineSurfaceHit> intersectRay(const Surface& surface, const glm::dvec3& origin,
                                         const glm::dvec3& direction);

}  // namespace geom
