#include "geom/GridEvaluator.h"

#include "geom/Basis.h"
#include "geom/ControlNet.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <string>

namespace geom {
namespace {

/// Span and basis values with first derivatives for each parameter of one direction.
struct DirectionBasis {
    std::vector<std::size_t> spans;
    std::vector<double> values;  ///< per parameter: degree+1 values, then degree+1 derivatives
};

DirectionBasis directionBasis(int degree, const std::vector<double>& knots, std::size_t count,
                              std::span<const double> params) {
    const std::size_t w = static_cast<std::size_t>(degree) + 1;
    const double lo = knots[static_cast<std::size_t>(degree)], hi = knots[count];
    DirectionBasis b;
    b.spans.resize(params.size());
    b.values.resize(params.size() * 2 * w);
    for (std::size_t i = 0; i < params.size(); ++i) {
        const double u = std::clamp(params[i], lo, hi);
        b.spans[i] = findSpan(degree, knots, count, u);
        basisDerivatives(b.spans[i], u, degree, knots, 1,
                         std::span<double>(b.values).subspan(i * 2 * w, 2 * w));
    }
    return b;
}

}  // namespace

GridEvaluator::GridEvaluator(const Surface& surface)
    : surface_(surface), net_(homogeneousNet(surface, false).data) {
}

void GridEvaluator::evaluate(std::span<const double> us, std::span<const double> vs,
                             std::span<GridSample> out) const {
    if (out.size() < us.size() * vs.size())
        throw GeometryError("GridEvaluator: output holds " + std::to_string(out.size()) + " samples, " +
                            std::to_string(us.size() * vs.size()) + " needed");
    const Surface& s = surface_;
    const std::size_t p = static_cast<std::size_t>(s.degreeU), q = static_cast<std::size_t>(s.degreeV);
    const std::size_t wu = p + 1, wv = q + 1;
    const DirectionBasis bu = directionBasis(s.degreeU, s.knotsU, s.countU, us);
    const DirectionBasis bv = directionBasis(s.degreeV, s.knotsV, s.countV, vs);
    // The columns any v parameter touches.
    std::size_t firstColumn = s.countV, lastColumn = 0;
    for (std::size_t span : bv.spans) {
        firstColumn = std::min(firstColumn, span - q);
        lastColumn = std::max(lastColumn, span);
    }
    std::vector<glm::dvec4> row(s.countV), rowU(s.countV);
    for (std::size_t i = 0; i < us.size(); ++i) {
        const double* n = bu.values.data() + i * 2 * wu;
        const double* dn = n + wu;
        const std::size_t base = bu.spans[i] - p;
        for (std::size_t j = firstColumn; j <= lastColumn; ++j) {
            glm::dvec4 c(0.0), cu(0.0);
            for (std::size_t r = 0; r < wu; ++r) {
                const glm::dvec4& pw = net_[(base + r) * s.countV + j];
                c += n[r] * pw;
                cu += dn[r] * pw;
            }
            row[j] = c;
            rowU[j] = cu;
        }
        for (std::size_t j = 0; j < vs.size(); ++j) {
            const double* m = bv.values.data() + j * 2 * wv;
            const double* dm = m + wv;
            const std::size_t first = bv.spans[j] - q;
            glm::dvec4 h(0.0), hu(0.0), hv(0.0);
            for (std::size_t k = 0; k < wv; ++k) {
                h += m[k] * row[first + k];
                hv += dm[k] * row[first + k];
                hu += m[k] * rowU[first + k];
            }
            GridSample& g = out[i * vs.size() + j];
            const double inv = 1.0 / h.w;
            g.point = glm::dvec3(h) * inv;
            g.su = (glm::dvec3(hu) - hu.w * g.point) * inv;
            g.sv = (glm::dvec3(hv) - hv.w * g.point) * inv;
            const glm::dvec3 cr = glm::cross(g.su, g.sv);
            const double len2 = glm::dot(cr, cr);
            if (len2 > 1e-24 * glm::dot(g.su, g.su) * glm::dot(g.sv, g.sv) && len2 > 0.0)
                g.normal = cr / std::sqrt(len2);
            else
                g.normal =
                    normalFromDerivatives(s, std::clamp(us[i], s.domainStartU(), s.domainEndU()),
                                          std::clamp(vs[j], s.domainStartV(), s.domainEndV()), g.su, g.sv);
        }
    }
}

std::vector<GridSample> GridEvaluator::evaluate(std::span<const double> us,
                                                std::span<const double> vs) const {
    std::vector<GridSample> out(us.size() * vs.size());
    evaluate(us, vs, out);
    return out;
}

std::vector<glm::dvec3> evaluateMany(const Curve& curve, std::span<const double> us) {
    const std::size_t w = static_cast<std::size_t>(curve.degree) + 1;
    std::vector<double> basis(w);
    std::vector<glm::dvec3> out;
    out.reserve(us.size());
    const ControlNet net = homogeneousNet(curve);
    for (double u : us) {
        u = std::clamp(u, curve.domainStart(), curve.domainEnd());
        const std::size_t span = findSpan(curve.degree, curve.knots, curve.points.size(), u);
        basisFunctions(span, u, curve.degree, curve.knots, basis);
        glm::dvec4 h(0.0);
        for (std::size_t k = 0; k < w; ++k) h += basis[k] * net.data[span - w + 1 + k];
        out.push_back(glm::dvec3(h) / h.w);
    }
    return out;
}

}  // namespace geom
