#include "phigs/hardcopy/FacetOrdering.h"

#include "DepthSpace.h"
#include "FacetBsp.h"
#include "phigs/hardcopy/FacetOverlaps.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>

namespace phigs::hardcopy {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
constexpr std::size_t kPairsPerFacet = 64, kMinPairBudget = std::size_t(1) << 20;

/// Which of two facets that overlap on the page is painted first.
enum class First { A, B, Unknown };

/// A colour channel at the 8 bits of the raster (and of the painter's colours).
std::int64_t channelByte(float c) {
    return std::lround(std::clamp(double(c), 0.0, 1.0) * 255.0);
}

/// The view and the colour at 8 bits a channel: facets painted in a row with one key can be one
/// path (CairoPainter).
constexpr std::int64_t kColourBits = 0xFFFFFF;

std::int64_t paintKey(const ProjectedFacet& f) {
    return std::int64_t(f.clip) << 24 | channelByte(f.colour.x) << 16 | channelByte(f.colour.y) << 8 |
           channelByte(f.colour.z);
}

/// The plane with its normal toward the viewer, who looks down -z from z = +infinity.
glm::dvec4 facingViewer(const glm::dvec4& plane) {
    return plane.z < 0.0 ? -plane : plane;
}

/// The scaled depth of a plane facing the viewer over a page point.
double depthOn(const glm::dvec4& plane, glm::dvec2 p) {
    return -(plane.x * p.x + plane.y * p.y + plane.w) / plane.z;
}

/// Which of facets a and b, which overlap on the page, lies behind the other where they overlap.
/// First each facet's points against the other's plane (Newell's tests); where those do not
/// settle it, the depths of the two planes over the part of the page the hulls share, which
/// differ linearly, so their order at its corners is the order all over it. Facets that lie in
/// one plane there keep the traversal's order (a before b). Unknown: they pierce each other, or
/// one faces edge-on.
First paintedFirst(const DepthSpace& space, const ProjectedFacet& a, const ProjectedFacet& b,
                   const glm::dvec4& planeA, const glm::dvec4& planeB, const FacetOverlaps& overlaps,
                   std::uint32_t ia, std::uint32_t ib) {
    const glm::dvec4 pa = facingViewer(planeA), pb = facingViewer(planeB);
    // A plane nearly parallel to the view holds a depth range over a sliver of the page.
    constexpr double kEdgeOn = 1e-9;
    if (!(pa.z > kEdgeOn && pb.z > kEdgeOn)) return First::Unknown;
    const Side bOfA = space.classify(pa, b), aOfB = space.classify(pb, a);
    if (bOfA == Side::On && aOfB == Side::On) return First::A;
    const bool aNearer = bOfA == Side::Back || aOfB == Side::Front;
    const bool bNearer = aOfB == Side::Back || bOfA == Side::Front;
    if (aNearer != bNearer) return aNearer ? First::B : First::A;
    const std::vector<glm::dvec2> shared = convexIntersection(overlaps.hulls[ia], overlaps.hulls[ib]);
    if (shared.empty()) return First::A;  // they only touch after all
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (glm::dvec2 p : shared) {
        const double d = depthOn(pa, p) - depthOn(pb, p);
        lo = std::min(lo, d), hi = std::max(hi, d);
    }
    const double epsilon = space.epsilon();
    if (lo >= -epsilon && hi <= epsilon) return First::A;
    if (lo >= -epsilon) return First::B;
    if (hi <= epsilon) return First::A;
    return First::Unknown;
}

/// A directed graph in one array: the edges out of v are targets[offsets[v], offsets[v + 1]).
struct Graph {
    std::vector<std::uint32_t> offsets, targets;

    Graph(std::size_t vertices, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges)
        : offsets(vertices + 1, 0), targets(edges.size()) {
        for (const auto& e : edges) ++offsets[e.first + 1];
        for (std::size_t v = 1; v < offsets.size(); ++v) offsets[v] += offsets[v - 1];
        std::vector<std::uint32_t> fill(offsets.begin(), offsets.end() - 1);
        for (const auto& e : edges) targets[fill[e.first]++] = e.second;
    }
    std::size_t size() const { return offsets.size() - 1; }
};

/// The strongly connected components (Tarjan's algorithm, without recursion: a long chain of
/// facets each over the next would make it as deep as the chain): each vertex's component.
std::vector<std::uint32_t> components(const Graph& g, std::uint32_t& count) {
    const std::size_t n = g.size();
    std::vector<std::uint32_t> index(n, kNone), low(n, 0), component(n, kNone), stack;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> calls;  // vertex, next edge
    std::uint32_t next = 0;
    count = 0;
    auto open = [&](std::uint32_t v) {
        index[v] = low[v] = next++;
        stack.push_back(v);
        calls.emplace_back(v, g.offsets[v]);
    };
    for (std::uint32_t root = 0; root < n; ++root) {
        if (index[root] != kNone) continue;
        open(root);
        while (!calls.empty()) {
            const std::uint32_t v = calls.back().first;
            if (calls.back().second < g.offsets[v + 1]) {
                const std::uint32_t w = g.targets[calls.back().second++];
                if (index[w] == kNone)
                    open(w);
                else if (component[w] == kNone)  // still on the stack
                    low[v] = std::min(low[v], index[w]);
                continue;
            }
            calls.pop_back();
            if (!calls.empty()) low[calls.back().first] = std::min(low[calls.back().first], low[v]);
            if (low[v] != index[v]) continue;
            std::uint32_t w;
            do {
                w = stack.back();
                stack.pop_back();
                component[w] = count;
            } while (w != v);
            ++count;
        }
    }
    return component;
}

/// The edges between overlapping facets, from the one painted first to the other; both ways
/// where no whole-facet order is known, which puts the two in one component.
std::vector<std::pair<std::uint32_t, std::uint32_t>> paintingEdges(const std::vector<ProjectedFacet>& facets,
                                                                   const FacetOverlaps& overlaps,
                                                                   double pointsPerDepth) {
    const DepthSpace space(facets, pointsPerDepth);
    std::vector<glm::dvec4> planes;
    planes.reserve(facets.size());
    for (const ProjectedFacet& f : facets) planes.push_back(space.planeOf(f));
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    edges.reserve(overlaps.pairs.size());
    for (const auto& [a, b] : overlaps.pairs) {
        const First first = paintedFirst(space, facets[a], facets[b], planes[a], planes[b], overlaps, a, b);
        if (first != First::B) edges.emplace_back(a, b);
        if (first != First::A) edges.emplace_back(b, a);
    }
    return edges;
}

/// The facets by strongly connected component of their painting edges.
struct Components {
    std::vector<std::uint32_t> of;                      ///< each facet's component
    std::vector<std::vector<std::uint32_t>> members;    ///< each component's facets
    std::vector<std::vector<ProjectedFacet>> bspOrder;  ///< a component of several, its facets ordered
    std::vector<std::int64_t> keys;                     ///< each component's first facet's paintKey
    std::size_t output = 0;                             ///< the facets painted, pieces of splits included
};

/// The components of the painting edges; one of several facets (a cycle, or facets that pierce
/// each other) is ordered by a BSP tree, its facets moved there, and then paints in a row.
Components groupComponents(const Graph& graph, std::vector<ProjectedFacet>& facets, double pointsPerDepth,
                           FacetOrderStats& total) {
    Components c;
    std::uint32_t count = 0;
    c.of = components(graph, count);
    c.members.resize(count);
    for (std::uint32_t v = 0; v < facets.size(); ++v) c.members[c.of[v]].push_back(v);
    c.bspOrder.resize(count);
    c.keys.assign(count, 0);
    for (std::uint32_t k = 0; k < count; ++k) {
        if (c.members[k].size() == 1) {
            c.keys[k] = paintKey(facets[c.members[k].front()]);
            ++c.output;
            continue;
        }
        std::vector<ProjectedFacet> group;
        group.reserve(c.members[k].size());
        for (std::uint32_t v : c.members[k]) group.push_back(std::move(facets[v]));
        c.bspOrder[k] = bspBackToFront(std::move(group), pointsPerDepth, total);
        if (!c.bspOrder[k].empty()) c.keys[k] = paintKey(c.bspOrder[k].front());
        c.output += c.bspOrder[k].size();
        ++total.clusters;
    }
    return c;
}

/// The components in an order that keeps every edge (Kahn's algorithm): of those ready, one with
/// the last one's view and colour where there is one, else one of its view (a change of view is a
/// change of clip in the file), else the least. The facets move out of `facets` and the groups.
std::vector<ProjectedFacet> paintingOrder(const Graph& graph, Components& groups,
                                          std::vector<ProjectedFacet>& facets) {
    const std::size_t count = groups.members.size();
    std::vector<std::uint32_t> waiting(count, 0);
    for (std::uint32_t v = 0; v < graph.size(); ++v)
        for (std::uint32_t e = graph.offsets[v]; e < graph.offsets[v + 1]; ++e)
            if (groups.of[graph.targets[e]] != groups.of[v]) ++waiting[groups.of[graph.targets[e]]];
    std::map<std::int64_t, std::vector<std::uint32_t>> ready;
    for (std::uint32_t k = 0; k < count; ++k)
        if (waiting[k] == 0) ready[groups.keys[k]].push_back(k);
    std::vector<ProjectedFacet> out;
    out.reserve(groups.output);
    std::int64_t last = 0;
    while (!ready.empty()) {
        auto bucket = ready.find(last);
        if (bucket == ready.end()) bucket = ready.lower_bound(last & ~kColourBits);
        if (bucket == ready.end() || (bucket->first & ~kColourBits) != (last & ~kColourBits))
            bucket = ready.begin();
        last = bucket->first;
        const std::uint32_t k = bucket->second.back();
        bucket->second.pop_back();
        if (bucket->second.empty()) ready.erase(bucket);
        if (groups.members[k].size() == 1) {
            out.push_back(std::move(facets[groups.members[k].front()]));
        } else {
            for (ProjectedFacet& f : groups.bspOrder[k]) out.push_back(std::move(f));
            groups.bspOrder[k] = {};
        }
        for (std::uint32_t v : groups.members[k])
            for (std::uint32_t e = graph.offsets[v]; e < graph.offsets[v + 1]; ++e) {
                const std::uint32_t d = groups.of[graph.targets[e]];
                if (d != k && --waiting[d] == 0) ready[groups.keys[d]].push_back(d);
            }
    }
    return out;
}

}  // namespace

std::vector<ProjectedFacet> orderBackToFront(std::vector<ProjectedFacet> facets, double pointsPerDepth,
                                             FacetOrderStats* stats) {
    FacetOrderStats total;
    total.input = facets.size();
    // Facets that overlap by the hundred (a pile of large layers) would make the pairs outgrow
    // the facets many times over: past this bound one BSP tree orders them all.
    const std::size_t maxPairs = kPairsPerFacet * facets.size() + kMinPairBudget;
    FacetOverlaps overlaps;
    if (facets.size() < kNone) overlaps = facetOverlaps(facets, maxPairs);
    if (facets.size() >= kNone || !overlaps.complete) {
        ++total.clusters;
        std::vector<ProjectedFacet> out = bspBackToFront(std::move(facets), pointsPerDepth, total);
        total.output = out.size();
        if (stats) *stats = total;
        return out;
    }
    const Graph graph(facets.size(), paintingEdges(facets, overlaps, pointsPerDepth));
    overlaps = {};
    Components groups = groupComponents(graph, facets, pointsPerDepth, total);
    std::vector<ProjectedFacet> out = paintingOrder(graph, groups, facets);
    total.output = out.size();
    if (stats) *stats = total;
    return out;
}

}  // namespace phigs::hardcopy
