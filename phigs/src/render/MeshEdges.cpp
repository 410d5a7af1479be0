#include "phigs/render/MeshEdges.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>

namespace phigs::render {

std::vector<std::uint8_t> meshFacetEdges(const MeshData& mesh) {
    const std::size_t triangles = mesh.triangles.size() / 3;
    std::vector<std::uint8_t> masks(triangles, 7);
    auto corner = [&](std::size_t t, int k) { return mesh.triangles[3 * t + std::size_t(k % 3)]; };
    auto shares = [&](std::size_t t, int e, std::size_t u) {
        const std::uint32_t a = corner(t, e), b = corner(t, e + 1);
        for (int f = 0; f < 3; ++f) {
            const std::uint32_t c = corner(u, f), d = corner(u, f + 1);
            if ((a == c && b == d) || (a == d && b == c)) return true;
        }
        return false;
    };
    const std::size_t size = std::max<std::size_t>(mesh.trianglesPerFacet, 1);
    for (std::size_t first = 0, k = 0; first < triangles; ++k) {
        std::size_t end = mesh.facetEnds.empty()      ? first + size
                          : k < mesh.facetEnds.size() ? std::size_t(mesh.facetEnds[k])
                                                      : first + 1;
        end = std::clamp(end, first + 1, triangles);
        for (std::size_t t = first; t < end; ++t)
            for (std::size_t u = first; u < end; ++u)
                for (int e = 0; u != t && e < 3; ++e)
                    if (shares(t, e, u)) masks[t] &= std::uint8_t(~(1u << e));
        first = end;
    }
    return masks;
}

std::vector<RenderVertex> meshSidedEdges(const MeshData& mesh) {
    const std::vector<std::uint8_t> masks = meshFacetEdges(mesh);
    const std::size_t count = mesh.positions.size();
    std::vector<RenderVertex> v;
    for (std::size_t t = 0; t < masks.size(); ++t) {
        const std::uint32_t* corner = &mesh.triangles[3 * t];
        auto at = [&](int k) {
            RenderVertex r;
            const std::uint32_t i = corner[k];
            if (i >= count) return r;
            r.position = mesh.positions[i];
            if (i < mesh.colours.size()) r.colour = mesh.colours[i];
            return r;
        };
        const RenderVertex corners[3] = {at(0), at(1), at(2)};
        const glm::dvec3 a(corners[0].position), b(corners[1].position), c(corners[2].position);
        glm::dvec3 n = glm::cross(b - a, c - a);
        if (glm::length(n) > 0.0) n = glm::normalize(n);
        for (int e = 0; e < 3; ++e) {
            if (!(masks[t] >> e & 1)) continue;
            for (const int k : {e, (e + 1) % 3}) {
                RenderVertex r = corners[k];
                r.normal = glm::vec3(n);
                r.pattern = float(-glm::dot(n, a));
                v.push_back(r);
            }
        }
    }
    return v;
}

glm::dvec4 meshViewer(const glm::dmat4& toNpc) {
    // The NPC winding of a, b, c is det(x, y, w rows of toNpc (a, b, c)) / (wa wb wc), which is
    // det(toNpc) times the plane through them at toNpc^-1 (0, 0, 1, 0).
    const double det = glm::determinant(toNpc);
    return glm::inverse(toNpc) * glm::dvec4(0, 0, det < 0.0 ? -1.0 : 1.0, 0);
}

int triangleSide(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec4& viewer) {
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double s = glm::dot(n, glm::dvec3(viewer)) - viewer.w * glm::dot(n, a);
    return s >= 0.0 ? 1 : -1;
}

}  // namespace phigs::render
