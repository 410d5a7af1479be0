#pragma once

// Edge sets of a triangle mesh for line drawings of it: the raster's mesh edges, the patch
// boundaries and silhouettes of a hidden-line drawing, and chains of edges as polylines.

#include "geom/Surface.h"
#include "phigs/traverse/DrawList.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace phigs::hardcopy {

using MeshEdge = std::pair<std::uint32_t, std::uint32_t>;

/// The facets' edges (render::meshFacetEdges: no diagonals) of the triangles showing `side`
/// (`facing[t]` as in silhouetteEdges, edge on showing the front; side 0: of every triangle),
/// each once: what the raster draws for a mesh's HOLLOW sides and its edges.
std::vector<MeshEdge> facetEdges(const MeshData& mesh, const std::vector<int>& facing = {}, int side = 0);

/// The patch boundaries: edges whose ends lie on the same knot line of `surface` (u or v at a
/// knot value, the domain ends included; needs the mesh's uv), and the mesh's border edges (used
/// by one triangle: the outline of a trimmed or hand-made mesh).
std::vector<MeshEdge> patchBoundaryEdges(const MeshData& mesh, const geom::Surface* surface);

/// The silhouette: edges between a triangle facing the viewer and one facing away
/// (`facing[t]` > 0 front, < 0 back, 0 unknown, per triangle).
std::vector<MeshEdge> silhouetteEdges(const MeshData& mesh, const std::vector<int>& facing);

/// Edges joined end to end into polylines of vertex indices (greedy walk; a closed loop repeats its
/// first vertex at the end).
std::vector<std::vector<std::uint32_t>> chainEdges(const std::vector<MeshEdge>& edges);

}  // namespace phigs::hardcopy
