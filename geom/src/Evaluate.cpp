#include "geom/Evaluate.h"

#include "Checked.h"
#include "geom/Basis.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace geom {
namespace {

double binomial(int n, int k) {
    double r = 1.0;
    for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
    return r;
}

double clampTo(double x, double lo, double hi) {
    return std::min(std::max(x, lo), hi);
}

void checkOrder(int order, const char* where) {
    if (order < 0 || order > 64)
        throw GeometryError(std::string(where) + ": derivative order " + std::to_string(order) +
                            " is outside 0..64");
}

std::vector<glm::dvec3> curveDerivatives(const Curve& curve, double u, int order, const char* where) {
    detail::checkShape(curve, where);
    checkOrder(order, where);
    const int p = curve.degree;
    const std::size_t w = static_cast<std::size_t>(p) + 1;
    const int du = std::min(order, p);
    u = detail::checkedParameter(u, curve.domainStart(), curve.domainEnd(), where, "u");
    const std::size_t span = findSpan(p, curve.knots, curve.points.size(), u);
    detail::checkSpan(curve.knots, span, p, where);
    std::vector<double> nders(w * static_cast<std::size_t>(du + 1));
    basisDerivatives(span, u, p, curve.knots, du, nders);

    // Derivatives of the homogeneous curve (w*P, w).
    std::vector<glm::dvec4> hom(static_cast<std::size_t>(order) + 1, glm::dvec4(0.0));
    for (int k = 0; k <= du; ++k)
        for (std::size_t j = 0; j < w; ++j) {
            const std::size_t idx = span - static_cast<std::size_t>(p) + j;
            const double wt = curve.weight(idx);
            if (!(wt > 0.0))
                throw GeometryError(std::string(where) + ": weight " + std::to_string(idx) +
                                    " is not positive");
            hom[static_cast<std::size_t>(k)] +=
                nders[static_cast<std::size_t>(k) * w + j] * glm::dvec4(curve.points[idx] * wt, wt);
        }

    std::vector<glm::dvec3> ck(static_cast<std::size_t>(order) + 1);
    for (int k = 0; k <= order; ++k) {
        glm::dvec3 v(hom[static_cast<std::size_t>(k)]);
        for (int i = 1; i <= k; ++i)
            v -= binomial(k, i) * hom[static_cast<std::size_t>(i)].w * ck[static_cast<std::size_t>(k - i)];
        ck[static_cast<std::size_t>(k)] = v / hom[0].w;
        detail::checkResult(ck[static_cast<std::size_t>(k)], where);
    }
    return ck;
}

SurfaceDerivatives surfaceDerivatives(const Surface& surface, double u, double v, int order,
                                      const char* where) {
    detail::checkShape(surface, where);
    checkOrder(order, where);
    const int p = surface.degreeU;
    const int q = surface.degreeV;
    const std::size_t wu = static_cast<std::size_t>(p) + 1;
    const std::size_t wv = static_cast<std::size_t>(q) + 1;
    const int du = std::min(order, p);
    const int dv = std::min(order, q);
    u = detail::checkedParameter(u, surface.domainStartU(), surface.domainEndU(), where, "u");
    v = detail::checkedParameter(v, surface.domainStartV(), surface.domainEndV(), where, "v");
    const std::size_t spanU = findSpan(p, surface.knotsU, surface.countU, u);
    const std::size_t spanV = findSpan(q, surface.knotsV, surface.countV, v);
    detail::checkSpan(surface.knotsU, spanU, p, where);
    detail::checkSpan(surface.knotsV, spanV, q, where);
    std::vector<double> nu(wu * static_cast<std::size_t>(du + 1));
    std::vector<double> nv(wv * static_cast<std::size_t>(dv + 1));
    basisDerivatives(spanU, u, p, surface.knotsU, du, nu);
    basisDerivatives(spanV, v, q, surface.knotsV, dv, nv);

    const std::size_t side = static_cast<std::size_t>(order) + 1;
    std::vector<glm::dvec4> hom(side * side, glm::dvec4(0.0));
    std::vector<glm::dvec4> temp(wv);
    for (int k = 0; k <= du; ++k) {
        for (std::size_t s = 0; s < wv; ++s) {
            temp[s] = glm::dvec4(0.0);
            for (std::size_t r = 0; r < wu; ++r) {
                const std::size_t i = spanU - static_cast<std::size_t>(p) + r;
                const std::size_t j = spanV - static_cast<std::size_t>(q) + s;
                const double wt = surface.weight(i, j);
                if (!(wt > 0.0))
                    throw GeometryError(std::string(where) + ": weight (" + std::to_string(i) + ", " +
                                        std::to_string(j) + ") is not positive");
                temp[s] +=
                    nu[static_cast<std::size_t>(k) * wu + r] * glm::dvec4(surface.point(i, j) * wt, wt);
            }
        }
        const int dd = std::min(order - k, dv);
        for (int l = 0; l <= dd; ++l) {
            glm::dvec4 acc(0.0);
            for (std::size_t s = 0; s < wv; ++s) acc += nv[static_cast<std::size_t>(l) * wv + s] * temp[s];
            hom[static_cast<std::size_t>(k) * side + static_cast<std::size_t>(l)] = acc;
        }
    }

    // Quotient rule for rational surfaces (The NURBS Book A4.4).
    SurfaceDerivatives out;
    out.order = order;
    out.values.assign(side * side, glm::dvec3(0.0));
    auto H = [&](int k, int l) -> const glm::dvec4& {
        return hom[static_cast<std::size_t>(k) * side + static_cast<std::size_t>(l)];
    };
    const double w00 = H(0, 0).w;
    for (int k = 0; k <= order; ++k)
        for (int l = 0; l <= order - k; ++l) {
            glm::dvec3 val(H(k, l));
            for (int j = 1; j <= l; ++j) val -= binomial(l, j) * H(0, j).w * out.at(k, l - j);
            for (int i = 1; i <= k; ++i) {
                val -= binomial(k, i) * H(i, 0).w * out.at(k - i, l);
                glm::dvec3 v2(0.0);
                for (int j = 1; j <= l; ++j) v2 += binomial(l, j) * H(i, j).w * out.at(k - i, l - j);
                val -= binomial(k, i) * v2;
            }
            out.at(k, l) = val / w00;
            detail::checkResult(out.at(k, l), where);
        }
    return out;
}

}  // namespace

glm::dvec3 evaluate(const Curve& curve, double u) {
    return curveDerivatives(curve, u, 0, "evaluate")[0];
}

std::vector<glm::dvec3> derivatives(const Curve& curve, double u, int order) {
    return curveDerivatives(curve, u, order, "derivatives");
}

glm::dvec3 evaluate(const Surface& surface, double u, double v) {
    return surfaceDerivatives(surface, u, v, 0, "evaluate").at(0, 0);
}

SurfaceDerivatives derivatives(const Surface& surface, double u, double v, int order) {
    return surfaceDerivatives(surface, u, v, order, "derivatives");
}

glm::dvec3 normalFromDerivatives(const Surface& surface, double u, double v, const glm::dvec3& su,
                                 const glm::dvec3& sv) {
    detail::checkShape(surface, "normalFromDerivatives");
    u = detail::checkedParameter(u, surface.domainStartU(), surface.domainEndU(), "normalFromDerivatives",
                                 "u");
    v = detail::checkedParameter(v, surface.domainStartV(), surface.domainEndV(), "normalFromDerivatives",
                                 "v");
    const glm::dvec3 n = glm::cross(su, sv);
    const double len = glm::length(n);
    const double scale = glm::length(su) * glm::length(sv);
    if (len > 1e-12 * scale && len > 0.0) return n / len;

    // Degenerate point: step towards the inside of the domain along the diagonal and take the
    // limit of the normals there (they converge on a collapsed edge or at a pole).
    const double u0 = surface.domainStartU(), u1 = surface.domainEndU();
    const double v0 = surface.domainStartV(), v1 = surface.domainEndV();
    const double dirU = (u - u0) <= (u1 - u) ? 1.0 : -1.0;
    const double dirV = (v - v0) <= (v1 - v) ? 1.0 : -1.0;
    for (double t = 1e-7; t <= 1e-3; t *= 10.0) {
        const double uu = clampTo(u + dirU * t * (u1 - u0), u0, u1);
        const double vv = clampTo(v + dirV * t * (v1 - v0), v0, v1);
        const SurfaceDerivatives d = derivatives(surface, uu, vv, 1);
        const glm::dvec3 m = glm::cross(d.at(1, 0), d.at(0, 1));
        const double ml = glm::length(m);
        if (ml > 1e-12 * glm::length(d.at(1, 0)) * glm::length(d.at(0, 1)) && ml > 0.0) return m / ml;
    }
    return glm::dvec3(0.0);
}

glm::dvec3 normal(const Surface& surface, double u, double v) {
    const SurfaceDerivatives d = surfaceDerivatives(surface, u, v, 1, "normal");
    return normalFromDerivatives(surface, u, v, d.at(1, 0), d.at(0, 1));
}

}  // namespace geom
