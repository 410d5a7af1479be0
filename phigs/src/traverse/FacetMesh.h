#pragma once

// Private: triangle strips and quadrilateral meshes with facet data as draw meshes. Facet data is
// expanded to the facets' corners, so the renderers draw it through their vertex data.

#include "phigs/traverse/DrawList.h"

#include <cstdint>
#include <vector>

namespace phigs::detail {

/// A primitive's triangles over its points, with the data given for its vertices and facets
/// (colours already resolved to RGB). Each list is empty or complete.
struct FacetMeshInput {
    const std::vector<glm::dvec3>& points;
    const std::vector<glm::vec3>& vertexColours;   ///< one per point, or empty
    const std::vector<glm::dvec3>& vertexNormals;  ///< one per point, or empty
    const std::vector<glm::vec3>& facetColours;    ///< one per facet, or empty
    const std::vector<glm::dvec3>& facetNormals;   ///< one per facet, or empty
    std::vector<std::uint32_t> triangles;          ///< three point indices each
    std::vector<std::uint32_t> facetOf;            ///< the facet of each triangle
};

/// The mesh of `in` under the PHIGS PLUS precedence: vertex colours over facet colours over the
/// interior colour (mesh colours left empty), vertex normals over facet normals. When facet data
/// is used each facet gets corners of its own carrying it (flat per facet), and a triangle
/// whose winding disagrees with its facet normal is turned, so the facet normal decides its
/// front (lighting and culling). Without facet data in use the points are shared.
MeshData facetMesh(const FacetMeshInput& in);

/// Sets the mesh's facets (MeshData::trianglesPerFacet, facetEnds) from the facet of each of its
/// triangles, whose equal neighbours make one facet.
void setFacets(MeshData& mesh, const std::vector<std::uint32_t>& facetOf);

/// The triangles of a strip of `points` points: triangle k is k, k + 1, k + 2, every other one
/// turned so they all wind alike; facet k is triangle k.
FacetMeshInput stripTriangles(FacetMeshInput in);

/// The triangles of a rows x columns quadrilateral mesh (row by row): two per quadrilateral,
/// facet (r, c) is quadrilateral r * (columns - 1) + c.
FacetMeshInput gridTriangles(FacetMeshInput in, int rows, int columns);

}  // namespace phigs::detail
