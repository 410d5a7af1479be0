#pragma once

// Private to geom: the dense pieces shared by least-squares knot removal and data reduction.

#include "geom/Basis.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace geom::detail {

// Least squares min |M x - B| for a dense rows x cols matrix (row-major) and `width` right-hand
// sides (row-major rows x width) by Householder QR; returns cols x width. M must have full column
// rank, which the knot insertion matrix has.
inline std::vector<double> solveLeastSquares(std::vector<double> m, std::size_t rows, std::size_t cols,
                                             std::vector<double> b, std::size_t width) {
    for (std::size_t k = 0; k < cols; ++k) {
        double norm = 0.0;
        for (std::size_t i = k; i < rows; ++i) norm += m[i * cols + k] * m[i * cols + k];
        norm = std::sqrt(norm);
        if (norm == 0.0) throw GeometryError("removeKnotsLeastSquares: the local fit is rank deficient");
        const double alpha = m[k * cols + k] > 0.0 ? -norm : norm;
        std::vector<double> v(rows - k);
        for (std::size_t i = k; i < rows; ++i) v[i - k] = m[i * cols + k];
        v[0] -= alpha;
        double vv = 0.0;
        for (double x : v) vv += x * x;
        if (vv == 0.0) continue;
        for (std::size_t c = k; c < cols; ++c) {
            double dot = 0.0;
            for (std::size_t i = k; i < rows; ++i) dot += v[i - k] * m[i * cols + c];
            const double f = 2.0 * dot / vv;
            for (std::size_t i = k; i < rows; ++i) m[i * cols + c] -= f * v[i - k];
        }
        for (std::size_t c = 0; c < width; ++c) {
            double dot = 0.0;
            for (std::size_t i = k; i < rows; ++i) dot += v[i - k] * b[i * width + c];
            const double f = 2.0 * dot / vv;
            for (std::size_t i = k; i < rows; ++i) b[i * width + c] -= f * v[i - k];
        }
    }
    std::vector<double> x(cols * width, 0.0);
    for (std::size_t k = cols; k-- > 0;)
        for (std::size_t c = 0; c < width; ++c) {
            double s = b[k * width + c];
            for (std::size_t j = k + 1; j < cols; ++j) s -= m[k * cols + j] * x[j * width + c];
            x[k * width + c] = s / m[k * cols + k];
        }
    return x;
}

// The knot insertion matrix of a local spline: rows[i][c] is the weight of coefficient c of
// the spline on knots u (degree p, u.size() - p - 1 coefficients) in coefficient i of the same
// spline after inserting `values` (ascending, inside [u[p], u[n]) ), one Boehm step each. u is
// refined in place.
inline std::vector<std::vector<double>> insertionRows(int degree, std::vector<double>& u,
                                                      const std::vector<double>& values, const char* where) {
    const std::size_t p = static_cast<std::size_t>(degree);
    const std::size_t nl = u.size() - p - 1;
    std::vector<std::vector<double>> rows(nl, std::vector<double>(nl, 0.0));
    for (std::size_t i = 0; i < nl; ++i) rows[i][i] = 1.0;
    for (double x : values) {
        const std::size_t n = rows.size();
        if (!(x >= u[p] && x < u[n])) throw GeometryError(std::string(where) + ": internal window error");
        const std::size_t k =
            static_cast<std::size_t>(std::upper_bound(u.begin(), u.end(), x) - u.begin()) - 1;
        std::size_t s = 0;
        for (std::size_t i = k + 1; i-- > 0 && u[i] == x;) ++s;
        std::vector<std::vector<double>> next(n + 1);
        for (std::size_t i = 0; i <= k - p; ++i) next[i] = rows[i];
        for (std::size_t i = k - s + 1; i <= n; ++i) next[i] = rows[i - 1];
        for (std::size_t i = k - p + 1; i + s <= k; ++i) {
            const double alpha = (x - u[i]) / (u[i + p] - u[i]);
            next[i].assign(nl, 0.0);
            for (std::size_t c = 0; c < nl; ++c)
                next[i][c] = alpha * rows[i][c] + (1.0 - alpha) * rows[i - 1][c];
        }
        rows = std::move(next);
        u.insert(u.begin() + static_cast<std::ptrdiff_t>(k + 1), x);
    }
    return rows;
}

// Row j of the knot insertion matrix from coarse knots tau (nTau coefficients) to fine knots t
// (t contains tau): the weights of coarse coefficients mu-p .. mu in fine coefficient j, by the
// Oslo algorithm (the coarse B-splines' blossoms at t[j+1..j+p], a Cox-de Boor triangle whose
// levels take successive fine knots). Writes p+1 weights to out and returns mu.
inline std::size_t osloRow(int degree, const std::vector<double>& tau, std::size_t nTau,
                           const std::vector<double>& t, std::size_t j, double* out) {
    const std::size_t p = static_cast<std::size_t>(degree);
    // tau[mu] <= t[j] < tau[mu+1] on a non-empty span inside [p, nTau-1].
    std::size_t mu = static_cast<std::size_t>(std::upper_bound(tau.begin(), tau.end(), t[j]) - tau.begin());
    mu = mu == 0 ? 0 : mu - 1;
    mu = std::clamp(mu, p, nTau - 1);
    while (mu > p && !(tau[mu] < tau[mu + 1])) --mu;
    out[0] = 1.0;
    for (std::size_t level = 1; level <= p; ++level) {
        const double x = t[j + level];
        double saved = 0.0;
        for (std::size_t r = 0; r < level; ++r) {
            const double hi = tau[mu + r + 1], lo = tau[mu + r + 1 - level];
            const double temp = hi > lo ? out[r] / (hi - lo) : 0.0;
            out[r] = saved + (hi - x) * temp;
            saved = (x - lo) * temp;
        }
        out[level] = saved;
    }
    return mu;
}

// Values of a polynomial spline (degree, knots, count coefficients) at ascending parameters
// inside its domain, walking the spans instead of searching for each one.
inline void evaluateAscending(int degree, const std::vector<double>& knots, const glm::dvec3* points,
                              std::size_t count, std::span<const double> params, glm::dvec3* out) {
    const std::size_t p = static_cast<std::size_t>(degree);
    double basis[32];
    std::vector<double> heap;
    double* nb = basis;
    if (p + 1 > 32) heap.resize(p + 1), nb = heap.data();
    std::size_t span = p;
    for (std::size_t i = 0; i < params.size(); ++i) {
        const double u = params[i];
        if (i > 0 && u < params[i - 1]) span = p;
        while (span + 1 < count && knots[span + 1] <= u) ++span;
        basisFunctions(span, u, degree, knots, std::span<double>(nb, p + 1));
        glm::dvec3 c(0.0);
        for (std::size_t k = 0; k <= p; ++k) c += nb[k] * points[span - p + k];
        out[i] = c;
    }
}

// The distance from target to a polynomial spline found by Newton from parameter u, never more
// than `bound` (the caller's distance to a known point of the spline). Every distance it takes
// is to a real point of the spline, so the answer bounds the true closest distance from above.
inline double newtonDistance(int degree, const std::vector<double>& knots, const glm::dvec3* points,
                             std::size_t count, const glm::dvec3& target, double u, double bound,
                             double* foot = nullptr) {
    const std::size_t p = static_cast<std::size_t>(degree);
    const double lo = knots[p], hi = knots[count];
    std::vector<double> ders(3 * (p + 1));
    double best = bound;
    for (int it = 0; it < 8; ++it) {
        const std::size_t span = findSpan(degree, knots, count, u);
        basisDerivatives(span, u, degree, knots, 2, ders);
        glm::dvec3 c(0.0), d1(0.0), d2(0.0);
        for (std::size_t k = 0; k <= p; ++k) {
            const glm::dvec3& q = points[span - p + k];
            c += ders[k] * q;
            d1 += ders[p + 1 + k] * q;
            d2 += ders[2 * (p + 1) + k] * q;
        }
        const glm::dvec3 r = c - target;
        if (glm::length(r) < best) {
            best = glm::length(r);
            if (foot) *foot = u;
        }
        double h = glm::dot(d1, d1) + glm::dot(r, d2);
        if (h <= 1e-6 * glm::dot(d1, d1)) h = glm::dot(d1, d1);
        if (!(h > 0.0)) break;
        const double next = std::clamp(u - glm::dot(r, d1) / h, lo, hi);
        if (std::abs(next - u) <= 1e-15 * (hi - lo)) break;
        u = next;
    }
    return best;
}

// Solves the symmetric positive definite banded system N x = b in place by Cholesky: N is n x n
// with half bandwidth w, stored by rows as band[i * (w + 1) + k] = N(i, i + k); b has n rows of
// glm::dvec3. Returns false when N is not positive definite.
inline bool solveBanded(std::vector<double>& band, std::size_t n, std::size_t w, std::vector<glm::dvec3>& b) {
    const std::size_t wb = w + 1;
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t k0 = i > w ? i - w : 0;
        double d = band[i * wb];
        for (std::size_t k = k0; k < i; ++k) d -= band[k * wb + (i - k)] * band[k * wb + (i - k)];
        if (!(d > 0.0)) return false;
        d = std::sqrt(d);
        band[i * wb] = d;
        for (std::size_t j = i + 1; j <= std::min(n - 1, i + w); ++j) {
            double s = band[i * wb + (j - i)];
            const std::size_t kj = j > w ? j - w : 0;
            for (std::size_t k = std::max(k0, kj); k < i; ++k)
                s -= band[k * wb + (i - k)] * band[k * wb + (j - k)];
            band[i * wb + (j - i)] = s / d;
        }
    }
    for (std::size_t i = 0; i < n; ++i) {  // U^T y = b
        glm::dvec3 s = b[i];
        for (std::size_t k = i > w ? i - w : 0; k < i; ++k) s -= band[k * wb + (i - k)] * b[k];
        b[i] = s / band[i * wb];
    }
    for (std::size_t i = n; i-- > 0;) {  // U x = y
        glm::dvec3 s = b[i];
        for (std::size_t j = i + 1; j <= std::min(n - 1, i + w); ++j) s -= band[i * wb + (j - i)] * b[j];
        b[i] = s / band[i * wb];
    }
    return true;
}

}  // namespace geom::detail
