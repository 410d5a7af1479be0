#include "geom/BezierSubdivision.h"

#include "Checked.h"

#include "geom/Bezier.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace geom {
namespace {

double largestSpacing(const std::vector<glm::dvec3>& net, std::size_t nu, std::size_t nv) {
    double m = 0.0;
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j) {
            if (i + 1 < nu) m = std::max(m, glm::length(net[(i + 1) * nv + j] - net[i * nv + j]));
            if (j + 1 < nv) m = std::max(m, glm::length(net[i * nv + j + 1] - net[i * nv + j]));
        }
    return m;
}

double lineDistance(const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& r) {
    const glm::dvec3 d = r - q, e = p - q;
    const double dd = glm::dot(d, d);
    if (!(dd > 0.0)) return glm::length(e);
    return std::sqrt(std::max(0.0, glm::dot(e, e) - glm::dot(d, e) * glm::dot(d, e) / dd));
}

bool locallyFlat(const std::vector<glm::dvec3>& net, std::size_t nu, std::size_t nv, double tol) {
    auto P = [&](std::size_t i, std::size_t j) -> const glm::dvec3& { return net[i * nv + j]; };
    const std::size_t m = nu - 1, n = nv - 1;
    const glm::dvec3 normal = glm::cross(P(m, 0) - P(0, 0), P(0, n) - P(0, 0));
    const double len = glm::length(normal);
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j) {
            // A degenerate corner triangle has no plane: fall back on the spacing of the net.
            const double d = len > 0.0 ? std::abs(glm::dot(normal, P(i, j) - P(0, 0))) / len
                                       : glm::length(P(i, j) - P(0, 0));
            if (d >= tol) return false;
        }
    for (std::size_t k = 0; k < nu; ++k)
        if (lineDistance(P(k, 0), P(0, 0), P(m, 0)) >= tol || lineDistance(P(k, n), P(m, n), P(0, n)) >= tol)
            return false;
    for (std::size_t j = 0; j < nv; ++j)
        if (lineDistance(P(0, j), P(0, 0), P(0, n)) >= tol || lineDistance(P(m, j), P(m, n), P(m, 0)) >= tol)
            return false;
    return true;
}

static_assert(sizeof(glm::dvec3) == 3 * sizeof(double), "rows of points are read as rows of doubles");

/// Midpoint split along u of a net of nu rows of nv points (u slow): de Casteljau on whole rows,
/// so each step is one pass over 3 nv contiguous doubles. `low` gets [0, 1/2], `high` [1/2, 1].
void halveU(const std::vector<glm::dvec3>& net, std::size_t nu, std::size_t nv, std::vector<glm::dvec3>& low,
            std::vector<glm::dvec3>& high, std::vector<glm::dvec3>& work) {
    work = net;
    low.resize(net.size());
    high.resize(net.size());
    const std::size_t width = 3 * nv, m = nu - 1;
    double* w = &work[0].x;
    std::copy_n(net.begin(), nv, low.begin());
    std::copy_n(net.begin() + static_cast<std::ptrdiff_t>(m * nv), nv,
                high.begin() + static_cast<std::ptrdiff_t>(m * nv));
    for (std::size_t k = 1; k <= m; ++k) {
        for (std::size_t i = 0; i + k <= m; ++i) {
            double* a = w + i * width;
            const double* b = a + width;
            for (std::size_t j = 0; j < width; ++j) a[j] = 0.5 * (a[j] + b[j]);
        }
        std::copy_n(work.begin(), nv, low.begin() + static_cast<std::ptrdiff_t>(k * nv));
        std::copy_n(work.begin() + static_cast<std::ptrdiff_t>((m - k) * nv), nv,
                    high.begin() + static_cast<std::ptrdiff_t>((m - k) * nv));
    }
}

/// Midpoint split along v: each row's nv points by de Casteljau.
void halveV(const std::vector<glm::dvec3>& net, std::size_t nu, std::size_t nv, std::vector<glm::dvec3>& low,
            std::vector<glm::dvec3>& high) {
    low = net;
    high.resize(net.size());
    const std::size_t n = nv - 1;
    for (std::size_t i = 0; i < nu; ++i) {
        glm::dvec3* row = &low[i * nv];
        glm::dvec3* right = &high[i * nv];
        right[n] = row[n];
        // In place: after step k, row[k..n] hold the k-th differences; row[k] is the low half's
        // k-th point once shifted, so keep the low half's points in front as they are made.
        for (std::size_t k = 1; k <= n; ++k) {
            for (std::size_t j = n; j >= k; --j) row[j] = 0.5 * (row[j - 1] + row[j]);
            right[n - k] = row[n];
        }
    }
}

struct Generator {
    std::size_t nu, nv;
    SubdivisionOptions options;
    int globalDepth = 0;
    SubdivisionStats stats;
    std::vector<SubdivisionLeaf> leaves;
    std::vector<glm::dvec3> work;

    bool stop(const SubdivisionLeaf& node) const {
        switch (options.rule) {
            case StoppingRule::FixedDepth:
                return node.depth >= options.depth;
            case StoppingRule::GlobalError:
                return node.depth >= globalDepth;
            case StoppingRule::MeshRefinement:
                return node.depth >= options.depth || largestSpacing(node.net, nu, nv) < options.tolerance;
            case StoppingRule::LocalFlatness:
                return node.depth >= options.depth || locallyFlat(node.net, nu, nv, options.tolerance);
            case StoppingRule::FlatnessOrRefinement:
                return node.depth >= options.depth || locallyFlat(node.net, nu, nv, options.tolerance) ||
                       largestSpacing(node.net, nu, nv) < options.tolerance;
        }
        return true;
    }

    void generate(SubdivisionLeaf node) {
        ++stats.gens;
        if (stop(node)) {
            leaves.push_back(std::move(node));
            return;
        }
        std::vector<glm::dvec3> low, high, q[4];
        halveU(node.net, nu, nv, low, high, work);
        halveV(low, nu, nv, q[0], q[2]);
        halveV(high, nu, nv, q[1], q[3]);
        stats.splits += 3;
        const double um = 0.5 * (node.u0 + node.u1), vm = 0.5 * (node.v0 + node.v1);
        const int d = node.depth + 1;
        generate({std::move(q[0]), node.u0, um, node.v0, vm, d});
        generate({std::move(q[1]), um, node.u1, node.v0, vm, d});
        generate({std::move(q[2]), node.u0, um, vm, node.v1, d});
        generate({std::move(q[3]), um, node.u1, vm, node.v1, d});
    }
};

/// Every leaf at one depth: the quadtree's leaves without its inner nodes. The u and v halvings
/// commute (tensor product), so each u interval is halved once (2^depth - 1 u splits, not one
/// per quadtree node), then each u strip along v. Leaves come in the quadtree's depth-first order.
std::vector<SubdivisionLeaf> uniformLeaves(const std::vector<glm::dvec3>& net, std::size_t nu, std::size_t nv,
                                           int depth) {
    std::vector<std::vector<glm::dvec3>> strips{net}, next;
    std::vector<glm::dvec3> work;
    for (int d = 0; d < depth; ++d) {
        next.assign(2 * strips.size(), {});
        for (std::size_t s = 0; s < strips.size(); ++s)
            halveU(strips[s], nu, nv, next[2 * s], next[2 * s + 1], work);
        strips.swap(next);
    }
    const std::size_t side = std::size_t{1} << depth;
    std::vector<SubdivisionLeaf> leaves(side * side);
    const double step = 1.0 / static_cast<double>(side);
    std::vector<std::vector<glm::dvec3>> pieces, halves;
    for (std::size_t iu = 0; iu < side; ++iu) {
        pieces.assign(1, std::move(strips[iu]));
        for (int d = 0; d < depth; ++d) {
            halves.assign(2 * pieces.size(), {});
            for (std::size_t s = 0; s < pieces.size(); ++s)
                halveV(pieces[s], nu, nv, halves[2 * s], halves[2 * s + 1]);
            pieces.swap(halves);
        }
        for (std::size_t iv = 0; iv < side; ++iv) {
            // Depth-first position: one quadrant digit (u bit + 2 v bit) per level, top first.
            std::size_t at = 0;
            for (int level = depth - 1; level >= 0; --level)
                at = 4 * at + ((iu >> level) & 1) + 2 * ((iv >> level) & 1);
            SubdivisionLeaf& leaf = leaves[at];
            leaf.net = std::move(pieces[iv]);
            leaf.u0 = static_cast<double>(iu) * step;
            leaf.u1 = static_cast<double>(iu + 1) * step;
            leaf.v0 = static_cast<double>(iv) * step;
            leaf.v1 = static_cast<double>(iv + 1) * step;
            leaf.depth = depth;
        }
    }
    return leaves;
}

}  // namespace

std::vector<SubdivisionLeaf> subdivideAdaptive(std::span<const glm::dvec3> net, std::size_t countU,
                                               std::size_t countV, const SubdivisionOptions& options,
                                               SubdivisionStats* stats) {
    if (countU < 2 || countV < 2 || !detail::gridSizeIs(net.size(), countU, countV))
        throw GeometryError("subdivideAdaptive: a " + std::to_string(countU) + " x " +
                            std::to_string(countV) +
                            " net needs at least 2 x 2 points and countU * countV of them, " +
                            std::to_string(net.size()) + " given");
    // A NaN fails every flatness test and so passes as flat: the net would come back as a leaf.
    for (std::size_t i = 0; i < net.size(); ++i)
        if (!detail::finite(net[i]))
            throw GeometryError("subdivideAdaptive: net point " + std::to_string(i) +
                                " has a non-finite coordinate");
    if (options.depth < 0 || options.depth > 16)
        throw GeometryError("subdivideAdaptive: depth " + std::to_string(options.depth) +
                            " is outside 0..16");
    if (options.rule != StoppingRule::FixedDepth &&
        (!std::isfinite(options.tolerance) || !(options.tolerance > 0)))
        throw GeometryError("subdivideAdaptive: tolerance must be positive");
    Generator g{countU, countV, options, 0, {}, {}, {}};
    SubdivisionLeaf root;
    root.net.assign(net.begin(), net.end());
    if (options.rule == StoppingRule::GlobalError) {
        const double m = largestSpacing(root.net, countU, countV);
        // The thesis stops with an error when the formula gives no subdivision; depth 0 here.
        g.globalDepth =
            m > options.tolerance
                ? std::min(options.depth, static_cast<int>(std::ceil(std::log2(m / options.tolerance))))
                : 0;
    }
    const int uniform = options.rule == StoppingRule::FixedDepth    ? options.depth
                        : options.rule == StoppingRule::GlobalError ? g.globalDepth
                                                                    : -1;
    if (uniform >= 0) {
        g.leaves = uniformLeaves(root.net, countU, countV, uniform);
        // The quadtree the recursion walks: (4^d - 1) / 3 inner nodes.
        const std::size_t inner = (g.leaves.size() - 1) / 3;
        g.stats.splits = 3 * inner;
        g.stats.gens = 1 + 4 * inner;
    } else {
        g.generate(std::move(root));
    }
    g.stats.leaves = g.leaves.size();
    g.stats.points = g.leaves.size() * countU * countV;
    g.stats.minDepth = g.leaves.front().depth;
    g.stats.maxDepth = g.leaves.front().depth;
    for (const SubdivisionLeaf& l : g.leaves) {
        g.stats.minDepth = std::min(g.stats.minDepth, l.depth);
        g.stats.maxDepth = std::max(g.stats.maxDepth, l.depth);
    }
    if (stats) *stats = g.stats;
    return std::move(g.leaves);
}

}  // namespace geom
