#include "phigs/hardcopy/MeshOutline.h"

#include "phigs/render/MeshEdges.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

namespace phigs::hardcopy {
namespace {

std::uint64_t undirectedEdgeKey(std::uint32_t a, std::uint32_t b) {
    if (a > b) std::swap(a, b);
    return (std::uint64_t(a) << 32) | b;
}

/// For each edge (smaller index first), the triangles that use it, in order of first use.
std::vector<std::pair<MeshEdge, std::vector<std::uint32_t>>> edgeTriangles(const MeshData& mesh) {
    std::unordered_map<std::uint64_t, std::size_t> index;
    std::vector<std::pair<MeshEdge, std::vector<std::uint32_t>>> edges;
    const auto count = std::uint32_t(mesh.positions.size());
    for (std::size_t t = 0; t + 2 < mesh.triangles.size(); t += 3)
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = mesh.triangles[t + e], b = mesh.triangles[t + (e + 1) % 3];
            if (a >= count || b >= count || a == b) continue;
            auto [it, added] = index.emplace(undirectedEdgeKey(a, b), edges.size());
            if (added) edges.push_back({{std::min(a, b), std::max(a, b)}, {}});
            edges[it->second].second.push_back(std::uint32_t(t / 3));
        }
    return edges;
}

/// Distinct knot values of a direction within its domain, ends included.
std::vector<double> knotLines(const std::vector<double>& knots, double start, double end) {
    std::vector<double> lines;
    for (double k : knots)
        if (k >= start && k <= end && (lines.empty() || k > lines.back())) lines.push_back(k);
    return lines;
}

bool onLine(const std::vector<double>& lines, double a, double b, double tolerance) {
    for (double k : lines)
        if (std::abs(a - k) <= tolerance && std::abs(b - k) <= tolerance) return true;
    return false;
}

}  // namespace

std::vector<MeshEdge> facetEdges(const MeshData& mesh, const std::vector<int>& facing, int side) {
    const std::vector<std::uint8_t> masks = render::meshFacetEdges(mesh);
    const auto count = std::uint32_t(mesh.positions.size());
    std::unordered_set<std::uint64_t> seen;
    std::vector<MeshEdge> out;
    for (std::size_t t = 0; t < masks.size(); ++t) {
        // Edge on (facing 0) shows the front, as the raster and the picker take it.
        if (side != 0 && ((t < facing.size() ? facing[t] : 0) >= 0 ? 1 : -1) != side) continue;
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = mesh.triangles[3 * t + e], b = mesh.triangles[3 * t + (e + 1) % 3];
            if ((masks[t] >> e & 1) && a < count && b < count && a != b &&
                seen.insert(undirectedEdgeKey(a, b)).second)
                out.push_back({std::min(a, b), std::max(a, b)});
        }
    }
    return out;
}

std::vector<MeshEdge> patchBoundaryEdges(const MeshData& mesh, const geom::Surface* surface) {
    const bool haveUv = surface && mesh.uv.size() == mesh.positions.size();
    std::vector<double> us, vs;
    double toleranceU = 0.0, toleranceV = 0.0;
    if (haveUv) {
        us = knotLines(surface->knotsU, surface->domainStartU(), surface->domainEndU());
        vs = knotLines(surface->knotsV, surface->domainStartV(), surface->domainEndV());
        // uv arrive as floats: a knot line matches within float precision of the domain.
        toleranceU = 1e-5 * std::max(1.0, surface->domainEndU() - surface->domainStartU());
        toleranceV = 1e-5 * std::max(1.0, surface->domainEndV() - surface->domainStartV());
    }
    std::vector<MeshEdge> out;
    for (const auto& [edge, triangles] : edgeTriangles(mesh)) {
        bool boundary = triangles.size() == 1;
        if (!boundary && haveUv) {
            const glm::vec2 a = mesh.uv[edge.first], b = mesh.uv[edge.second];
            boundary = onLine(us, a.x, b.x, toleranceU) || onLine(vs, a.y, b.y, toleranceV);
        }
        if (boundary) out.push_back(edge);
    }
    return out;
}

std::vector<MeshEdge> silhouetteEdges(const MeshData& mesh, const std::vector<int>& facing) {
    std::vector<MeshEdge> out;
    for (const auto& [edge, triangles] : edgeTriangles(mesh)) {
        bool front = false, back = false;
        for (std::uint32_t t : triangles) {
            const int f = t < facing.size() ? facing[t] : 0;
            front = front || f > 0;
            back = back || f < 0;
        }
        if (front && back) out.push_back(edge);
    }
    return out;
}

std::vector<std::vector<std::uint32_t>> chainEdges(const std::vector<MeshEdge>& edges) {
    std::unordered_map<std::uint32_t, std::vector<std::size_t>> at;
    for (std::size_t i = 0; i < edges.size(); ++i) {
        at[edges[i].first].push_back(i);
        at[edges[i].second].push_back(i);
    }
    std::vector<bool> used(edges.size(), false);
    auto nextFrom = [&](std::uint32_t vertex) -> std::ptrdiff_t {
        for (std::size_t e : at[vertex])
            if (!used[e]) return std::ptrdiff_t(e);
        return -1;
    };
    std::vector<std::vector<std::uint32_t>> chains;
    for (std::size_t i = 0; i < edges.size(); ++i) {
        if (used[i]) continue;
        used[i] = true;
        std::vector<std::uint32_t> chain{edges[i].first, edges[i].second};
        // Forward from the end, then backward from the start (reversed in place afterwards).
        for (int pass = 0; pass < 2; ++pass) {
            for (std::ptrdiff_t e = nextFrom(chain.back()); e >= 0; e = nextFrom(chain.back())) {
                used[std::size_t(e)] = true;
                const MeshEdge& edge = edges[std::size_t(e)];
                chain.push_back(edge.first == chain.back() ? edge.second : edge.first);
            }
            std::reverse(chain.begin(), chain.end());
        }
        chains.push_back(std::move(chain));
    }
    return chains;
}

}  // namespace phigs::hardcopy
