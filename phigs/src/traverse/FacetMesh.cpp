#include "FacetMesh.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <utility>

namespace phigs::detail {

namespace {

glm::vec3 unit(const glm::dvec3& n) {
    return glm::vec3(glm::length(n) > 0.0 ? glm::normalize(n) : n);
}

/// Shared points: what a primitive without facet data in use draws.
MeshData sharedMesh(const FacetMeshInput& in) {
    MeshData m;
    m.positions.reserve(in.points.size());
    for (const auto& p : in.points) m.positions.push_back(glm::vec3(p));
    for (const auto& n : in.vertexNormals) m.normals.push_back(unit(n));
    m.colours = in.vertexColours;
    m.triangles = in.triangles;
    return m;
}

}  // namespace

void setFacets(MeshData& mesh, const std::vector<std::uint32_t>& facetOf) {
    std::vector<std::uint32_t> ends;
    for (std::size_t t = 1; t <= facetOf.size(); ++t)
        if (t == facetOf.size() || facetOf[t] != facetOf[t - 1]) ends.push_back(std::uint32_t(t));
    mesh.facetEnds.clear();
    mesh.trianglesPerFacet = ends.empty() ? 1 : ends[0];
    for (std::size_t k = 0; k < ends.size(); ++k)
        if (ends[k] != (k + 1) * mesh.trianglesPerFacet) {
            mesh.facetEnds = std::move(ends);
            mesh.trianglesPerFacet = 1;
            return;
        }
}

MeshData facetMesh(const FacetMeshInput& in) {
    const bool facetColours = in.vertexColours.empty() && !in.facetColours.empty();
    const bool facetNormals = in.vertexNormals.empty() && !in.facetNormals.empty();
    if (!facetColours && !facetNormals) {
        MeshData m = sharedMesh(in);
        setFacets(m, in.facetOf);
        return m;
    }
    MeshData m;
    const std::size_t corners = in.triangles.size() / 3 * 3;
    m.positions.reserve(corners);
    // The facet's points so far and their vertices: a facet's triangles share their corners (its
    // data is alike at a point), so its diagonals are found by index (render::meshFacetEdges).
    std::vector<std::pair<std::uint32_t, std::uint32_t>> facetVertices;
    for (std::size_t t = 0; t < corners; t += 3) {
        const std::uint32_t f = in.facetOf[t / 3];
        if (t == 0 || f != in.facetOf[t / 3 - 1]) facetVertices.clear();
        std::uint32_t a = in.triangles[t], b = in.triangles[t + 1], c = in.triangles[t + 2];
        if (facetNormals) {
            const glm::dvec3 winding = glm::cross(in.points[b] - in.points[a], in.points[c] - in.points[a]);
            if (glm::dot(winding, in.facetNormals[f]) < 0.0) std::swap(b, c);
        }
        for (std::uint32_t i : {a, b, c}) {
            const auto shared = std::find_if(facetVertices.begin(), facetVertices.end(),
                                             [&](const auto& pv) { return pv.first == i; });
            if (shared != facetVertices.end()) {
                m.triangles.push_back(shared->second);
                continue;
            }
            facetVertices.push_back({i, static_cast<std::uint32_t>(m.positions.size())});
            m.triangles.push_back(static_cast<std::uint32_t>(m.positions.size()));
            m.positions.push_back(glm::vec3(in.points[i]));
            if (!in.vertexColours.empty()) m.colours.push_back(in.vertexColours[i]);
            if (facetColours) m.colours.push_back(in.facetColours[f]);
            if (!in.vertexNormals.empty()) m.normals.push_back(unit(in.vertexNormals[i]));
            if (facetNormals) m.normals.push_back(unit(in.facetNormals[f]));
        }
    }
    m.normalsPerFacet = facetNormals;
    setFacets(m, in.facetOf);
    return m;
}

FacetMeshInput stripTriangles(FacetMeshInput in) {
    for (std::uint32_t k = 0; k + 2 < in.points.size(); ++k) {
        if (k % 2 == 0)
            in.triangles.insert(in.triangles.end(), {k, k + 1, k + 2});
        else
            in.triangles.insert(in.triangles.end(), {k + 1, k, k + 2});
        in.facetOf.push_back(k);
    }
    return in;
}

FacetMeshInput gridTriangles(FacetMeshInput in, int rows, int columns) {
    auto at = [&](int r, int c) { return static_cast<std::uint32_t>(r * columns + c); };
    for (int r = 0; r + 1 < rows; ++r)
        for (int c = 0; c + 1 < columns; ++c) {
            in.triangles.insert(in.triangles.end(), {at(r, c), at(r, c + 1), at(r + 1, c + 1)});
            in.triangles.insert(in.triangles.end(), {at(r, c), at(r + 1, c + 1), at(r + 1, c)});
            const auto facet = static_cast<std::uint32_t>(r * (columns - 1) + c);
            in.facetOf.insert(in.facetOf.end(), {facet, facet});
        }
    return in;
}

}  // namespace phigs::detail
