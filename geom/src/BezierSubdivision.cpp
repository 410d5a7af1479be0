#include "geom/BezierSubdivision.h"

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

struct Generator {
    std::size_t nu, nv;
    SubdivisionOptions options;
    int globalDepth = 0;
    SubdivisionStats stats;
    std::vector<SubdivisionLeaf> leaves;

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
        subdivideBezierNet<glm::dvec3>(node.net, nu, nv, 0.5, false, low, high);
        subdivideBezierNet<glm::dvec3>(low, nu, nv, 0.5, true, q[0], q[2]);
        subdivideBezierNet<glm::dvec3>(high, nu, nv, 0.5, true, q[1], q[3]);
        stats.splits += 3;
        const double um = 0.5 * (node.u0 + node.u1), vm = 0.5 * (node.v0 + node.v1);
        const int d = node.depth + 1;
        generate({std::move(q[0]), node.u0, um, node.v0, vm, d});
        generate({std::move(q[1]), um, node.u1, node.v0, vm, d});
        generate({std::move(q[2]), node.u0, um, vm, node.v1, d});
        generate({std::move(q[3]), um, node.u1, vm, node.v1, d});
    }
};

}  // namespace

std::vector<SubdivisionLeaf> subdivideAdaptive(std::span<const glm::dvec3> net, std::size_t countU,
                                               std::size_t countV, const SubdivisionOptions& options,
                                               SubdivisionStats* stats) {
    if (countU < 2 || countV < 2 || net.size() != countU * countV)
        throw GeometryError("subdivideAdaptive: a " + std::to_string(countU) + " x " +
                            std::to_string(countV) + " net needs at least 2 x 2 points and " +
                            std::to_string(countU * countV) + " points, " + std::to_string(net.size()) +
                            " given");
    if (options.depth < 0 || options.depth > 16)
        throw GeometryError("subdivideAdaptive: depth " + std::to_string(options.depth) +
                            " is outside 0..16");
    if (options.rule != StoppingRule::FixedDepth &&
        (!std::isfinite(options.tolerance) || !(options.tolerance > 0)))
        throw GeometryError("subdivideAdaptive: tolerance must be positive");
    Generator g{countU, countV, options, 0, {}, {}};
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
    g.generate(std::move(root));
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
