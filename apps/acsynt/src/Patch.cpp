#include "acsynt/Patch.h"

#include "geom/Bezier.h"
#include "geom/BezierExtraction.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"

#include <algorithm>
#include <span>

namespace acsynt {

PatchList buildPatches(const geom::Surface& surface) {
    geom::validate(surface);
    if (surface.degreeU != 3 || surface.degreeV != 3)
        throw geom::GeometryError("patch list: the surface must be bicubic, it has degrees " +
                                  std::to_string(surface.degreeU) + " x " + std::to_string(surface.degreeV));
    if (surface.rational())
        throw geom::GeometryError("patch list: the surface must be polynomial (no weights)");
    // extractBezier gives one piece per non-empty span pair, u span slow, w span fast: the patches.
    const std::vector<geom::BezierSurfacePiece> pieces = geom::extractBezier(surface);
    PatchList list;
    list.countW = static_cast<std::size_t>(std::count_if(
        pieces.begin(), pieces.end(), [&](const auto& b) { return b.spanU == pieces[0].spanU; }));
    list.countU = pieces.size() / list.countW;
    list.patches.reserve(pieces.size());
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const geom::BezierSurfacePiece& piece = pieces[k];
        Patch p;
        p.number = static_cast<int>(k + 1);
        p.row = k / list.countW;
        p.column = k % list.countW;
        p.spanU = piece.spanU;
        p.spanW = piece.spanV;
        for (std::size_t i = 0; i < 8; ++i) {
            p.knotsU[i] = surface.knotsU[p.spanU - 3 + i];
            p.knotsW[i] = surface.knotsV[p.spanW - 3 + i];
        }
        p.u0 = piece.u0;
        p.u1 = piece.u1;
        p.w0 = piece.v0;
        p.w1 = piece.v1;
        for (std::size_t i = 0; i < 4; ++i)
            for (std::size_t j = 0; j < 4; ++j)
                p.hull[i * 4 + j] = surface.point(p.spanU - 3 + i, p.spanW - 3 + j);
        std::copy(piece.surface.points.begin(), piece.surface.points.end(), p.bezier.begin());
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
    // The piece alone: 4 x 4 control points on the 8 + 8 local knots, domain [u0, u1] x [w0, w1].
    const geom::Surface local(3, 3, {p.knotsU.begin(), p.knotsU.end()}, {p.knotsW.begin(), p.knotsW.end()}, 4,
                              4, {p.hull.begin(), p.hull.end()});
    return geom::evaluate(local, u, w);
}

glm::dvec3 evaluateBezierPatch(const Patch& p, double u, double w) {
    const double s = (u - p.u0) / (p.u1 - p.u0);
    const double t = (w - p.w0) / (p.w1 - p.w0);
    std::array<glm::dvec3, 4> column{};
    for (std::size_t i = 0; i < 4; ++i)
        column[i] = geom::deCasteljau<glm::dvec3>(std::span(p.bezier).subspan(i * 4, 4), t);
    return geom::deCasteljau<glm::dvec3>(column, s);
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
