#include "geom/GridEvaluator.h"

#include "Checked.h"

#include "geom/Basis.h"
#include "geom/ControlNet.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace geom {
namespace {

/// Parameters must be finite (they are clamped into the domain, which NaN defeats).
void checkFinite(std::span<const double> values, const char* where, const char* name) {
    for (std::size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i]))
            throw GeometryError(std::string(where) + ": parameter " + name + "[" + std::to_string(i) +
                                "] is not finite");
}

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

/// One grid row: W is the v basis width when known at compile time (the common low degrees, so
/// the sums unroll), 0 for any other.
template <std::size_t W, bool Rational>
void evaluateRow(const Surface& s, const DirectionBasis& bv, const std::vector<glm::dvec4>& row,
                 const std::vector<glm::dvec4>& rowU, double u, double scaleU, std::span<const double> vs,
                 std::span<GridSample> out) {
    const std::size_t q = static_cast<std::size_t>(s.degreeV);
    const std::size_t wv = W == 0 ? q + 1 : W;
    for (std::size_t j = 0; j < vs.size(); ++j) {
        const double* m = bv.values.data() + j * 2 * wv;
        const double* dm = m + wv;
        const glm::dvec4* c = row.data() + (bv.spans[j] - q);
        const glm::dvec4* cu = rowU.data() + (bv.spans[j] - q);
        glm::dvec3 point, su, sv;
        if constexpr (Rational) {
            glm::dvec4 h(0.0), hu(0.0), hv(0.0);
            for (std::size_t k = 0; k < wv; ++k) {
                h += m[k] * c[k];
                hv += dm[k] * c[k];
                hu += m[k] * cu[k];
            }
            // Locals first, one store at the end: the output is made of doubles too, so writing
            // it early would make the compiler reload the row data after every store.
            const double inv = 1.0 / h.w;
            point = glm::dvec3(h) * inv;
            su = (glm::dvec3(hu) - hu.w * point) * inv;
            sv = (glm::dvec3(hv) - hv.w * point) * inv;
        } else {
            // Polynomial: the weights are all 1, so the homogeneous sums are the answer.
            glm::dvec4 h(0.0), hu(0.0), hv(0.0);
            for (std::size_t k = 0; k < wv; ++k) {
                h += m[k] * c[k];
                hv += dm[k] * c[k];
                hu += m[k] * cu[k];
            }
            point = glm::dvec3(h);
            su = glm::dvec3(hu);
            sv = glm::dvec3(hv);
        }
        const double uc = std::clamp(u, s.domainStartU(), s.domainEndU());
        const double vc = std::clamp(vs[j], s.domainStartV(), s.domainEndV());
        double scaleV = 0.0;
        for (std::size_t k = 0; k < wv; ++k) scaleV += std::abs(dm[k]);
        if (detail::derivativesMayBeRounding(s, point, su, sv, scaleU, scaleV)) {
            // Next to a collapsed edge: the per-point path takes them about a control point.
            const SurfaceDerivatives d = derivatives(s, uc, vc, 1);
            su = d.at(1, 0), sv = d.at(0, 1);
        }
        const glm::dvec3 cr = glm::cross(su, sv);
        const double len2 = glm::dot(cr, cr);
        // Derivatives a million times apart (by squares, 1e-12), or any on a domain edge (a pole
        // row): the smaller's direction may mean nothing, which normalFromDerivatives decides.
        const double su2 = glm::dot(su, su), sv2 = glm::dot(sv, sv);
        const bool comparable = std::min(su2, sv2) > 1e-12 * std::max(su2, sv2);
        const bool edge =
            uc == s.domainStartU() || uc == s.domainEndU() || vc == s.domainStartV() || vc == s.domainEndV();
        glm::dvec3 n;
        if (comparable && !edge && len2 > 1e-24 * su2 * sv2 && len2 > 0.0)
            n = cr * (1.0 / std::sqrt(len2));
        else
            n = normalFromDerivatives(s, uc, vc, su, sv);
        out[j] = GridSample{point, su, sv, n};
    }
}

}  // namespace

GridEvaluator::GridEvaluator(const Surface& surface)
    : surface_((validate(surface, "GridEvaluator"), surface)), net_(homogeneousNet(surface, false).data) {
}

void GridEvaluator::evaluate(std::span<const double> us, std::span<const double> vs,
                             std::span<GridSample> out) const {
    if (out.size() < us.size() * vs.size())
        throw GeometryError("GridEvaluator: output holds " + std::to_string(out.size()) + " samples, " +
                            std::to_string(us.size() * vs.size()) + " needed");
    checkFinite(us, "GridEvaluator", "us");
    checkFinite(vs, "GridEvaluator", "vs");
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
        const std::span<GridSample> line = out.subspan(i * vs.size(), vs.size());
        const double du = detail::absoluteSum(std::span<const double>(dn, wu));
        if (s.rational()) {
            switch (wv) {
                case 3:
                    evaluateRow<3, true>(s, bv, row, rowU, us[i], du, vs, line);
                    break;
                case 4:
                    evaluateRow<4, true>(s, bv, row, rowU, us[i], du, vs, line);
                    break;
                default:
                    evaluateRow<0, true>(s, bv, row, rowU, us[i], du, vs, line);
                    break;
            }
        } else {
            switch (wv) {
                case 3:
                    evaluateRow<3, false>(s, bv, row, rowU, us[i], du, vs, line);
                    break;
                case 4:
                    evaluateRow<4, false>(s, bv, row, rowU, us[i], du, vs, line);
                    break;
                default:
                    evaluateRow<0, false>(s, bv, row, rowU, us[i], du, vs, line);
                    break;
            }
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
    validate(curve, "evaluateMany");
    checkFinite(us, "evaluateMany", "us");
    const std::size_t w = static_cast<std::size_t>(curve.degree) + 1;
    std::vector<double> basis(w);
    std::vector<glm::dvec3> out;
    out.reserve(us.size());
    const ControlNet net = homogeneousNet(curve);
    std::string name;
    for (std::size_t i = 0; i < us.size(); ++i) {
        double u = us[i];
        if (u < curve.domainStart() || u > curve.domainEnd()) {
            name = "us[" + std::to_string(i) + "]";
            u = detail::checkedParameter(u, curve.domainStart(), curve.domainEnd(), "evaluateMany",
                                         name.c_str());
        }
        const std::size_t span = findSpan(curve.degree, curve.knots, curve.points.size(), u);
        basisFunctions(span, u, curve.degree, curve.knots, basis);
        glm::dvec4 h(0.0);
        for (std::size_t k = 0; k < w; ++k) h += basis[k] * net.data[span - w + 1 + k];
        out.push_back(glm::dvec3(h) / h.w);
        detail::checkResult(out.back(), "evaluateMany");
    }
    return out;
}

}  // namespace geom
