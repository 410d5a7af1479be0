#pragma once

#include <glm/vec2.hpp>

#include <cstdint>
#include <vector>

namespace phigs::render {

/// A triangulation vertex: a point on edge (from, to) of the input contours at parameter t, so
/// per-vertex data (colours, normals) can be interpolated; indices count over all contours.
struct TriangulationVertex {
    glm::dvec2 point{0.0};
    std::uint32_t from = 0;
    std::uint32_t to = 0;
    double t = 0.0;
};

/// Triangles covering the even-odd interior of planar contours.
struct Triangulation {
    std::vector<TriangulationVertex> vertices;
    std::vector<std::uint32_t> triangles;  ///< three indices per triangle, counter-clockwise
};

/// Triangulates closed contours (concave, with holes, even self-intersecting) by the even-odd rule:
/// the plane is cut into horizontal slabs at every vertex and crossing, and each slab's inside
/// spans become trapezoids, one per pair of edges for as many slabs as the pair bounds them (a
/// simple polygon of n points gives O(n)). Degenerate contours (fewer than 3 points) are ignored.
/// A lone triangle (one contour of 3 points) is returned as it is, its corners as the vertices.
/// Throws std::length_error for contours whose edges cross so often that the work would pass
/// about 2 x 10^9 steps or the slabs 4 million.
Triangulation triangulateEvenOdd(const std::vector<std::vector<glm::dvec2>>& contours);

/// Total area of a triangulation (used by tests and to detect empty fills).
double triangulatedArea(const Triangulation& triangulation);

}  // namespace phigs::render
