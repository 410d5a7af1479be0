#pragma once

#include "geom/Curve.h"
#include "geom/Surface.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace geom {

/// A triangle mesh of a surface: one position, unit normal and (u, v) per vertex, three vertex
/// indices per triangle, counter-clockwise seen from the side Su x Sv points to.
struct SurfaceMesh {
    std::vector<glm::dvec3> positions, normals;
    std::vector<glm::dvec2> uv;
    std::vector<std::uint32_t> triangles;
};

/// A (segmentsU + 1) x (segmentsV + 1) grid of vertices, evenly spaced in parameter; vertex
/// (i, j) is at index i * (segmentsV + 1) + j.
SurfaceMesh tessellateUniform(const Surface& surface, int segmentsU, int segmentsV);

/// A mesh whose distance from the surface stays within tolerance: a tensor grid each of whose
/// intervals between neighbouring parameter lines is halved while a cell over it misses, until
/// the surface point at every edge midpoint and triangle centroid lies within tolerance of the
/// mesh point at the same (u, v). Every parameter line runs through the whole surface, so
/// neighbouring Bézier pieces share their edge vertices and the mesh has no cracks or T-junctions.
/// Distances are measured with the net scaled by a power of two to unit size (exact), so the mesh
/// of a scaled surface is the scaled mesh, at any finite coordinates. A mesh that would need more
/// than 4,194,304 vertices (a tolerance too fine for the surface) is refused with GeometryError;
/// so is a polyline of tessellate past that many points.
SurfaceMesh tessellateAdaptive(const Surface& surface, double tolerance);

/// A polyline through the curve whose chords stay within tolerance of it, from the domain start
/// to its end: each Bézier piece is halved until every part's control points lie within tolerance
/// of its chord (the part lies in their convex hull, rational ones too). A tolerance below 16
/// units in the last place of the largest coordinate is refused. One polyline joins the ends of a
/// jump (a knot of multiplicity degree + 1): draw splitAtBreaks' pieces instead. Measured like
/// tessellateAdaptive, in coordinates scaled to unit size.
std::vector<glm::dvec3> tessellate(const Curve& curve, double tolerance);

}  // namespace geom
