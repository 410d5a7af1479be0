#include "phigs/hardcopy/FacetOrdering.h"

#include "phigs/hardcopy/FacetClusters.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

namespace phigs::hardcopy {
namespace {

enum class Side { On, Front, Back, Both };

/// A colour channel at the 8 bits of the raster (and of the painter's colours).
int channel8(float c) {
    return int(std::lround(std::clamp(double(c), 0.0, 1.0) * 255.0));
}

/// The BSP tree over facets in page space with depth scaled to points.
class Bsp {
public:
    Bsp(std::vector<ProjectedFacet> facets, double pointsPerDepth)
        : pool_(std::move(facets)), depthScale_(pointsPerDepth) {
        glm::dvec3 lo(1e300), hi(-1e300);
        for (const ProjectedFacet& f : pool_)
            for (const auto& c : f.contours)
                for (const PagePoint& p : c) lo = glm::min(lo, scaled(p)), hi = glm::max(hi, scaled(p));
        epsilon_ = 1e-9 * std::max(1.0, glm::length(hi - lo));
        for (const ProjectedFacet& f : pool_) planes_.push_back(planeOf(f));
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

    glm::dvec3 scaled(const PagePoint& p) const { return {p.x, p.y, p.z * depthScale_}; }

    glm::dvec4 planeOf(const ProjectedFacet& f) const {
        glm::dvec3 normal(0.0), centre(0.0);
        std::size_t count = 0;
        for (const auto& c : f.contours)
            for (std::size_t i = 0; i < c.size(); ++i) {
                const glm::dvec3 a = scaled(c[i]), b = scaled(c[(i + 1) % c.size()]);
                normal += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x),
                                     (a.x - b.x) * (a.y + b.y));
                centre += a;
                ++count;
            }
        const double length = glm::length(normal);
        if (length == 0.0 || count == 0) return glm::dvec4(0.0);
        normal /= length;
        centre /= double(count);
        return {normal, -glm::dot(normal, centre)};
    }

    double distance(const glm::dvec4& plane, const PagePoint& p) const {
        return glm::dot(glm::dvec3(plane), scaled(p)) + plane.w;
    }

    Side classify(const glm::dvec4& plane, const ProjectedFacet& f) const {
        bool front = false, back = false;
        for (const auto& c : f.contours)
            for (const PagePoint& p : c) {
                const double d = distance(plane, p);
                front = front || d > epsilon_;
                back = back || d < -epsilon_;
                if (front && back) return Side::Both;
            }
        return front && back ? Side::Both : front ? Side::Front : back ? Side::Back : Side::On;
    }

    /// The facet's parts on the plane's front and back sides (each contour clipped both ways).
    std::pair<ProjectedFacet, ProjectedFacet> split(const glm::dvec4& plane, const ProjectedFacet& f) const {
        ProjectedFacet front = f, back = f;
        front.contours.clear(), back.contours.clear();
        front.seam = back.seam = true;
        for (const auto& c : f.contours) {
            std::vector<PagePoint> plus, minus;
            for (std::size_t i = 0; i < c.size(); ++i) {
                const PagePoint &a = c[i], &b = c[(i + 1) % c.size()];
                const double da = distance(plane, a), db = distance(plane, b);
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
                splits += classify(planes_[candidate], pool_[facets[s * n / samples]]) == Side::Both;
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
    double depthScale_;
    double epsilon_ = 0.0;
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
            const Side side = plane == glm::dvec4(0.0) || f == chosen ? Side::On : classify(plane, pool_[f]);
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

std::vector<ProjectedFacet> orderBackToFront(std::vector<ProjectedFacet> facets, double pointsPerDepth,
                                             FacetOrderStats* stats) {
    FacetOrderStats total;
    total.input = facets.size();
    std::vector<ProjectedFacet> out;
    const auto clusters = overlapClusters(facets);
    // A facet that overlaps no other may be painted at any time: these come first, by view and
    // colour, so that the painter can paint a run of one colour as one path (CairoPainter).
    std::vector<std::size_t> alone;
    for (const auto& cluster : clusters)
        if (cluster.size() == 1) alone.push_back(cluster[0]);
    std::stable_sort(alone.begin(), alone.end(), [&](std::size_t a, std::size_t b) {
        const ProjectedFacet &p = facets[a], &q = facets[b];
        const auto key = [](const ProjectedFacet& f) {
            return std::tuple(f.clip, channel8(f.colour.x), channel8(f.colour.y), channel8(f.colour.z));
        };
        return key(p) < key(q);
    });
    // The clusters' orders first, then one list of the size they make (splits add facets): a
    // growing list would hold its old and new room at once, the describe step's largest need.
    std::vector<std::vector<ProjectedFacet>> ordered;
    std::size_t count = alone.size();
    for (const auto& cluster : clusters) {
        if (cluster.size() == 1) continue;
        std::vector<ProjectedFacet> group;
        group.reserve(cluster.size());
        for (std::size_t i : cluster) group.push_back(std::move(facets[i]));
        Bsp bsp(std::move(group), pointsPerDepth);
        ordered.push_back(bsp.backToFront());
        count += ordered.back().size();
        ++total.clusters;
        total.splits += bsp.stats.splits;
        total.fellBack = total.fellBack || bsp.stats.fellBack;
    }
    out.reserve(count);
    for (std::size_t i : alone) out.push_back(std::move(facets[i]));
    facets = {};
    for (auto& group : ordered) {
        for (ProjectedFacet& f : group) out.push_back(std::move(f));
        group = {};
    }
    total.output = out.size();
    if (stats) *stats = total;
    return out;
}

}  // namespace phigs::hardcopy
