#include "geom/Tessellate.h"
#include "NumberText.h"
#include "SegmentDistance.h"

#include "geom/Bezier.h"
#include "geom/BezierExtraction.h"
#include "geom/BezierPatchTree.h"
#include "geom/ControlNet.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>

namespace geom {
namespace {

constexpr std::size_t kMaxVertices = 1u << 22;

void checkTolerance(double tolerance, const char* where) {
    if (!std::isfinite(tolerance) || !(tolerance > 0.0))
        throw GeometryError(std::string(where) + ": tolerance " + detail::numberText(tolerance) +
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
            throw GeometryError("tessellateAdaptive: tolerance " + detail::numberText(tolerance) +
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
    throw GeometryError("tessellateAdaptive: tolerance " + detail::numberText(tolerance) +
                        " was not reached after 40 refinements");
}

namespace {

using detail::segmentDistance;

/// The largest distance of a Bézier piece's control points (homogeneous, positive weights) from
/// the chord between its end points: with positive weights the piece lies in the convex hull of
/// its control points, and the distance to a segment is convex, so the piece lies within this
/// distance of its chord.
double hullDistance(std::span<const glm::dvec4> piece) {
    const glm::dvec3 a = glm::dvec3(piece.front()) / piece.front().w;
    const glm::dvec3 b = glm::dvec3(piece.back()) / piece.back().w;
    double farthest = 0.0;
    for (std::size_t i = 1; i + 1 < piece.size(); ++i)
        farthest = std::max(farthest, segmentDistance(glm::dvec3(piece[i]) / piece[i].w, a, b));
    return farthest;
}

/// Appends the far ends of the chords of one Bézier piece: halved (de Casteljau) until each
/// part's control points lie within tolerance of its chord.
void tessellatePiece(std::vector<glm::dvec4> piece, double tolerance, std::vector<glm::dvec3>& out) {
    const std::size_t n = piece.size();
    std::vector<std::vector<glm::dvec4>> stack;
    stack.push_back(std::move(piece));
    std::vector<glm::dvec4> left(n), right(n);
    while (!stack.empty()) {
        std::vector<glm::dvec4> part = std::move(stack.back());
        stack.pop_back();
        if (hullDistance(part) > tolerance && stack.size() < 60) {
            subdivideBezier<glm::dvec4>(part, 0.5, left, right);
            stack.push_back(right);
            stack.push_back(left);
            continue;
        }
        out.push_back(glm::dvec3(part.back()) / part.back().w);
        if (out.size() > kMaxVertices)
            throw GeometryError("tessellate: tolerance " + detail::numberText(tolerance) +
                                " needs more than " + std::to_string(kMaxVertices) + " points");
    }
}

}  // namespace

std::vector<glm::dvec3> tessellate(const Curve& curve, double tolerance) {
    checkTolerance(tolerance, "tessellate");
    validate(curve, "tessellate");
    // Below a few units in the last place of the coordinates no chord can be told from the
    // curve: halving would go on until the vertex limit.
    double extent = 0.0;
    for (const glm::dvec3& p : curve.points)
        extent = std::max({extent, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    if (tolerance < 16.0 * std::numeric_limits<double>::epsilon() * extent)
        throw GeometryError("tessellate: tolerance " + detail::numberText(tolerance) +
                            " is below what coordinates of " + detail::numberText(extent) + " resolve");
    // Knot values are always vertices (corners of C0 curves stay sharp): each Bézier piece is
    // tessellated on its own, and where one starts away from where the last ended (a jump) the
    // polyline joins the two.
    std::vector<glm::dvec3> out;
    for (const BezierCurvePiece& piece : extractBezier(curve)) {
        std::vector<glm::dvec4> net = homogeneousNet(piece.curve).data;
        const glm::dvec3 start = glm::dvec3(net.front()) / net.front().w;
        if (out.empty() || out.back() != start) out.push_back(start);
        tessellatePiece(std::move(net), tolerance, out);
    }
    return out;
}

}  // namespace geom
