#include "acsynt/Patch.h"

#include "geom/Evaluate.h"
#include "geom/GeometryError.h"

#include <algorithm>

namespace acsynt {
namespace {

/// Blossom of one cubic B-spline segment with local knots t[0..7] (segment [t3, t4]) and
/// control points d[0..3], at the three arguments x (de Boor with one argument per level).
glm::dvec3 blossom(const std::array<double, 8>& t, std::array<glm::dvec3, 4> d,
                   const std::array<double, 3>& x) {
    for (int r = 1; r <= 3; ++r)
        for (int i = 3; i >= r; --i) {
            const double a = (x[static_cast<std::size_t>(r - 1)] - t[static_cast<std::size_t>(i)]) /
                             (t[static_cast<std::size_t>(i + 4 - r)] - t[static_cast<std::size_t>(i)]);
            d[static_cast<std::size_t>(i)] =
                (1.0 - a) * d[static_cast<std::size_t>(i - 1)] + a * d[static_cast<std::size_t>(i)];
        }
    return d[3];
}

/// The four Bezier points of a cubic B-spline segment: blossoms at (u0,u0,u0), (u0,u0,u1), ...
std::array<glm::dvec3, 4> segmentToBezier(const std::array<double, 8>& t,
                                          const std::array<glm::dvec3, 4>& d) {
    const double a = t[3], b = t[4];
    return {blossom(t, d, {a, a, a}), blossom(t, d, {a, a, b}), blossom(t, d, {a, b, b}),
            blossom(t, d, {b, b, b})};
}

glm::dvec3 deCasteljau(std::array<glm::dvec3, 4> b, double s) {
    for (int r = 1; r <= 3; ++r)
        for (int i = 0; i + r <= 3; ++i)
            b[static_cast<std::size_t>(i)] =
                (1.0 - s) * b[static_cast<std::size_t>(i)] + s * b[static_cast<std::size_t>(i + 1)];
    return b[0];
}

std::vector<std::size_t> nonEmptySpans(const std::vector<double>& knots, std::size_t count) {
    std::vector<std::size_t> spans;
    for (std::size_t s = 3; s < count; ++s)
        if (knots[s] < knots[s + 1]) spans.push_back(s);
    return spans;
}

}  // namespace

PatchList buildPatches(const geom::Surface& surface) {
    geom::validate(surface);
    if (surface.degreeU != 3 || surface.degreeV != 3)
        throw geom::GeometryError("patch list: the surface must be bicubic, it has degrees " +
                                  std::to_string(surface.degreeU) + " x " + std::to_string(surface.degreeV));
    if (surface.rational())
        throw geom::GeometryError("patch list: the surface must be polynomial (no weights)");
    const std::vector<std::size_t> spansU = nonEmptySpans(surface.knotsU, surface.countU);
    const std::vector<std::size_t> spansW = nonEmptySpans(surface.knotsV, surface.countV);
    PatchList list;
    list.countU = spansU.size();
    list.countW = spansW.size();
    list.patches.reserve(list.countU * list.countW);
    for (std::size_t r = 0; r < spansU.size(); ++r)
        for (std::size_t c = 0; c < spansW.size(); ++c) {
            Patch p;
            p.number = static_cast<int>(r * list.countW + c + 1);
            p.row = r;
            p.column = c;
            p.spanU = spansU[r];
            p.spanW = spansW[c];
            for (std::size_t k = 0; k < 8; ++k) {
                p.knotsU[k] = surface.knotsU[p.spanU - 3 + k];
                p.knotsW[k] = surface.knotsV[p.spanW - 3 + k];
            }
            p.u0 = p.knotsU[3];
            p.u1 = p.knotsU[4];
            p.w0 = p.knotsW[3];
            p.w1 = p.knotsW[4];
            for (std::size_t i = 0; i < 4; ++i)
                for (std::size_t j = 0; j < 4; ++j)
                    p.hull[i * 4 + j] = surface.point(p.spanU - 3 + i, p.spanW - 3 + j);
            // Bezier extraction: rows along w first, then the columns of the result along u.
            std::array<glm::dvec3, 16> rows{};
            for (std::size_t i = 0; i < 4; ++i) {
                const auto b = segmentToBezier(
                    p.knotsW, {p.hull[i * 4], p.hull[i * 4 + 1], p.hull[i * 4 + 2], p.hull[i * 4 + 3]});
                for (std::size_t j = 0; j < 4; ++j) rows[i * 4 + j] = b[j];
            }
            for (std::size_t j = 0; j < 4; ++j) {
                const auto b = segmentToBezier(p.knotsU, {rows[j], rows[4 + j], rows[8 + j], rows[12 + j]});
                for (std::size_t i = 0; i < 4; ++i) p.bezier[i * 4 + j] = b[i];
            }
            p.corner = geom::evaluate(surface, p.u0, p.w0);
            p.u1w0 = geom::evaluate(surface, p.u1, p.w0);
            p.u0w1 = geom::evaluate(surface, p.u0, p.w1);
            p.middle = geom::evaluate(surface, 0.5 * (p.u0 + p.u1), 0.5 * (p.w0 + p.w1));
            const geom::SurfaceDerivatives d = geom::derivatives(surface, p.u0, p.w0, 1);
            p.tangentU = d.at(1, 0);
            p.tangentW = d.at(0, 1);
            p.normal = geom::normalFromDerivatives(surface, p.u0, p.w0, p.tangentU, p.tangentW);
            list.patches.push_back(p);
        }
    return list;
}

const Patch* PatchList::find(double u, double w) const {
    if (patches.empty()) return nullptr;
    const Patch& first = patches.front();
    const Patch& last = patches.back();
    if (u < first.u0 || u > last.u1 || w < first.w0 || w > last.w1) return nullptr;
    std::size_t r = 0, c = 0;
    while (r + 1 < countU && u >= patches[(r + 1) * countW].u0) ++r;
    while (c + 1 < countW && w >= patches[c + 1].w0) ++c;
    return &patches[r * countW + c];
}

glm::dvec3 evaluatePatchHull(const Patch& p, double u, double w) {
    std::array<glm::dvec3, 4> column{};
    for (std::size_t i = 0; i < 4; ++i)
        column[i] = blossom(
            p.knotsW, {p.hull[i * 4], p.hull[i * 4 + 1], p.hull[i * 4 + 2], p.hull[i * 4 + 3]}, {w, w, w});
    return blossom(p.knotsU, column, {u, u, u});
}

glm::dvec3 evaluateBezierPatch(const Patch& p, double u, double w) {
    const double s = (u - p.u0) / (p.u1 - p.u0);
    const double t = (w - p.w0) / (p.w1 - p.w0);
    std::array<glm::dvec3, 4> column{};
    for (std::size_t i = 0; i < 4; ++i)
        column[i] =
            deCasteljau({p.bezier[i * 4], p.bezier[i * 4 + 1], p.bezier[i * 4 + 2], p.bezier[i * 4 + 3]}, t);
    return deCasteljau(column, s);
}

std::array<glm::dvec3, 16> powerBasisCoefficients(const Patch& p) {
    // Bernstein to monomial: b(s) = sum_k M[k][i] s^k b_i for the cubic basis.
    static constexpr double m[4][4] = {{1, 0, 0, 0}, {-3, 3, 0, 0}, {3, -6, 3, 0}, {-1, 3, -3, 1}};
    std::array<glm::dvec3, 16> c{};
    for (std::size_t k = 0; k < 4; ++k)
        for (std::size_t l = 0; l < 4; ++l) {
            glm::dvec3 sum(0.0);
            for (std::size_t i = 0; i < 4; ++i)
                for (std::size_t j = 0; j < 4; ++j) sum += m[k][i] * m[l][j] * p.bezier[i * 4 + j];
            c[k * 4 + l] = sum;
        }
    return c;
}

}  // namespace acsynt
