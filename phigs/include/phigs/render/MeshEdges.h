#pragma once

// The edges of a mesh's facets and the side each of its triangles shows: what the renderers draw
// and the picker hits for a mesh's HOLLOW sides and edges.

#include "phigs/render/ItemGeometry.h"
#include "phigs/traverse/DrawList.h"

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace phigs::render {

/// Which edges of each triangle are edges of the primitive's facets (bit e: from corner e to corner
/// e + 1 mod 3): all but those another triangle of its facet shares (MeshData::facetEnds: a
/// quadrilateral's or grid cell's diagonal), matched by vertex index: a facet's triangles share
/// their corners' vertices, and a pole's distinct vertices at one position stay apart.
std::vector<std::uint8_t> meshFacetEdges(const MeshData& mesh);

/// Each triangle's facet edges as a line list in modelling coordinates (vertex data as
/// meshVertices), every vertex carrying its triangle's plane: the unit normal (b - a) x (c - a) as
/// `normal`, the offset -normal . a as `pattern`, for the side test against meshViewer.
std::vector<RenderVertex> meshSidedEdges(const MeshData& mesh);

/// The viewer of a mesh for the side test of its triangles: NPC's point at infinity toward +z
/// brought back to modelling coordinates, signed so that the plane (n, -n . a) of a triangle a, b,
/// c (n = (b - a) x (c - a)) is counter-clockwise in NPC exactly when dot(plane, viewer) > 0; a
/// mirroring transform turns the sign. The renderers, picker and hardcopy take >= 0 as the front:
/// an edge-on triangle shows its front. toNpc: the view's mapping times its orientation times the
/// item's modelling transform.
glm::dvec4 meshViewer(const glm::dmat4& toNpc);

/// The side of the triangle a, b, c (modelling coordinates) that `viewer` (meshViewer) sees: +1
/// its front (edge on or degenerate too), -1 its back.
int triangleSide(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec4& viewer);

}  // namespace phigs::render
