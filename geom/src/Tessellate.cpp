#include "geom/Tessellate.h"
#include "NumberText.h"
#include "SegmentDistance.h"
#include "UnitScale.h"

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

namespace {

/// The parameter lines of one direction of the adaptive grid, and what the last halving changed.
struct GridLines {
    static constexpr std::size_t kNew = std::numeric_limits<std::size_t>::max();
    std::vector<double> at;
    std::vector<char> fresh;            ///< per interval: made by the last halving (all, at first)
    std::vector<std::size_t> previous;  ///< per line: its index before the last halving, or kNew
};

GridLines firstLines(std::vector<double> at) {
    const std::size_t n = at.size();
    return {std::move(at), std::vector<char>(n - 1, 1), std::vector<std::size_t>(n, GridLines::kNew)};
}

/// The lines with one added in the middle of each failed interval.
GridLines halved(const GridLines& x, const std::vector<char>& failed) {
    GridLines out;
    const std::size_t added = static_cast<std::size_t>(std::count(failed.begin(), failed.end(), 1));
    out.at.reserve(x.at.size() + added);
    for (std::size_t k = 0; k + 1 < x.at.size(); ++k) {
        out.at.push_back(x.at[k]);
        out.previous.push_back(k);
        out.fresh.push_back(failed[k]);
        if (!failed[k]) continue;
        out.at.push_back(0.5 * (x.at[k] + x.at[k + 1]));
        out.previous.push_back(GridLines::kNew);
        out.fresh.push_back(1);
    }
    out.at.push_back(x.at.back());
    out.previous.push_back(x.at.size() - 1);
    return out;
}

/// The surface points of the grid: those on lines of the last grid copied from it (nv: its
/// v line count), the others evaluated.
std::vector<glm::dvec3> gridPoints(const BezierPatchTree& tree, const GridLines& u, const GridLines& v,
                                   const std::vector<glm::dvec3>& last, std::size_t lastNv) {
    const std::size_t nv = v.at.size();
    std::vector<glm::dvec3> grid(u.at.size() * nv);
    for (std::size_t i = 0; i < u.at.size(); ++i)
        for (std::size_t j = 0; j < nv; ++j)
            grid[i * nv + j] = u.previous[i] != GridLines::kNew && v.previous[j] != GridLines::kNew
                                   ? last[u.previous[i] * lastNv + v.previous[j]]
                                   : tree.evaluate(u.at[i], v.at[j], 0).point;
    return grid;
}

/// The intervals between neighbouring parameter lines of a tensor grid that fail the tolerance.
struct FailedIntervals {
    std::vector<char> u, v;
    bool any = false;
};

/// Measures the grid cells with a fresh interval (every other cell passed last time, or one of
/// its intervals would have been halved) at their edge midpoints, the middle of their diagonal
/// and their triangles' centroids, against the mesh there.
FailedIntervals failedIntervals(const BezierPatchTree& tree, const GridLines& u, const GridLines& v,
                                const std::vector<glm::dvec3>& grid, double tolerance) {
    const std::vector<double>&us = u.at, &vs = v.at;
    const std::size_t nv = vs.size();
    FailedIntervals failed{std::vector<char>(us.size() - 1, 0), std::vector<char>(nv - 1, 0)};
    auto off = [&](double a, double b, const glm::dvec3& mesh) {
        return glm::length(tree.evaluate(a, b, 0).point - mesh);
    };
    for (std::size_t i = 0; i + 1 < us.size(); ++i)
        for (std::size_t j = 0; j + 1 < nv; ++j) {
            if (!u.fresh[i] && !v.fresh[j]) continue;
            const double u0 = us[i], u1 = us[i + 1], v0 = vs[j], v1 = vs[j + 1];
            const double um = 0.5 * (u0 + u1), vm = 0.5 * (v0 + v1);
            const glm::dvec3& p00 = grid[i * nv + j];
            const glm::dvec3& p10 = grid[(i + 1) * nv + j];
            const glm::dvec3& p11 = grid[(i + 1) * nv + j + 1];
            const glm::dvec3& p01 = grid[i * nv + j + 1];
            // The far edges belong to the neighbouring cells, except on the domain's border.
            double eu = off(um, v0, 0.5 * (p00 + p10)), ev = off(u0, vm, 0.5 * (p00 + p01));
            if (j + 2 == nv) eu = std::max(eu, off(um, v1, 0.5 * (p01 + p11)));
            if (i + 2 == us.size()) ev = std::max(ev, off(u1, vm, 0.5 * (p10 + p11)));
            // The cell is split along p00-p11.
            const double inside =
                std::max({off(um, vm, 0.5 * (p00 + p11)),
                          off((2.0 * u1 + u0) / 3.0, (v1 + 2.0 * v0) / 3.0, (p00 + p10 + p11) / 3.0),
                          off((u1 + 2.0 * u0) / 3.0, (2.0 * v1 + v0) / 3.0, (p00 + p11 + p01) / 3.0)});
            if (eu > tolerance) failed.u[i] = 1;
            if (ev > tolerance) failed.v[j] = 1;
            if (inside > tolerance && eu <= tolerance && ev <= tolerance) failed.u[i] = failed.v[j] = 1;
            failed.any = failed.any || eu > tolerance || ev > tolerance || inside > tolerance;
        }
    return failed;
}

}  // namespace

namespace {

/// tessellateAdaptive on a surface scaled to unit size (so that no distance overflows);
/// `asked` is the caller's tolerance, for the messages.
SurfaceMesh adaptiveMesh(const Surface& surface, double tolerance, double asked) {
    const BezierPatchTree tree(surface);
    // Start from the degree (a degree-p span needs about p chords to show its shape at all).
    auto start = [](const std::vector<double>& breaks, int degree) {
        return firstLines(
            lines(breaks, std::vector<int>(breaks.size() - 1, degree == 1 ? 1 : std::min(degree, 8))));
    };
    GridLines u = start(tree.breaksU(), surface.degreeU), v = start(tree.breaksV(), surface.degreeV);
    std::vector<glm::dvec3> grid;
    std::size_t lastNv = 0;
    // Only the intervals that fail are halved: small weights squeeze much of a patch's shape into
    // a sliver of its parameters, which lines spread over whole spans would need millions of
    // vertices to reach.
    for (int round = 0; round < 40; ++round) {
        if (u.at.size() * v.at.size() > kMaxVertices)
            throw GeometryError("tessellateAdaptive: tolerance " + detail::numberText(asked) +
                                " needs more than " + std::to_string(kMaxVertices) + " vertices");
        grid = gridPoints(tree, u, v, grid, lastNv);
        lastNv = v.at.size();
        const FailedIntervals failed = failedIntervals(tree, u, v, grid, tolerance);
        if (!failed.any) return gridMesh(surface, tree, u.at, v.at);
        u = halved(u, failed.u);
        v = halved(v, failed.v);
    }
    throw GeometryError("tessellateAdaptive: tolerance " + detail::numberText(asked) +
                        " was not reached after 40 refinements");
}

/// Whether a shape of unit scale `scale` (detail::unitScale) must be measured scaled: within 2^100
/// of unit size nothing overflows (4th powers of coordinates stay normal), and as scaling is
/// exact the shape itself gives the same result without a copy.
bool measuredScaled(double scale) {
    return scale < 0x1p-100 || scale > 0x1p100;
}

}  // namespace

SurfaceMesh tessellateAdaptive(const Surface& surface, double tolerance) {
    checkTolerance(tolerance, "tessellateAdaptive");
    validate(surface, "tessellateAdaptive");
    // Measured on the surface scaled to unit size: at coordinates past 1e154 every squared
    // distance would overflow, every cell fail, and the vertex limit be blamed.
    const double scale = detail::unitScale(surface.points);
    if (!measuredScaled(scale)) return adaptiveMesh(surface, tolerance, tolerance);
    Surface unit = surface;
    for (glm::dvec3& p : unit.points) p *= scale;
    SurfaceMesh mesh = adaptiveMesh(unit, tolerance * scale, tolerance);
    for (glm::dvec3& p : mesh.positions) p /= scale;
    return mesh;
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
/// `asked` is the caller's tolerance, for the message.
void tessellatePiece(std::vector<glm::dvec4> piece, double tolerance, double asked,
                     std::vector<glm::dvec3>& out) {
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
            throw GeometryError("tessellate: tolerance " + detail::numberText(asked) + " needs more than " +
                                std::to_string(kMaxVertices) + " points");
    }
}

}  // namespace

std::vector<glm::dvec3> tessellate(const Curve& curve, double tolerance) {
    checkTolerance(tolerance, "tessellate");
    validate(curve, "tessellate");
    // Below a few units in the last place of the coordinates no chord can be told from the
    // curve: halving would go on until the vertex limit.
    double extent = 0.0;
    for (const glm::dvec3& p : curve.points) extent = std::max(extent, detail::largestCoordinate(p));
    if (tolerance < 16.0 * std::numeric_limits<double>::epsilon() * extent)
        throw GeometryError("tessellate: tolerance " + detail::numberText(tolerance) +
                            " is below what coordinates of " + detail::numberText(extent) + " resolve");
    // Measured on the curve scaled to unit size: at coordinates past 1e154 the squared distances
    // of the flatness test would overflow and pass any piece as one chord.
    double scale = detail::unitScaleOf(extent);
    if (!measuredScaled(scale)) scale = 1.0;
    Curve scaled;
    if (scale != 1.0) {
        scaled = curve;
        for (glm::dvec3& p : scaled.points) p *= scale;
    }
    const Curve& unit = scale != 1.0 ? scaled : curve;
    // Knot values are always vertices (corners of C0 curves stay sharp): each Bézier piece is
    // tessellated on its own, and where one starts away from where the last ended (a jump) the
    // polyline joins the two.
    std::vector<glm::dvec3> out;
    for (const BezierCurvePiece& piece : extractBezier(unit)) {
        std::vector<glm::dvec4> net = homogeneousNet(piece.curve).data;
        const glm::dvec3 start = glm::dvec3(net.front()) / net.front().w;
        if (out.empty() || out.back() != start) out.push_back(start);
        tessellatePiece(std::move(net), tolerance * scale, tolerance, out);
    }
    if (scale != 1.0)
        for (glm::dvec3& p : out) p /= scale;
    return out;
}

}  // namespace geom
