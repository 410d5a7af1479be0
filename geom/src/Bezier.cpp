#include "geom/Bezier.h"
#include "NumberText.h"

#include "geom/ControlNet.h"
#include "geom/GeometryError.h"

#include <glm/vec4.hpp>

#include <string>

namespace geom {
namespace {

bool bezierKnots(const std::vector<double>& knots, int degree, std::size_t count) {
    const std::size_t p = static_cast<std::size_t>(degree);
    if (count != p + 1 || knots.size() != 2 * p + 2) return false;
    for (std::size_t i = 0; i <= p; ++i)
        if (knots[i] != knots[0] || knots[p + 1 + i] != knots[p + 1]) return false;
    return knots[0] < knots[p + 1];
}

std::vector<double> knotsOver(int degree, double a, double b) {
    std::vector<double> k(2 * static_cast<std::size_t>(degree + 1), a);
    std::fill(k.begin() + degree + 1, k.end(), b);
    return k;
}

double localParameter(double u, double a, double b) {
    return (u - a) / (b - a);
}

// bernsteinBasis runs once per evaluated point: its refusal's message is made out of line.
[[noreturn, gnu::cold, gnu::noinline]] void badBernsteinArguments(int degree, std::size_t values,
                                                                  std::size_t first, std::size_t second) {
    throw GeometryError("bernsteinBasis: degree " + std::to_string(degree) +
                        " needs degree + 1 values in each output (given " + std::to_string(values) + ", " +
                        std::to_string(first) + ", " + std::to_string(second) + ")");
}

}  // namespace

void bernsteinBasis(int degree, double t, std::span<double> values, std::span<double> first,
                    std::span<double> second) {
    const std::size_t n = static_cast<std::size_t>(degree);
    // Size comparisons only: this runs once per evaluated point.
    if (degree < 0 || values.size() <= n || (!first.empty() && first.size() <= n) ||
        (!second.empty() && second.size() <= n))
        badBernsteinArguments(degree, values.size(), first.size(), second.size());
    const double s = 1.0 - t;
    // Raise the degree step by step (The NURBS Book A1.3), keeping degrees n-1 and n-2 for
    // the derivatives: B'_{i,n} = n (B_{i-1,n-1} - B_{i,n-1}).
    double* b = values.data();
    b[0] = 1.0;
    for (std::size_t j = 1; j <= n; ++j) {
        if (j == n && !first.empty()) {
            for (std::size_t i = 0; i <= n; ++i) {
                const double left = i > 0 ? b[i - 1] : 0.0;
                const double right = i < n ? b[i] : 0.0;
                first[i] = static_cast<double>(n) * (left - right);
            }
        }
        if (j + 1 == n && !second.empty() && n >= 2) {
            for (std::size_t i = 0; i <= n; ++i) {
                const double a0 = i >= 2 ? b[i - 2] : 0.0;
                const double a1 = (i >= 1 && i - 1 <= n - 2) ? b[i - 1] : 0.0;
                const double a2 = i <= n - 2 ? b[i] : 0.0;
                second[i] = static_cast<double>(n * (n - 1)) * (a0 - 2.0 * a1 + a2);
            }
        }
        double saved = 0.0;
        for (std::size_t k = 0; k < j; ++k) {
            const double temp = b[k];
            b[k] = saved + s * temp;
            saved = t * temp;
        }
        b[j] = saved;
    }
    if (!first.empty() && n == 0) first[0] = 0.0;
    if (!second.empty() && n < 2)
        for (std::size_t i = 0; i <= n; ++i) second[i] = 0.0;
}

bool isBezier(const Curve& curve) {
    validate(curve, "isBezier");
    return bezierKnots(curve.knots, curve.degree, curve.points.size());
}

bool isBezier(const Surface& s) {
    validate(s, "isBezier");
    return bezierKnots(s.knotsU, s.degreeU, s.countU) && bezierKnots(s.knotsV, s.degreeV, s.countV);
}

glm::dvec3 evaluateBezier(const Curve& bezier, double u) {
    validate(bezier, "evaluateBezier");
    if (!isBezier(bezier)) throw GeometryError("evaluateBezier: the curve is not a single Bézier segment");
    const ControlNet net = homogeneousNet(bezier);
    const glm::dvec4 h =
        deCasteljau<glm::dvec4>(net.data, localParameter(u, bezier.domainStart(), bezier.domainEnd()));
    return glm::dvec3(h) / h.w;
}

glm::dvec3 evaluateBezier(const Surface& bezier, double u, double v) {
    validate(bezier, "evaluateBezier");
    if (!isBezier(bezier)) throw GeometryError("evaluateBezier: the surface is not a single Bézier patch");
    const ControlNet net = homogeneousNet(bezier, false);
    const double tv = localParameter(v, bezier.domainStartV(), bezier.domainEndV());
    std::vector<glm::dvec4> column(bezier.countU);
    for (std::size_t i = 0; i < bezier.countU; ++i)
        column[i] =
            deCasteljau<glm::dvec4>(std::span(net.data).subspan(i * bezier.countV, bezier.countV), tv);
    const glm::dvec4 h =
        deCasteljau<glm::dvec4>(column, localParameter(u, bezier.domainStartU(), bezier.domainEndU()));
    return glm::dvec3(h) / h.w;
}

std::pair<Curve, Curve> subdivide(const Curve& bezier, double u) {
    validate(bezier, "subdivide");
    if (!isBezier(bezier)) throw GeometryError("subdivide: the curve is not a single Bézier segment");
    const double a = bezier.domainStart(), b = bezier.domainEnd();
    if (!(u > a && u < b))
        throw GeometryError("subdivide: parameter " + detail::numberText(u) + " is not inside (" +
                            detail::numberText(a) + ", " + detail::numberText(b) + ")");
    const ControlNet net = homogeneousNet(bezier);
    ControlNet left, right;
    left.data.resize(net.data.size());
    right.data.resize(net.data.size());
    subdivideBezier<glm::dvec4>(net.data, localParameter(u, a, b), left.data, right.data);
    std::pair<Curve, Curve> out{bezier, bezier};
    out.first.knots = knotsOver(bezier.degree, a, u);
    out.second.knots = knotsOver(bezier.degree, u, b);
    setFromNet(out.first, left, bezier.rational());
    setFromNet(out.second, right, bezier.rational());
    return out;
}

std::pair<Surface, Surface> subdivide(const Surface& bezier, double t, bool alongV) {
    validate(bezier, "subdivide");
    if (!isBezier(bezier)) throw GeometryError("subdivide: the surface is not a single Bézier patch");
    const double a = alongV ? bezier.domainStartV() : bezier.domainStartU();
    const double b = alongV ? bezier.domainEndV() : bezier.domainEndU();
    if (!(t > a && t < b))
        throw GeometryError("subdivide: parameter " + detail::numberText(t) + " is not inside (" +
                            detail::numberText(a) + ", " + detail::numberText(b) + ")");
    const ControlNet net = homogeneousNet(bezier, false);
    ControlNet first, second;
    first.stride = second.stride = bezier.countV;
    subdivideBezierNet<glm::dvec4>(net.data, bezier.countU, bezier.countV, localParameter(t, a, b), alongV,
                                   first.data, second.data);
    std::pair<Surface, Surface> out{bezier, bezier};
    auto& k1 = alongV ? out.first.knotsV : out.first.knotsU;
    auto& k2 = alongV ? out.second.knotsV : out.second.knotsU;
    const int degree = alongV ? bezier.degreeV : bezier.degreeU;
    k1 = knotsOver(degree, a, t);
    k2 = knotsOver(degree, t, b);
    setFromNet(out.first, first, false, bezier.rational());
    setFromNet(out.second, second, false, bezier.rational());
    return out;
}

}  // namespace geom
