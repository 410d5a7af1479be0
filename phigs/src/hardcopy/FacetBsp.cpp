#include "FacetBsp.h"

#include "DepthSpace.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <utility>

namespace phigs::hardcopy {
namespace {

/// The BSP tree over facets in depth-scaled page space.
class Bsp {
public:
    Bsp(std::vector<ProjectedFacet> facets, double pointsPerDepth)
        : pool_(std::move(facets)), space_(pool_, pointsPerDepth) {
        for (const ProjectedFacet& f : pool_) planes_.push_back(space_.planeOf(f));
        budget_ = 8 * pool_.size() + 10000;
    }

    FacetOrderStats stats;

    std::vector<ProjectedFacet> backToFront() {
        stats.input = pool_.size();
        std::vector<std::size_t> all(pool_.size());
        for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
        if (!all.empty()) build(std::move(all));
        std::vector<ProjectedFacet> out;
        std::size_t count = 0;
        for (const Node& node : nodes_) count += node.on.size();
        out.reserve(count);
        walk(out);
        pool_ = {};
        stats.output = out.size();
        return out;
    }

private:
    struct Node {
        glm::dvec4 plane{0.0};
        std::vector<std::size_t> on;  ///< coplanar facets in traversal order (or the fallback's sorted list)
        int front = -1, back = -1;
    };

    /// The facet's parts on the plane's front and back sides (each contour clipped both ways).
    std::pair<ProjectedFacet, ProjectedFacet> split(const glm::dvec4& plane, const ProjectedFacet& f) const {
        ProjectedFacet front = f, back = f;
        front.contours.clear(), back.contours.clear();
        front.seam = back.seam = true;
        for (const auto& c : f.contours) {
            std::vector<PagePoint> plus, minus;
            for (std::size_t i = 0; i < c.size(); ++i) {
                const PagePoint &a = c[i], &b = c[(i + 1) % c.size()];
                const double da = space_.distance(plane, a), db = space_.distance(plane, b);
                if (da >= 0.0) plus.push_back(a);
                if (da <= 0.0) minus.push_back(a);
                if ((da > 0.0 && db < 0.0) || (da < 0.0 && db > 0.0)) {
                    const PagePoint cut = a + (b - a) * (da / (da - db));
                    plus.push_back(cut);
                    minus.push_back(cut);
                }
            }
            if (plus.size() >= 3) front.contours.push_back(std::move(plus));
            if (minus.size() >= 3) back.contours.push_back(std::move(minus));
        }
        return {std::move(front), std::move(back)};
    }

    /// The candidate (of a few spread over the list) whose plane splits the fewest of a sample.
    std::size_t choosePlane(const std::vector<std::size_t>& facets) const {
        const std::size_t n = facets.size(), candidates = std::min<std::size_t>(n, 16),
                          samples = std::min<std::size_t>(n, 64);
        std::size_t best = facets[0], fewest = ~std::size_t(0);
        for (std::size_t c = 0; c < candidates; ++c) {
            const std::size_t candidate = facets[c * n / candidates];
            if (planes_[candidate] == glm::dvec4(0.0)) continue;
            // Counting stops where this candidate can no longer be the first with the fewest, and
            // the search where one splits none: the choice is the full count's.
            std::size_t splits = 0;
            for (std::size_t s = 0; s < samples && splits < fewest; ++s)
                splits += space_.classify(planes_[candidate], pool_[facets[s * n / samples]]) == Side::Both;
            if (splits < fewest) fewest = splits, best = candidate;
            if (fewest == 0) break;
        }
        return best;
    }

    void build(std::vector<std::size_t> all);
    /// Moves the facets out of the pool, far to near: each is on one node only.
    void walk(std::vector<ProjectedFacet>& out);
    void sortByDepth(Node& node) const;

    std::vector<ProjectedFacet> pool_;
    std::vector<glm::dvec4> planes_;
    std::vector<Node> nodes_;
    DepthSpace space_;
    std::size_t budget_ = 0;
};

void Bsp::build(std::vector<std::size_t> all) {
    // Iterative: a mesh of parallel facets would make the tree as deep as the mesh is large.
    std::vector<std::pair<int, std::vector<std::size_t>>> work;
    nodes_.emplace_back();
    work.emplace_back(0, std::move(all));
    while (!work.empty()) {
        auto [index, facets] = std::move(work.back());
        work.pop_back();
        if (stats.splits >= budget_) {
            stats.fellBack = true;
            nodes_[std::size_t(index)].on = std::move(facets);
            sortByDepth(nodes_[std::size_t(index)]);
            continue;
        }
        const std::size_t chosen = choosePlane(facets);
        const glm::dvec4 plane = planes_[chosen];
        std::vector<std::size_t> on, front, back;
        for (std::size_t f : facets) {
            // The chosen facet stays at its node whatever rounding says of a sliver's own plane,
            // so every node takes at least one facet and the build ends.
            const Side side =
                plane == glm::dvec4(0.0) || f == chosen ? Side::On : space_.classify(plane, pool_[f]);
            if (side == Side::On) on.push_back(f);
            if (side == Side::Front) front.push_back(f);
            if (side == Side::Back) back.push_back(f);
            if (side != Side::Both) continue;
            auto [plus, minus] = split(plane, pool_[f]);
            ++stats.splits;
            for (auto* part : {&plus, &minus}) {
                if (part->contours.empty()) continue;
                pool_.push_back(std::move(*part));
                planes_.push_back(planes_[f]);
                (part == &plus ? front : back).push_back(pool_.size() - 1);
            }
        }
        nodes_[std::size_t(index)].plane = plane;
        nodes_[std::size_t(index)].on = std::move(on);
        for (auto* side : {&front, &back}) {
            if (side->empty()) continue;
            const int child = int(nodes_.size());
            nodes_.emplace_back();
            (side == &front ? nodes_[std::size_t(index)].front : nodes_[std::size_t(index)].back) = child;
            work.emplace_back(child, std::move(*side));
        }
    }
}

void Bsp::sortByDepth(Node& node) const {
    auto depth = [&](std::size_t f) {
        double sum = 0.0;
        std::size_t count = 0;
        for (const auto& c : pool_[f].contours)
            for (const PagePoint& p : c) sum += p.z, ++count;
        return count ? sum / double(count) : 0.0;
    };
    std::stable_sort(node.on.begin(), node.on.end(),
                     [&](std::size_t a, std::size_t b) { return depth(a) < depth(b); });
}

void Bsp::walk(std::vector<ProjectedFacet>& out) {
    if (nodes_.empty()) return;
    // The viewer looks down -z from z = +infinity: the side the plane's normal z points to is near.
    struct Step {
        int node;
        bool emit;
    };
    std::vector<Step> stack{{0, false}};
    while (!stack.empty()) {
        const Step step = stack.back();
        stack.pop_back();
        const Node& node = nodes_[std::size_t(step.node)];
        if (step.emit) {
            for (std::size_t f : node.on) out.push_back(std::move(pool_[f]));
            continue;
        }
        const bool frontIsNear = node.plane.z >= 0.0;
        const int nearChild = frontIsNear ? node.front : node.back,
                  farChild = frontIsNear ? node.back : node.front;
        if (nearChild >= 0) stack.push_back({nearChild, false});
        stack.push_back({step.node, true});
        if (farChild >= 0) stack.push_back({farChild, false});
    }
}

}  // namespace

std::vector<ProjectedFacet> bspBackToFront(std::vector<ProjectedFacet> facets, double pointsPerDepth,
                                           FacetOrderStats& stats) {
    Bsp bsp(std::move(facets), pointsPerDepth);
    std::vector<ProjectedFacet> out = bsp.backToFront();
    stats.splits += bsp.stats.splits;
    stats.fellBack = stats.fellBack || bsp.stats.fellBack;
    return out;
}

}  // namespace phigs::hardcopy
