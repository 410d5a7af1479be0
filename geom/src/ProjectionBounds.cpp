#include "ProjectionBounds.h"

#include "geom/BoundingBox.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace geom::detail {
namespace {

/// The sign of (S - p) . S_u over a polynomial Bézier piece with net points c, +1 or -1 where
/// the net proves it, else 0: S - p lies in the hull of the points c - p, and S_u is a positive
/// combination of the net's differences along u. alongV swaps the roles of u and v.
int polynomialGradientSign(const std::vector<glm::dvec3>& c, std::size_t pu, std::size_t qv, bool alongV,
                           const glm::dvec3& p) {
    const std::size_t lines = alongV ? qv : pu, across = alongV ? pu : qv;
    auto at = [&](std::size_t line, std::size_t k) { return alongV ? c[k * qv + line] : c[line * qv + k]; };
    int sign = 0;
    for (std::size_t i = 0; i + 1 < lines; ++i)
        for (std::size_t k = 0; k < across; ++k) {
            const glm::dvec3 a = at(i + 1, k) - at(i, k);
            for (const glm::dvec3& q : c) {
                const double d = glm::dot(a, q - p);
                const int here = d > 0.0 ? 1 : (d < 0.0 ? -1 : 0);
                if (here == 0 || (sign != 0 && here != sign)) return 0;
                sign = here;
            }
        }
    return sign;
}

/// A closed interval of reals, for bounding a rational piece's derivative.
struct ValueRange {
    double lo, hi;
};
ValueRange operator*(ValueRange a, ValueRange b) {
    const double x = a.lo * b.lo, y = a.lo * b.hi, z = a.hi * b.lo, w = a.hi * b.hi;
    return {std::min({x, y, z, w}), std::max({x, y, z, w})};
}
ValueRange operator-(ValueRange a, ValueRange b) {
    return {a.lo - b.hi, a.hi - b.lo};
}
ValueRange operator+(ValueRange a, ValueRange b) {
    return {a.lo + b.lo, a.hi + b.hi};
}

/// The homogeneous net with its points taken about `origin` (X - origin w, w), in a buffer of the
/// thread's own: the bounds below read each point several times.
const glm::dvec4* aboutOrigin(const glm::dvec4* h, std::size_t count, const glm::dvec3& origin) {
    thread_local std::vector<glm::dvec4> moved;
    moved.resize(count);
    for (std::size_t k = 0; k < count; ++k) moved[k] = glm::dvec4(glm::dvec3(h[k]) - origin * h[k].w, h[k].w);
    return moved.data();
}

/// The range of each coordinate of the points c less `offset`.
std::array<ValueRange, 3> pointRanges(const std::vector<glm::dvec3>& c, const glm::dvec3& offset) {
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const glm::dvec3& q : c) lo = glm::min(lo, q), hi = glm::max(hi, q);
    lo -= offset, hi -= offset;
    return {ValueRange{lo.x, hi.x}, ValueRange{lo.y, hi.y}, ValueRange{lo.z, hi.z}};
}

/// gradientSign for a rational piece with homogeneous net h and points c: S_u = (X_u w - X w_u)
/// / w^2 bounded coordinate by coordinate from the ranges of the net and of its differences.
int rationalGradientSign(const glm::dvec4* h, const std::vector<glm::dvec3>& c, std::size_t pu,
                         std::size_t qv, bool alongV, const glm::dvec3& p) {
    const std::size_t lines = alongV ? qv : pu, across = alongV ? pu : qv;
    const glm::dvec3 origin = c[0];  // as in provablyConvex
    const glm::dvec4* moved = aboutOrigin(h, pu * qv, origin);
    auto at = [&](std::size_t line, std::size_t k) {
        return alongV ? moved[k * qv + line] : moved[line * qv + k];
    };
    const double inf = std::numeric_limits<double>::infinity();
    ValueRange x[4], dx[4];
    for (int m = 0; m < 4; ++m) x[m] = dx[m] = {inf, -inf};
    for (std::size_t i = 0; i < lines; ++i)
        for (std::size_t k = 0; k < across; ++k) {
            const glm::dvec4 a = at(i, k);
            const glm::dvec4 d = i + 1 < lines ? at(i + 1, k) - a : glm::dvec4(0.0);
            for (int m = 0; m < 4; ++m) {
                x[m] = {std::min(x[m].lo, a[m]), std::max(x[m].hi, a[m])};
                if (i + 1 < lines) dx[m] = {std::min(dx[m].lo, d[m]), std::max(dx[m].hi, d[m])};
            }
        }
    ValueRange g{0.0, 0.0};
    const std::array<ValueRange, 3> toPoint = pointRanges(c, p);
    for (int m = 0; m < 3; ++m) {
        // The sign of S_u is that of X_u w - X w_u (w > 0); scale does not matter.
        const ValueRange derivative = dx[m] * x[3] - x[m] * dx[3];
        g = g + derivative * toPoint[static_cast<std::size_t>(m)];
    }
    return g.lo > 0.0 ? 1 : (g.hi < 0.0 ? -1 : 0);
}

ValueRange operator/(ValueRange a, ValueRange positive) {
    return a * ValueRange{1.0 / positive.hi, 1.0 / positive.lo};
}
ValueRange operator*(double k, ValueRange a) {
    return k >= 0.0 ? ValueRange{k * a.lo, k * a.hi} : ValueRange{k * a.hi, k * a.lo};
}
ValueRange square(ValueRange a) {
    const double lo = a.lo > 0.0 ? a.lo * a.lo : (a.hi < 0.0 ? a.hi * a.hi : 0.0);
    return {lo, std::max(a.lo * a.lo, a.hi * a.hi)};
}

/// The range of each homogeneous coordinate of a net's (i, j) -> value(i, j) over the net.
template <class F>
std::array<ValueRange, 4> range(std::size_t rows, std::size_t columns, F&& value) {
    const double inf = std::numeric_limits<double>::infinity();
    std::array<ValueRange, 4> r;
    r.fill({inf, -inf});
    if (rows == 0 || columns == 0) r.fill({0.0, 0.0});
    for (std::size_t i = 0; i < rows; ++i)
        for (std::size_t j = 0; j < columns; ++j) {
            const glm::dvec4 x = value(i, j);
            for (int m = 0; m < 4; ++m) r[m] = {std::min(r[m].lo, x[m]), std::max(r[m].hi, x[m])};
        }
    return r;
}

}  // namespace

void halveLine(const glm::dvec4* in, std::size_t stride, std::size_t n, glm::dvec4* left, glm::dvec4* right,
               std::vector<glm::dvec4>& work) {
    work.resize(n);
    for (std::size_t k = 0; k < n; ++k) work[k] = in[k * stride];
    left[0] = work[0];
    right[(n - 1) * stride] = work[n - 1];
    for (std::size_t r = 1; r < n; ++r) {
        for (std::size_t i = 0; i + r < n; ++i) work[i] = 0.5 * (work[i] + work[i + 1]);
        left[r * stride] = work[0];
        right[(n - 1 - r) * stride] = work[n - 1 - r];
    }
}

void project(const glm::dvec4* net, std::size_t count, std::vector<glm::dvec3>& points) {
    points.resize(count);
    for (std::size_t k = 0; k < count; ++k) points[k] = glm::dvec3(net[k]) / net[k].w;
}

std::size_t nearestPoint(const std::vector<glm::dvec3>& c, const glm::dvec3& p) {
    std::size_t nearest = 0;
    double nearestDistance = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < c.size(); ++k) {
        const double d = glm::dot(c[k] - p, c[k] - p);
        if (d < nearestDistance) {
            nearestDistance = d;
            nearest = k;
        }
    }
    return nearest;
}

double lowerBound(const std::vector<glm::dvec3>& c, const glm::dvec3& p, const glm::dvec3* toward) {
    BoundingBox box;
    double along = std::numeric_limits<double>::infinity();
    for (const glm::dvec3& q : c) {
        box.add(q);
        if (toward) along = std::min(along, glm::dot(q - p, *toward));
    }
    const double d = box.distance(p);
    return toward ? std::max(d, along) : d;
}

// The Hessian of |S - p|^2 / 2 bounded by interval arithmetic on the ranges of the net and of its
// differences (the derivatives of the rational point by the quotient rule), then shown positive
// definite everywhere.
bool provablyConvex(const glm::dvec4* h, const std::vector<glm::dvec3>& c, std::size_t pu, std::size_t qv,
                    const glm::dvec3& p) {
    // Taken about the piece's first point: the quotient rule's terms then stay as small as the piece.
    const glm::dvec3 origin = c[0];
    const glm::dvec4* moved = aboutOrigin(h, pu * qv, origin);
    auto at = [&](std::size_t i, std::size_t j) { return moved[i * qv + j]; };
    const double nu = static_cast<double>(pu - 1), nv = static_cast<double>(qv - 1);
    const auto x = range(pu, qv, at);
    const auto xu =
        range(pu - 1, qv, [&](std::size_t i, std::size_t j) { return nu * (at(i + 1, j) - at(i, j)); });
    const auto xv =
        range(pu, qv - 1, [&](std::size_t i, std::size_t j) { return nv * (at(i, j + 1) - at(i, j)); });
    const auto xuu = range(pu >= 3 ? pu - 2 : 0, qv, [&](std::size_t i, std::size_t j) {
        return nu * (nu - 1.0) * (at(i + 2, j) - 2.0 * at(i + 1, j) + at(i, j));
    });
    const auto xvv = range(pu, qv >= 3 ? qv - 2 : 0, [&](std::size_t i, std::size_t j) {
        return nv * (nv - 1.0) * (at(i, j + 2) - 2.0 * at(i, j + 1) + at(i, j));
    });
    const auto xuv = range(pu - 1, qv - 1, [&](std::size_t i, std::size_t j) {
        return nu * nv * (at(i + 1, j + 1) - at(i + 1, j) - at(i, j + 1) + at(i, j));
    });
    const ValueRange w = x[3];
    if (!(w.lo > 0.0)) return false;
    ValueRange huu{0.0, 0.0}, huv{0.0, 0.0}, hvv{0.0, 0.0};
    const std::array<ValueRange, 3> points = pointRanges(c, origin);
    for (int m = 0; m < 3; ++m) {
        const ValueRange point = points[static_cast<std::size_t>(m)];
        const ValueRange su = (xu[m] - xu[3] * point) / w;
        const ValueRange sv = (xv[m] - xv[3] * point) / w;
        const ValueRange suu = (xuu[m] - 2.0 * (xu[3] * su) - xuu[3] * point) / w;
        const ValueRange svv = (xvv[m] - 2.0 * (xv[3] * sv) - xvv[3] * point) / w;
        const ValueRange suv = (xuv[m] - xu[3] * sv - xv[3] * su - xuv[3] * point) / w;
        const ValueRange r{point.lo - (p[m] - origin[m]), point.hi - (p[m] - origin[m])};
        huu = huu + square(su) + r * suu;
        hvv = hvv + square(sv) + r * svv;
        huv = huv + su * sv + r * suv;
    }
    if (qv == 1) return huu.lo > 0.0;
    const double cross = std::max(huv.lo * huv.lo, huv.hi * huv.hi);
    return huu.lo > 0.0 && hvv.lo > 0.0 && huu.lo * hvv.lo > cross;
}

bool provablyFarther(const glm::dvec4* h, std::size_t pu, std::size_t qv, const glm::dvec3& p,
                     double distance) {
    // Bernstein products: B_i^n B_j^n = C(n,i) C(n,j) / C(2n,i+j) B_{i+j}^{2n}, in each direction;
    // only the signs of the coefficients matter, so the positive C(2n,i+j) is left out.
    auto binomial = [](std::size_t n, std::size_t k) {
        double r = 1.0;
        for (std::size_t i = 1; i <= k; ++i) r = r * static_cast<double>(n - k + i) / static_cast<double>(i);
        return r;
    };
    const std::size_t nu = pu - 1, nv = qv - 1, ku = 2 * nu + 1, kv = 2 * nv + 1;
    constexpr std::size_t kMax = 16;
    if (pu > kMax || qv > kMax) return false;
    double cu[kMax], cv[kMax];
    for (std::size_t i = 0; i <= nu; ++i) cu[i] = binomial(nu, i);
    for (std::size_t j = 0; j <= nv; ++j) cv[j] = binomial(nv, j);
    // Each net point relative to p, scaled by its binomial weights: the product's terms are then
    // dot products, each pair of points met once (the product is symmetric); the term of a pair
    // is 2 (a . b - m^2 a.w b.w), the dot of (2 a, -2 m^2 a.w) with b.
    thread_local std::vector<glm::dvec4> y;
    thread_local std::vector<double> g;
    const std::size_t count = pu * qv;
    y.resize(count);
    for (std::size_t k = 0; k < count; ++k)
        y[k] = cu[k / qv] * cv[k % qv] * glm::dvec4(glm::dvec3(h[k]) - p * h[k].w, h[k].w);
    g.assign(ku * kv, 0.0);
    const double m2 = distance * distance;
    for (std::size_t i = 0; i <= nu; ++i)
        for (std::size_t j = 0; j <= nv; ++j) {
            const glm::dvec4 a = y[i * qv + j];
            const glm::dvec4 twice(2.0 * glm::dvec3(a), -2.0 * m2 * a.w);
            g[2 * i * kv + 2 * j] += glm::dot(glm::dvec3(a), glm::dvec3(a)) - m2 * a.w * a.w;
            for (std::size_t j2 = j + 1; j2 <= nv; ++j2)
                g[2 * i * kv + j + j2] += glm::dot(twice, y[i * qv + j2]);
            for (std::size_t i2 = i + 1; i2 <= nu; ++i2)
                for (std::size_t j2 = 0; j2 <= nv; ++j2)
                    g[(i + i2) * kv + j + j2] += glm::dot(twice, y[i2 * qv + j2]);
        }
    for (std::size_t k = 0; k < ku; ++k)
        for (std::size_t l = 0; l < kv; ++l)
            if (g[k * kv + l] < 0.0) return false;
    return true;
}

int gradientSign(const glm::dvec4* h, const std::vector<glm::dvec3>& c, std::size_t pu, std::size_t qv,
                 bool rational, bool alongV, const glm::dvec3& p) {
    return rational ? rationalGradientSign(h, c, pu, qv, alongV, p)
                    : polynomialGradientSign(c, pu, qv, alongV, p);
}

double departureFromEdge(const glm::dvec4* h, const std::vector<glm::dvec3>& c, std::size_t pu,
                         std::size_t qv, bool alongV) {
    // The edge point of net point (i, j), and the weight factors a_i = w_i0, b_j = w_0j / w_00
    // (alongV; the roles swap otherwise), exact on the edge and the first line.
    BoundingBox box;
    double spread = 0.0, weights = 0.0;
    for (std::size_t i = 0; i < pu; ++i)
        for (std::size_t j = 0; j < qv; ++j) {
            const std::size_t k = i * qv + j, edge = alongV ? i * qv : j;
            box.add(c[k]);
            spread = std::max(spread, glm::distance(c[k], c[edge]));
            const double product = h[i * qv].w * h[j].w / h[0].w;
            weights = std::max(weights, std::abs(h[k].w / product - 1.0));
        }
    const double departure = spread + 2.0 * weights * box.diagonal();
    return std::isfinite(departure) ? departure : std::numeric_limits<double>::infinity();
}

}  // namespace geom::detail
