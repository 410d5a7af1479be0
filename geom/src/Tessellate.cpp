#include "geom/Tessellate.h"

#include "geom/BezierPatchTree.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace geom {
namespace {

constexpr std::size_t kMaxVertices = 1u << 22;

void checkTolerance(double tolerance, const char* where) {
    if (!std::isfinite(tolerance) || !(tolerance > 0.0))
        throw GeometryError(std::string(where) + ": tolerance " + std::to_string(tolerance) +
                            " must be a positive number");
}

/// Grid mesh over the parameter lines us x vs, evaluated through the patch tree.
SurfaceMesh gridMesh(const Surface& surface, const BezierPatchTree& tree, const std::vector<double>& us,
                     const std::vector<double>& vs) {
    SurfaceMesh mesh;
    const std::size_t nu = us.size(), nv = vs.size();
    mesh.positions.reserve(nu * nv);
    mesh.normals.reserve(nu * nv);
    mesh.uv.reserve(nu * nv);
    for (double u : us)
        for (double v : vs) {
            const BezierPatchTree::PatchPoint e = tree.evaluate(u, v, 1);
            mesh.positions.push_back(e.point);
            mesh.normals.push_back(normalFromDerivatives(surface, u, v, e.su, e.sv));
            mesh.uv.emplace_back(u, v);
        }
    mesh.triangles.reserve((nu - 1) * (nv - 1) * 6);
    for (std::size_t i = 0; i + 1 < nu; ++i)
        for (std::size_t j = 0; j + 1 < nv; ++j) {
            const auto a = static_cast<std::uint32_t>(i * nv + j);
            const auto b = static_cast<std::uint32_t>((i + 1) * nv + j);
            const auto c = static_cast<std::uint32_t>((i + 1) * nv + j + 1);
            const auto d = static_cast<std::uint32_t>(i * nv + j + 1);
            mesh.triangles.insert(mesh.triangles.end(), {a, b, c, a, c, d});
        }
    return mesh;
}

std::vector<double> evenly(double a, double b, int segments) {
    std::vector<double> x(static_cast<std::size_t>(segments) + 1);
    for (int i = 0; i <= segments; ++i) x[static_cast<std::size_t>(i)] = a + (b - a) * i / segments;
    x.back() = b;
    return x;
}

/// Parameter lines from per-interval segment counts over the breakpoints.
std::vector<double> lines(const std::vector<double>& breaks, const std::vector<int>& counts) {
    std::vector<double> x;
    for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
        const std::vector<double> part = evenly(breaks[k], breaks[k + 1], counts[k]);
        x.insert(x.end(), part.begin() + (k == 0 ? 0 : 1), part.end());
    }
    return x;
}

}  // namespace

SurfaceMesh tessellateUniform(const Surface& surface, int segmentsU, int segmentsV) {
    validate(surface, "tessellateUniform");
    if (segmentsU < 1 || segmentsV < 1)
        throw GeometryError("tessellateUniform: segment counts " + std::to_string(segmentsU) + " x " +
                            std::to_string(segmentsV) + " must both be at least 1");
    if ((static_cast<double>(segmentsU) + 1.0) * (static_cast<double>(segmentsV) + 1.0) >
        static_cast<double>(kMaxVertices))
        throw GeometryError("tessellateUniform: " + std::to_string(segmentsU) + " x " +
                            std::to_string(segmentsV) + " segments are too many");
    const BezierPatchTree tree(surface);
    return gridMesh(surface, tree, evenly(surface.domainStartU(), surface.domainEndU(), segmentsU),
                    evenly(surface.domainStartV(), surface.domainEndV(), segmentsV));
}

SurfaceMesh tessellateAdaptive(const Surface& surface, double tolerance) {
    checkTolerance(tolerance, "tessellateAdaptive");
    validate(surface, "tessellateAdaptive");
    const BezierPatchTree tree(surface);
    const std::vector<double>& breaksU = tree.breaksU();
    const std::vector<double>& breaksV = tree.breaksV();
    // Start from the degree (a degree-p span needs about p chords to show its shape at all).
    std::vector<int> countsU(breaksU.size() - 1, std::max(1, std::min(surface.degreeU, 8)));
    std::vector<int> countsV(breaksV.size() - 1, std::max(1, std::min(surface.degreeV, 8)));
    if (surface.degreeU == 1) std::fill(countsU.begin(), countsU.end(), 1);
    if (surface.degreeV == 1) std::fill(countsV.begin(), countsV.end(), 1);

    for (int round = 0; round < 40; ++round) {
        const std::vector<double> us = lines(breaksU, countsU);
        const std::vector<double> vs = lines(breaksV, countsV);
        if (us.size() * vs.size() > kMaxVertices)
            throw GeometryError("tessellateAdaptive: tolerance " + std::to_string(tolerance) +
                                " needs more than " + std::to_string(kMaxVertices) + " vertices");
        const std::size_t nv = vs.size();
        std::vector<glm::dvec3> grid(us.size() * nv);
        for (std::size_t i = 0; i < us.size(); ++i)
            for (std::size_t j = 0; j < nv; ++j) grid[i * nv + j] = tree.evaluate(us[i], vs[j], 0).point;
        // Which intervals of which span need splitting, measured at edge midpoints and centres.
        std::vector<char> splitU(us.size() - 1, 0), splitV(nv - 1, 0);
        bool any = false;
        for (std::size_t i = 0; i + 1 < us.size(); ++i)
            for (std::size_t j = 0; j + 1 < nv; ++j) {
                const double um = 0.5 * (us[i] + us[i + 1]), vm = 0.5 * (vs[j] + vs[j + 1]);
                const glm::dvec3& p00 = grid[i * nv + j];
                const glm::dvec3& p10 = grid[(i + 1) * nv + j];
                const glm::dvec3& p11 = grid[(i + 1) * nv + j + 1];
                const glm::dvec3& p01 = grid[i * nv + j + 1];
                const double errU = glm::length(tree.evaluate(um, vs[j], 0).point - 0.5 * (p00 + p10));
                const double errV = glm::length(tree.evaluate(us[i], vm, 0).point - 0.5 * (p00 + p01));
                const double errD = glm::length(tree.evaluate(um, vm, 0).point - 0.5 * (p00 + p11));
                // The far edges belong to the neighbouring cells, except on the domain's border.
                double errU2 = 0.0, errV2 = 0.0;
                if (j + 2 == nv)
                    errU2 = glm::length(tree.evaluate(um, vs[j + 1], 0).point - 0.5 * (p01 + p11));
                if (i + 2 == us.size())
                    errV2 = glm::length(tree.evaluate(us[i + 1], vm, 0).point - 0.5 * (p10 + p11));
                const double eu = std::max(errU, errU2), ev = std::max(errV, errV2);
                if (eu > tolerance) splitU[i] = 1;
                if (ev > tolerance) splitV[j] = 1;
                if (errD > tolerance && eu <= tolerance && ev <= tolerance) splitU[i] = splitV[j] = 1;
                any = any || eu > tolerance || ev > tolerance || errD > tolerance;
            }
        if (!any) return gridMesh(surface, tree, us, vs);
        // Double the count of every span holding an interval that failed.
        auto grow = [](const std::vector<double>& breaks, const std::vector<double>& x,
                       const std::vector<char>& split, std::vector<int>& counts) {
            std::vector<char> spanFailed(counts.size(), 0);
            for (std::size_t k = 0; k < split.size(); ++k) {
                if (!split[k]) continue;
                const double mid = 0.5 * (x[k] + x[k + 1]);
                const auto span = static_cast<std::size_t>(
                                      std::upper_bound(breaks.begin(), breaks.end(), mid) - breaks.begin()) -
                                  1;
                spanFailed[std::min(span, counts.size() - 1)] = 1;
            }
            for (std::size_t k = 0; k < counts.size(); ++k)
                if (spanFailed[k]) counts[k] *= 2;
        };
        grow(breaksU, us, splitU, countsU);
        grow(breaksV, vs, splitV, countsV);
    }
    throw GeometryError("tessellateAdaptive: tolerance " + std::to_string(tolerance) +
                        " was not reached after 40 refinements");
}

std::vector<glm::dvec3> tessellate(const Curve& curve, double tolerance) {
    checkTolerance(tolerance, "tessellate");
    validate(curve, "tessellate");
    auto segmentDistance = [](const glm::dvec3& x, const glm::dvec3& a, const glm::dvec3& b) {
        const glm::dvec3 ab = b - a;
        const double len2 = glm::dot(ab, ab);
        const double s = len2 > 0.0 ? std::clamp(glm::dot(x - a, ab) / len2, 0.0, 1.0) : 0.0;
        return glm::length(x - (a + s * ab));
    };
    // Knot values are always vertices (corners of C0 curves stay sharp); each span starts with
    // degree chords and bisects any chord whose quarter points lie farther than tolerance.
    std::vector<double> breaks;
    for (std::size_t k = static_cast<std::size_t>(curve.degree); k <= curve.points.size(); ++k)
        if (breaks.empty() || curve.knots[k] > breaks.back()) breaks.push_back(curve.knots[k]);
    std::vector<glm::dvec3> out{evaluate(curve, breaks.front())};
    struct Piece {
        double a, b;
        glm::dvec3 pa, pb;
        int depth;
    };
    std::vector<Piece> stack;
    for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
        const int n = std::max(1, std::min(curve.degree, 16));
        for (int i = n - 1; i >= 0; --i) {
            const double a = breaks[k] + (breaks[k + 1] - breaks[k]) * i / n;
            const double b =
                i + 1 == n ? breaks[k + 1] : breaks[k] + (breaks[k + 1] - breaks[k]) * (i + 1) / n;
            stack.push_back({a, b, evaluate(curve, a), evaluate(curve, b), 0});
        }
        while (!stack.empty()) {
            const Piece piece = stack.back();
            stack.pop_back();
            double err = 0.0;
            if (curve.degree > 1)
                for (double f : {0.25, 0.5, 0.75})
                    err = std::max(err, segmentDistance(evaluate(curve, piece.a + f * (piece.b - piece.a)),
                                                        piece.pa, piece.pb));
            if (err > tolerance && piece.depth < 30) {
                const double m = 0.5 * (piece.a + piece.b);
                const glm::dvec3 pm = evaluate(curve, m);
                stack.push_back({m, piece.b, pm, piece.pb, piece.depth + 1});
                stack.push_back({piece.a, m, piece.pa, pm, piece.depth + 1});
                continue;
            }
            out.push_back(piece.pb);
            if (out.size() > kMaxVertices)
                throw GeometryError("tessellate: tolerance " + std::to_string(tolerance) +
                                    " needs too many points");
        }
    }
    return out;
}

}  // namespace geom
