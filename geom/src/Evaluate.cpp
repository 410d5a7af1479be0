#include "geom/Evaluate.h"

#include "Checked.h"
#include "SmallBuffer.h"
#include "UnitScale.h"
#include "geom/Basis.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
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

/// findSpan with a per-thread hint: per-point callers walk their parameters in order, so the span
/// of a recent call on the same knot vector usually still holds u (SISL's s1421 takes the same
/// hint from its caller). A hint is used only where it is the span findSpan would return.
std::size_t hintedSpan(int degree, const std::vector<double>& knots, std::size_t count, double u) {
    struct Hint {
        const double* knots = nullptr;
        std::size_t span = 0;
    };
    thread_local Hint hints[2];  // a surface's two directions
    thread_local std::size_t next = 0;
    const std::size_t p = static_cast<std::size_t>(degree);
    for (const Hint& hint : hints)
        if (hint.knots == knots.data() && hint.span >= p && hint.span < count && knots[hint.span] <= u &&
            u < knots[hint.span + 1])
            return hint.span;
    const std::size_t span = findSpan(degree, knots, count, u);
    hints[next] = {knots.data(), span};
    next ^= 1;
    return span;
}

/// The public entries check the order before sizing their output; the internal evaluations
/// below take it as given.
void checkOrder(int order, const char* where) {
    if (order < 0 || order > kMaxDerivativeOrder)
        throw GeometryError(std::string(where) + ": derivative order " + std::to_string(order) +
                            " is outside 0.." + std::to_string(kMaxDerivativeOrder));
}

/// C(u) .. C^(order)(u) into out[0..order].
void curveDerivatives(const Curve& curve, double u, int order, const char* where, glm::dvec3* out) {
    detail::checkShape(curve, where);
    const int p = curve.degree;
    const std::size_t w = static_cast<std::size_t>(p) + 1;
    const int du = std::min(order, p);
    u = detail::checkedParameter(u, curve.domainStart(), curve.domainEnd(), where, "u");
    const std::size_t span = hintedSpan(p, curve.knots, curve.points.size(), u);
    detail::checkSpan(curve.knots, span, p, where);
    detail::SmallBuffer<double, 64> nders(w * static_cast<std::size_t>(du + 1));
    basisDerivatives(span, u, p, curve.knots, du, nders.span());

    // Derivatives of the homogeneous curve (w*P, w).
    detail::SmallBuffer<glm::dvec4, 8> hom(static_cast<std::size_t>(order) + 1, glm::dvec4(0.0));
    for (int k = 0; k <= du; ++k)
        for (std::size_t j = 0; j < w; ++j) {
            const std::size_t idx = span - static_cast<std::size_t>(p) + j;
            const double wt = curve.weight(idx);
            if (!detail::usableWeight(wt))
                throw GeometryError(std::string(where) + ": weight " + std::to_string(idx) +
                                    " is not a positive normal number");
            hom[static_cast<std::size_t>(k)] +=
                nders[static_cast<std::size_t>(k) * w + j] * glm::dvec4(curve.points[idx] * wt, wt);
        }

    for (int k = 0; k <= order; ++k) {
        glm::dvec3 v(hom[static_cast<std::size_t>(k)]);
        for (int i = 1; i <= k; ++i) v -= binomial(k, i) * hom[static_cast<std::size_t>(i)].w * out[k - i];
        out[k] = v / hom[0].w;
        detail::checkResult(out[k], where);
    }
}

[[noreturn]] void weightNotNormal(const char* where, std::size_t i, std::size_t j) {
    throw GeometryError(std::string(where) + ": weight (" + std::to_string(i) + ", " + std::to_string(j) +
                        ") is not a positive normal number");
}

/// The control point at the corner of the span's net nearest (u, v) in parameter, about which
/// derivatives keep their digits: next to a collapsed edge, whose points are then exact zeros,
/// the derivatives across it are as small as the distance to it, and taken from the origin they
/// are differences of terms as large as the coordinates (at the edge itself rounding noise that
/// looks like a direction).
glm::dvec3 spanCorner(const Surface& surface, std::size_t spanU, std::size_t spanV, double u, double v) {
    const std::size_t p = static_cast<std::size_t>(surface.degreeU),
                      q = static_cast<std::size_t>(surface.degreeV);
    const auto& ku = surface.knotsU;
    const auto& kv = surface.knotsV;
    const std::size_t ci = u - ku[spanU] <= ku[spanU + 1] - u ? spanU - p : spanU;
    const std::size_t cj = v - kv[spanV] <= kv[spanV + 1] - v ? spanV - q : spanV;
    return surface.point(ci, cj);
}

/// Su and Sv (out[2], out[1]) again, from the span's net taken about spanCorner.
void firstDerivativesAbout(const Surface& surface, std::size_t spanU, std::size_t spanV, double u, double v,
                           std::span<const double> nu, std::span<const double> dnu,
                           std::span<const double> nv, std::span<const double> dnv, glm::dvec3* out) {
    const std::size_t p = static_cast<std::size_t>(surface.degreeU),
                      q = static_cast<std::size_t>(surface.degreeV);
    const glm::dvec3 origin = spanCorner(surface, spanU, spanV, u, v);
    glm::dvec4 h(0.0), hu(0.0), hv(0.0);
    for (std::size_t r = 0; r <= p; ++r) {
        const std::size_t i = spanU - p + r;
        glm::dvec4 row(0.0), rowV(0.0);
        for (std::size_t c = 0; c <= q; ++c) {
            const std::size_t j = spanV - q + c;
            const double wt = surface.weight(i, j);
            const glm::dvec4 pw((surface.point(i, j) - origin) * wt, wt);
            row += nv[c] * pw;
            rowV += dnv[c] * pw;
        }
        h += nu[r] * row;
        hu += dnu[r] * row;
        hv += nu[r] * rowV;
    }
    const glm::dvec3 relative = glm::dvec3(h) / h.w;  // S - origin
    out[1] = (glm::dvec3(hv) - hv.w * relative) / h.w;
    out[2] = (glm::dvec3(hu) - hu.w * relative) / h.w;
}

/// S, and for order 1 also Sv, Su (out as surfaceDerivatives lays it out: S, Sv, Su, 0), in one
/// pass over the span's net: the per-point path most callers take (points, normals).
void firstOrder(const Surface& surface, double u, double v, std::size_t spanU, std::size_t spanV, int order,
                const char* where, glm::dvec3* out) {
    const std::size_t p = static_cast<std::size_t>(surface.degreeU),
                      q = static_cast<std::size_t>(surface.degreeV);
    detail::SmallBuffer<double, 32> nu(p + 1), dnu(p + 1), nv(q + 1), dnv(q + 1);
    if (order == 0) {
        basisFunctions(spanU, u, surface.degreeU, surface.knotsU, nu.span());
        basisFunctions(spanV, v, surface.degreeV, surface.knotsV, nv.span());
        std::fill_n(dnu.span().begin(), p + 1, 0.0);
        std::fill_n(dnv.span().begin(), q + 1, 0.0);
    } else {
        basisWithFirstDerivatives(spanU, u, surface.degreeU, surface.knotsU, nu.span(), dnu.span());
        basisWithFirstDerivatives(spanV, v, surface.degreeV, surface.knotsV, nv.span(), dnv.span());
    }
    glm::dvec4 h(0.0), hu(0.0), hv(0.0);
    if (surface.rational()) {
        for (std::size_t r = 0; r <= p; ++r) {
            const std::size_t i = spanU - p + r;
            glm::dvec4 row(0.0), rowV(0.0);
            for (std::size_t c = 0; c <= q; ++c) {
                const std::size_t j = spanV - q + c;
                const double wt = surface.weights[i * surface.countV + j];
                if (!detail::usableWeight(wt)) weightNotNormal(where, i, j);
                const glm::dvec4 pw(surface.points[i * surface.countV + j] * wt, wt);
                row += nv[c] * pw;
                rowV += dnv[c] * pw;
            }
            h += nu[r] * row;
            hu += dnu[r] * row;
            hv += nu[r] * rowV;
        }
    } else {
        // Polynomial: three coordinates, weight 1.
        glm::dvec3 s(0.0), su(0.0), sv(0.0);
        for (std::size_t r = 0; r <= p; ++r) {
            const glm::dvec3* line = surface.points.data() + (spanU - p + r) * surface.countV + (spanV - q);
            glm::dvec3 row(0.0), rowV(0.0);
            for (std::size_t c = 0; c <= q; ++c) {
                row += nv[c] * line[c];
                rowV += dnv[c] * line[c];
            }
            s += nu[r] * row;
            su += dnu[r] * row;
            sv += nu[r] * rowV;
        }
        h = glm::dvec4(s, 1.0);
        hu = glm::dvec4(su, 0.0);
        hv = glm::dvec4(sv, 0.0);
    }
    out[0] = glm::dvec3(h) / h.w;
    detail::checkResult(out[0], where);
    if (order == 0) return;
    out[1] = (glm::dvec3(hv) - hv.w * out[0]) / h.w;
    out[2] = (glm::dvec3(hu) - hu.w * out[0]) / h.w;
    out[3] = glm::dvec3(0.0);
    if (detail::derivativesMayBeRounding(surface, out[0], out[2], out[1], detail::absoluteSum(dnu.span()),
                                         detail::absoluteSum(dnv.span())))
        firstDerivativesAbout(surface, spanU, spanV, u, v, nu.span(), dnu.span(), nv.span(), dnv.span(), out);
    detail::checkResult(out[1], where);
    detail::checkResult(out[2], where);
}

/// All partial derivatives up to total order into out, (order+1) x (order+1), row k column l.
void surfaceDerivatives(const Surface& surface, double u, double v, int order, const char* where,
                        glm::dvec3* out) {
    detail::checkShape(surface, where);
    const int p = surface.degreeU;
    const int q = surface.degreeV;
    const std::size_t wu = static_cast<std::size_t>(p) + 1;
    const std::size_t wv = static_cast<std::size_t>(q) + 1;
    const int du = std::min(order, p);
    const int dv = std::min(order, q);
    u = detail::checkedParameter(u, surface.domainStartU(), surface.domainEndU(), where, "u");
    v = detail::checkedParameter(v, surface.domainStartV(), surface.domainEndV(), where, "v");
    const std::size_t spanU = hintedSpan(p, surface.knotsU, surface.countU, u);
    const std::size_t spanV = hintedSpan(q, surface.knotsV, surface.countV, v);
    detail::checkSpan(surface.knotsU, spanU, p, where);
    detail::checkSpan(surface.knotsV, spanV, q, where);
    if (order <= 1) return firstOrder(surface, u, v, spanU, spanV, order, where, out);
    detail::SmallBuffer<double, 64> nu(wu * static_cast<std::size_t>(du + 1));
    detail::SmallBuffer<double, 64> nv(wv * static_cast<std::size_t>(dv + 1));
    basisDerivatives(spanU, u, p, surface.knotsU, du, nu.span());
    basisDerivatives(spanV, v, q, surface.knotsV, dv, nv.span());

    // Taken about a corner of the span's net (spanCorner), so that second derivatives next to a
    // collapsed edge (curvature there) keep their digits too; the point is moved back at the end.
    const glm::dvec3 origin = spanCorner(surface, spanU, spanV, u, v);
    const std::size_t side = static_cast<std::size_t>(order) + 1;
    detail::SmallBuffer<glm::dvec4, 16> hom(side * side, glm::dvec4(0.0));
    detail::SmallBuffer<glm::dvec4, 16> temp(wv);
    for (int k = 0; k <= du; ++k) {
        for (std::size_t s = 0; s < wv; ++s) {
            temp[s] = glm::dvec4(0.0);
            for (std::size_t r = 0; r < wu; ++r) {
                const std::size_t i = spanU - static_cast<std::size_t>(p) + r;
                const std::size_t j = spanV - static_cast<std::size_t>(q) + s;
                const double wt = surface.weight(i, j);
                if (!detail::usableWeight(wt)) weightNotNormal(where, i, j);
                temp[s] += nu[static_cast<std::size_t>(k) * wu + r] *
                           glm::dvec4((surface.point(i, j) - origin) * wt, wt);
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
    std::fill_n(out, side * side, glm::dvec3(0.0));
    auto at = [&](int k, int l) -> glm::dvec3& {
        return out[static_cast<std::size_t>(k) * side + static_cast<std::size_t>(l)];
    };
    auto H = [&](int k, int l) -> const glm::dvec4& {
        return hom[static_cast<std::size_t>(k) * side + static_cast<std::size_t>(l)];
    };
    const double w00 = H(0, 0).w;
    for (int k = 0; k <= order; ++k)
        for (int l = 0; l <= order - k; ++l) {
            glm::dvec3 val(H(k, l));
            for (int j = 1; j <= l; ++j) val -= binomial(l, j) * H(0, j).w * at(k, l - j);
            for (int i = 1; i <= k; ++i) {
                val -= binomial(k, i) * H(i, 0).w * at(k - i, l);
                glm::dvec3 v2(0.0);
                for (int j = 1; j <= l; ++j) v2 += binomial(l, j) * H(i, j).w * at(k - i, l - j);
                val -= binomial(k, i) * v2;
            }
            at(k, l) = val / w00;
            detail::checkResult(at(k, l), where);
        }
    at(0, 0) += origin;
    detail::checkResult(at(0, 0), where);
}

/// a over its largest coordinate: the cross product of two such neither overflows nor underflows
/// (a surface of 1e200 or of 1e-200), and has the same direction.
glm::dvec3 unitScaled(const glm::dvec3& a) {
    const double m = detail::largestCoordinate(a);
    return m > 0.0 && std::isfinite(m) ? a / m : a;
}

}  // namespace

glm::dvec3 evaluate(const Curve& curve, double u) {
    glm::dvec3 point;
    curveDerivatives(curve, u, 0, "evaluate", &point);
    return point;
}

std::vector<glm::dvec3> derivatives(const Curve& curve, double u, int order) {
    checkOrder(order, "derivatives");
    std::vector<glm::dvec3> out(static_cast<std::size_t>(order) + 1);
    curveDerivatives(curve, u, order, "derivatives", out.data());
    return out;
}

glm::dvec3 evaluate(const Surface& surface, double u, double v) {
    glm::dvec3 point;
    surfaceDerivatives(surface, u, v, 0, "evaluate", &point);
    return point;
}

SurfaceDerivatives derivatives(const Surface& surface, double u, double v, int order) {
    checkOrder(order, "derivatives");
    SurfaceDerivatives out(order);
    surfaceDerivatives(surface, u, v, order, "derivatives", out.data());
    return out;
}

namespace {

/// Whether `t` is an end of a clamped knot vector (degree p, count coefficients) and which row of
/// coefficients the edge there takes: 0 or count - 1; none otherwise.
std::optional<std::size_t> clampedEdge(const std::vector<double>& knots, int p, std::size_t count, double t) {
    const auto q = static_cast<std::size_t>(p);
    if (t == knots[q] && knots[0] == knots[q]) return 0;
    if (t == knots[count] && knots[count] == knots[count + q]) return count - 1;
    return std::nullopt;
}

/// Whether the edge isocurve at `t` (v when `alongU`: the row of points varying in u) is a pole:
/// its control points in one place to 1e-6 of their size or of their distance to the next row (a
/// C program's Pfloat grid leaves them apart by single-precision rounding, and Su there a
/// derivative of that size in a direction of no meaning).
bool poleRow(const Surface& s, bool alongU, double t) {
    const std::optional<std::size_t> edge = alongU ? clampedEdge(s.knotsV, s.degreeV, s.countV, t)
                                                   : clampedEdge(s.knotsU, s.degreeU, s.countU, t);
    if (!edge) return false;
    const std::size_t n = alongU ? s.countU : s.countV, other = alongU ? s.countV : s.countU;
    const std::size_t next = *edge == 0 ? 1 : *edge - 1;
    auto at = [&](std::size_t k, std::size_t row) { return alongU ? s.point(k, row) : s.point(row, k); };
    const glm::dvec3 first = at(0, *edge);
    double spread = 0.0, size = detail::largestCoordinate(first);
    for (std::size_t k = 0; k < n; ++k) {
        spread = std::max(spread, detail::largestCoordinate(at(k, *edge) - first));
        if (other > 1) size = std::max(size, detail::largestCoordinate(at(k, next) - at(k, *edge)));
    }
    return spread <= 1e-6 * size;
}

/// The normal on a collapsed edge (a pole row): next to an edge where Su vanishes, Su(u, v + h)
/// = h Suv + O(h^2), so the normals tend to Suv x Sv, taken towards the inside of the domain
/// (dirV), exactly rather than by stepping inside; likewise Su x Suv where Sv vanishes. Su
/// vanishes where it is below 1e-12 of Sv (rounding) or on a pole row (poleRow). Zero where
/// neither vanishes, or the limit does not decide either.
glm::dvec3 collapsedEdgeNormal(const Surface& surface, double u, double v, double dirU, double dirV) {
    const SurfaceDerivatives d = derivatives(surface, u, v, 2);
    const glm::dvec3 su = unitScaled(d.at(1, 0)), sv = unitScaled(d.at(0, 1)), suv = d.at(1, 1);
    const double lu = glm::length(d.at(1, 0)), lv = glm::length(d.at(0, 1));
    glm::dvec3 a(0.0), b(0.0);
    if (lu <= 1e-12 * lv || poleRow(surface, true, v))
        a = dirV * unitScaled(suv), b = sv;
    else if (lv <= 1e-12 * lu || poleRow(surface, false, u))
        a = su, b = dirU * unitScaled(suv);
    const glm::dvec3 m = glm::cross(a, b);
    const double ml = glm::length(m);
    return ml > 1e-8 * glm::length(a) * glm::length(b) && std::isfinite(ml) ? m / ml : glm::dvec3(0.0);
}

/// Whether neither derivative is below 1e-6 of the other (by largest coordinate, which neither
/// overflows nor underflows): below it, the smaller may be rounding noise (see
/// normalFromDerivatives). False for NaN.
bool comparable(const glm::dvec3& su, const glm::dvec3& sv) {
    const double a = detail::largestCoordinate(su), b = detail::largestCoordinate(sv);
    return std::min(a, b) > 1e-6 * std::max(a, b);
}

/// Su x Sv normalized, or zero where |Su x Sv| <= 1e-12 |Su| |Sv|. Compared squared: one square
/// root a point instead of three. Where the product overflows or underflows (derivatives of 1e150
/// or 1e-150), the scaled ones decide.
glm::dvec3 crossNormal(const glm::dvec3& su, const glm::dvec3& sv) {
    for (const bool scaled : {false, true}) {
        const glm::dvec3 a = scaled ? unitScaled(su) : su, b = scaled ? unitScaled(sv) : sv;
        const glm::dvec3 n = glm::cross(a, b);
        const double len2 = glm::dot(n, n);
        if (len2 > 1e-24 * glm::dot(a, a) * glm::dot(b, b) && len2 > 0.0 && std::isfinite(len2))
            return n / std::sqrt(len2);
    }
    return glm::dvec3(0.0);
}

/// Whether (u, v) lies on a pole row of the surface (poleRow), for a valid surface.
bool onPoleRow(const Surface& surface, double u, double v) {
    if (surface.knotsU.size() != surface.countU + surface.degreeU + 1 ||
        surface.knotsV.size() != surface.countV + surface.degreeV + 1 ||
        surface.points.size() != surface.countU * surface.countV)
        return false;
    return poleRow(surface, true, v) || poleRow(surface, false, u);
}

}  // namespace

glm::dvec3 normalFromDerivatives(const Surface& surface, double u, double v, const glm::dvec3& su,
                                 const glm::dvec3& sv) {
    // On a domain edge the derivatives may be comparable and still mean nothing (a pole row whose
    // points agree to single precision far from the origin): those go the long way.
    const bool edge = u == surface.domainStartU() || u == surface.domainEndU() ||
                      v == surface.domainStartV() || v == surface.domainEndV();
    if (const glm::dvec3 n = crossNormal(su, sv);
        comparable(su, sv) && n != glm::dvec3(0.0) && (!edge || !onPoleRow(surface, u, v)))
        return n;
    // Only the degenerate case reads the surface.
    detail::checkShape(surface, "normalFromDerivatives");
    u = detail::checkedParameter(u, surface.domainStartU(), surface.domainEndU(), "normalFromDerivatives",
                                 "u");
    v = detail::checkedParameter(v, surface.domainStartV(), surface.domainEndV(), "normalFromDerivatives",
                                 "v");
    // One derivative far smaller than the other: next to a collapsed edge, where a path that sums
    // the control points themselves (a patch tree, at any scale but about 1) leaves rounding noise
    // of arbitrary direction in the vanishing one. The per-point path takes them about a control
    // point and keeps their digits; the answer is then the one normal() gives.
    // A collapsed edge first: it answers only where one of those vanishes against the other
    // (collapsedEdgeNormal: rounding, or a pole row agreeing to single precision).
    const double u0 = surface.domainStartU(), u1 = surface.domainEndU();
    const double v0 = surface.domainStartV(), v1 = surface.domainEndV();
    const double dirU = (u - u0) <= (u1 - u) ? 1.0 : -1.0;
    const double dirV = (v - v0) <= (v1 - v) ? 1.0 : -1.0;
    if (const glm::dvec3 n = collapsedEdgeNormal(surface, u, v, dirU, dirV); n != glm::dvec3(0.0)) return n;
    const SurfaceDerivatives exact = derivatives(surface, u, v, 1);
    if (const glm::dvec3 n = crossNormal(exact.at(1, 0), exact.at(0, 1)); n != glm::dvec3(0.0)) return n;
    // Elsewhere: step towards the inside of the domain along the diagonal and take the limit of
    // the normals there.
    for (double t = 1e-7; t <= 1e-3; t *= 10.0) {
        const double uu = clampTo(u + dirU * t * (u1 - u0), u0, u1);
        const double vv = clampTo(v + dirV * t * (v1 - v0), v0, v1);
        const SurfaceDerivatives d = derivatives(surface, uu, vv, 1);
        const glm::dvec3 du = unitScaled(d.at(1, 0)), dv = unitScaled(d.at(0, 1));
        const glm::dvec3 m = glm::cross(du, dv);
        const double ml = glm::length(m);
        if (ml > 1e-12 * glm::length(du) * glm::length(dv) && ml > 0.0) return m / ml;
    }
    return glm::dvec3(0.0);
}

glm::dvec3 normal(const Surface& surface, double u, double v) {
    glm::dvec3 d[4];  // row k, column l of order 1: S, Sv, Su, Suv
    surfaceDerivatives(surface, u, v, 1, "normal", d);
    return normalFromDerivatives(surface, u, v, d[2], d[1]);
}

void SurfaceDerivatives::rejectOrder(int order) {
    checkOrder(order, "SurfaceDerivatives");
}

}  // namespace geom
