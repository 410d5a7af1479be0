#pragma once

// Private to geom: the dense pieces shared by least-squares knot removal and data reduction.

#include "geom/Basis.h"
#include "geom/GeometryError.h"
#include "geom/KnotRemoval.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace geom::detail {

// removeKnotsLeastSquares without the local fit: the new knots, the window, and the old
// coefficients in it as placeholders, for a caller that refits the window itself.
LeastSquaresRemoval removalWindow(int degree, std::span<const double> knots,
                                  std::span<const glm::dvec3> points, std::size_t sequences,
                                  std::span<const double> values, const EndConditions& ends, int margin);

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
inline std::size_t osloRowAt(int degree, const std::vector<double>& tau, const std::vector<double>& t,
                             std::size_t j, std::size_t mu, double* out);
inline std::size_t osloRow(int degree, const std::vector<double>& tau, std::size_t nTau,
                           const std::vector<double>& t, std::size_t j, double* out) {
    const std::size_t p = static_cast<std::size_t>(degree);
    // tau[mu] <= t[j] < tau[mu+1] on a non-empty span inside [p, nTau-1].
    std::size_t mu = static_cast<std::size_t>(std::upper_bound(tau.begin(), tau.end(), t[j]) - tau.begin());
    mu = mu == 0 ? 0 : mu - 1;
    mu = std::clamp(mu, p, nTau - 1);
    while (mu > p && !(tau[mu] < tau[mu + 1])) --mu;
    return osloRowAt(degree, tau, t, j, mu, out);
}

// osloRow with the span mu already found (a caller walking ascending t finds it cheaper).
inline std::size_t osloRowAt(int degree, const std::vector<double>& tau, const std::vector<double>& t,
                             std::size_t j, std::size_t mu, double* out) {
    const std::size_t p = static_cast<std::size_t>(degree);
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

// The reciprocals of the coarse knot differences osloRowAt divides by for span mu, level by
// level (level l, entry r at l (l - 1) / 2 + r; 0 for an empty difference): rows of the same span
// share them, and multiply where osloRowAt divides. inverse holds p (p + 1) / 2 entries.
inline void osloInverses(std::size_t degree, const std::vector<double>& tau, std::size_t mu,
                         double* inverse) {
    for (std::size_t level = 1, at = 0; level <= degree; ++level)
        for (std::size_t r = 0; r < level; ++r, ++at) {
            const double hi = tau[mu + r + 1], lo = tau[mu + r + 1 - level];
            inverse[at] = hi > lo ? 1.0 / (hi - lo) : 0.0;
        }
}

// osloRowAt with span mu's osloInverses (the same row up to rounding), the degree fixed at
// compile time where P > 0 (the loops unroll), any degree where P = 0.
template <std::size_t P>
inline void osloRowInverse(std::size_t degree, const std::vector<double>& tau, const std::vector<double>& t,
                           std::size_t j, std::size_t mu, const double* inverse, double* out) {
    const std::size_t d = P > 0 ? P : degree;
    out[0] = 1.0;
#pragma GCC unroll 8
    for (std::size_t level = 1; level <= d; ++level) {
        const double x = t[j + level];
        double saved = 0.0;
#pragma GCC unroll 8
        for (std::size_t r = 0; r < level; ++r) {
            const double hi = tau[mu + r + 1], lo = tau[mu + r + 1 - level];
            const double temp = out[r] * inverse[(level - 1) * level / 2 + r];
            out[r] = saved + (hi - x) * temp;
            saved = (x - lo) * temp;
        }
        out[level] = saved;
    }
}

// The largest degree the span power forms below take; higher degrees use Basis.h.
constexpr std::size_t smallDegree = 7;

// Calls f(std::integral_constant<std::size_t, P>{}) with P = degree for degrees 1 to
// smallDegree, whose loops the callers' templates unroll, and P = 0 (any degree) for the others.
template <class F>
inline void withFixedDegree(std::size_t degree, F&& f) {
    switch (degree) {
        case 1:
            return f(std::integral_constant<std::size_t, 1>{});
        case 2:
            return f(std::integral_constant<std::size_t, 2>{});
        case 3:
            return f(std::integral_constant<std::size_t, 3>{});
        case 4:
            return f(std::integral_constant<std::size_t, 4>{});
        case 5:
            return f(std::integral_constant<std::size_t, 5>{});
        case 6:
            return f(std::integral_constant<std::size_t, 6>{});
        case 7:
            return f(std::integral_constant<std::size_t, 7>{});
        default:
            return f(std::integral_constant<std::size_t, 0>{});
    }
}

// The polynomial of one non-empty span in powers of s = (u - knots[span]) / (span length): the
// Bezier points are blossoms (de Boor with a or b at each level), then the power coefficients
// are their binomial differences. Horner on these is several times cheaper than Cox-de Boor
// per point when a span holds several samples.
// P > 0 fixes the degree at compile time (p must equal it), which lets the loops unroll.
template <std::size_t P = 0>
inline void spanPowerForm(std::size_t span, std::size_t degree, const double* knots, const glm::dvec3* points,
                          glm::dvec3* power) {
    const std::size_t p = P > 0 ? P : degree;
    // The loops below are unrolled for the degrees fixed at compile time; the bound (callers
    // take Basis.h above it) lets the compiler see that any degree stays inside the arrays.
    if (p > smallDegree) return;
    static constexpr double binomial[smallDegree + 1][smallDegree + 1] = {{1},
                                                                          {1, 1},
                                                                          {1, 2, 1},
                                                                          {1, 3, 3, 1},
                                                                          {1, 4, 6, 4, 1},
                                                                          {1, 5, 10, 10, 5, 1},
                                                                          {1, 6, 15, 20, 15, 6, 1},
                                                                          {1, 7, 21, 35, 35, 21, 7, 1}};
    const double a = knots[span], b = knots[span + 1];
    // Bezier point k is the blossom at (a^(p-k), b^k): the levels taken at a are shared, so
    // state holds the de Boor triangle after r levels at a and each k finishes it at b.
    glm::dvec3 state[smallDegree + 1], d[smallDegree + 1], bezier[smallDegree + 1];
#pragma GCC unroll 8
    for (std::size_t j = 0; j <= p; ++j) state[j] = points[span - p + j];
    auto level = [&](glm::dvec3* net, std::size_t l, double x) {
#pragma GCC unroll 8
        for (std::size_t j = p; j >= l; --j) {
            const double lo = knots[span - p + j], hi = knots[span + 1 + j - l];
            const double alpha = (x - lo) / (hi - lo);
            net[j] = (1.0 - alpha) * net[j - 1] + alpha * net[j];
        }
    };
    // The levels at b repeat for every r: their ratios are made once.
    double atB[smallDegree + 1][smallDegree + 1];
#pragma GCC unroll 8
    for (std::size_t l = 1; l <= p; ++l)
#pragma GCC unroll 8
        for (std::size_t j = p; j >= l; --j) {
            const double lo = knots[span - p + j], hi = knots[span + 1 + j - l];
            atB[l][j] = (b - lo) / (hi - lo);
        }
#pragma GCC unroll 8
    for (std::size_t r = 0; r <= p; ++r) {
#pragma GCC unroll 8
        for (std::size_t j = r; j <= p; ++j) d[j] = state[j];
#pragma GCC unroll 8
        for (std::size_t l = r + 1; l <= p; ++l)
#pragma GCC unroll 8
            for (std::size_t j = p; j >= l; --j) d[j] = (1.0 - atB[l][j]) * d[j - 1] + atB[l][j] * d[j];
        bezier[p - r] = d[p];
        if (r < p) level(state, r + 1, a);
    }
#pragma GCC unroll 8
    for (std::size_t k = 0; k <= p; ++k) {
        glm::dvec3 sum(0.0);
#pragma GCC unroll 8
        for (std::size_t j = 0; j <= k; ++j)
            sum += ((k - j) % 2 == 0 ? 1.0 : -1.0) * binomial[k][j] * bezier[j];
        power[k] = binomial[p][k] * sum;
    }
}

// spanPowerForm with the common degrees fixed at compile time (the same arithmetic, unrolled).
inline void spanPowerFormAnyDegree(std::size_t span, std::size_t p, const double* knots,
                                   const glm::dvec3* points, glm::dvec3* power) {
    withFixedDegree(p, [&](auto fixed) { spanPowerForm<fixed()>(span, p, knots, points, power); });
}

// Values and derivatives of one polynomial spline (degree, knots, count coefficients, which
// must outlive it) at many parameters: the power form of the last span used is kept, so points
// near each other (samples in order, Newton iterations) cost a Horner step each.
class SplineSampler {
public:
    // everySpan keeps the power form of every span once made (for parameters that jump between
    // spans, as Newton from scattered seeds or samples sliding across knots do).
    SplineSampler(int degree, const std::vector<double>& knots, const glm::dvec3* points, std::size_t count,
                  bool everySpan = false)
        : degree_(degree),
          p_(static_cast<std::size_t>(degree)),
          knots_(knots),
          points_(points),
          count_(count) {
        if (p_ > smallDegree) basis_.resize(3 * (p_ + 1));
        if (everySpan && p_ <= smallDegree) {
            made_.assign(count_ + 1, 0);
            forms_.resize((count_ + 1) * (p_ + 1));
        }
    }

    // With every span's power form given (powerForms below, which must outlive it; empty for a
    // degree above smallDegree).
    SplineSampler(int degree, const std::vector<double>& knots, const glm::dvec3* points, std::size_t count,
                  const std::vector<glm::dvec3>& forms)
        : SplineSampler(degree, knots, points, count) {
        if (!forms.empty()) shared_ = forms.data();
    }

    // form_ may point into the object itself.
    SplineSampler(const SplineSampler&) = delete;
    SplineSampler& operator=(const SplineSampler&) = delete;

    // Forgets every power form made: the knots or coefficients (the same vector and array, the
    // same count) have changed in place.
    void restart() {
        formed_ = false;
        std::fill(made_.begin(), made_.end(), 0);
    }

    double start() const { return knots_[p_]; }
    double end() const { return knots_[count_]; }

    glm::dvec3 value(double u) {
        if (p_ > smallDegree) {
            const std::size_t span = findSpan(degree_, knots_, count_, u);
            basisFunctions(span, u, degree_, knots_, std::span<double>(basis_).first(p_ + 1));
            glm::dvec3 c(0.0);
            for (std::size_t k = 0; k <= p_; ++k) c += basis_[k] * points_[span - p_ + k];
            return c;
        }
        const double s = locate(u);
        glm::dvec3 c = form_[p_];
        for (std::size_t k = p_; k-- > 0;) c = c * s + form_[k];
        return c;
    }

    // The point and its first and second derivatives with respect to u.
    void derivatives(double u, glm::dvec3& c, glm::dvec3& d1, glm::dvec3& d2) {
        if (p_ > smallDegree) {
            const std::size_t span = findSpan(degree_, knots_, count_, u);
            basisDerivatives(span, u, degree_, knots_, 2, basis_);
            c = d1 = d2 = glm::dvec3(0.0);
            for (std::size_t k = 0; k <= p_; ++k) {
                const glm::dvec3& q = points_[span - p_ + k];
                c += basis_[k] * q;
                d1 += basis_[p_ + 1 + k] * q;
                d2 += basis_[2 * (p_ + 1) + k] * q;
            }
            return;
        }
        const double s = locate(u);
        c = form_[p_];
        d1 = d2 = glm::dvec3(0.0);
        for (std::size_t k = p_; k-- > 0;) {
            d2 = d2 * s + d1;
            d1 = d1 * s + c;
            c = c * s + form_[k];
        }
        const double h = knots_[span_ + 1] - knots_[span_];
        d1 /= h;
        d2 *= 2.0 / (h * h);
    }

private:
    // Makes span_ the span of u (as findSpan) and returns u's local parameter in it.
    double locate(double u) {
        const bool inside = formed_ && knots_[span_] <= u &&
                            (u < knots_[span_ + 1] || (span_ + 1 == count_ && u <= knots_[count_]));
        if (!inside) {
            span_ = findSpan(degree_, knots_, count_, u);
            if (shared_) {
                form_ = shared_ + span_ * (p_ + 1);
            } else if (made_.empty()) {
                spanPowerFormAnyDegree(span_, p_, knots_.data(), points_, power_);
                form_ = power_;
            } else {
                glm::dvec3* form = forms_.data() + span_ * (p_ + 1);
                if (!made_[span_])
                    spanPowerFormAnyDegree(span_, p_, knots_.data(), points_, form), made_[span_] = 1;
                form_ = form;
            }
            formed_ = true;
        }
        return (u - knots_[span_]) / (knots_[span_ + 1] - knots_[span_]);
    }

    int degree_;
    std::size_t p_;
    const std::vector<double>& knots_;
    const glm::dvec3* points_;
    std::size_t count_;
    std::size_t span_ = 0;
    bool formed_ = false;
    glm::dvec3 power_[smallDegree + 1];
    const glm::dvec3* form_ = power_;
    const glm::dvec3* shared_ = nullptr;
    std::vector<double> basis_;
    std::vector<char> made_;
    std::vector<glm::dvec3> forms_;
};

// Values of a polynomial spline (degree, knots, count coefficients) at parameters inside its
// domain (ascending ones cost one power form per span).
// The same as SplineSampler::value at each parameter, with the degree fixed at compile time.
template <std::size_t P>
void evaluateAscendingFixed(const std::vector<double>& knots, const glm::dvec3* points, std::size_t count,
                            std::span<const double> params, glm::dvec3* out, const glm::dvec3* forms) {
    glm::dvec3 made[P + 1];
    const glm::dvec3* form = made;
    std::size_t span = 0;
    bool formed = false;
    for (std::size_t i = 0; i < params.size(); ++i) {
        const double u = params[i];
        if (!formed ||
            !(knots[span] <= u && (u < knots[span + 1] || (span + 1 == count && u <= knots[count])))) {
            // The parameters ascend: a walk forward over the next few spans is cheaper than a
            // binary search (samples about as dense as the spans move one or two).
            std::size_t next = formed ? span : count;
            for (int steps = 0; next < count && steps < 4 && !(u < knots[next + 1]); ++steps) ++next;
            const bool found = next + 1 < count ? knots[next] <= u && u < knots[next + 1]
                                                : next + 1 == count && knots[next] <= u && u <= knots[count];
            span = found ? next : findSpan(static_cast<int>(P), knots, count, u);
            if (forms)
                form = forms + span * (P + 1);
            else
                spanPowerForm<P>(span, P, knots.data(), points, made);
            formed = true;
        }
        const double s = (u - knots[span]) / (knots[span + 1] - knots[span]);
        glm::dvec3 c = form[P];
#pragma GCC unroll 8
        for (std::size_t k = P; k > 0; --k) c = c * s + form[k - 1];
        out[i] = c;
    }
}

// Every non-empty span's power form, at span * (p + 1), into out; empty for a degree above
// smallDegree.
inline void powerFormsInto(std::vector<glm::dvec3>& out, int degree, const std::vector<double>& knots,
                           const glm::dvec3* points, std::size_t count) {
    const std::size_t p = static_cast<std::size_t>(degree);
    out.clear();
    if (p > smallDegree) return;
    out.resize((count + 1) * (p + 1));
    for (std::size_t span = p; span < count; ++span)
        if (knots[span + 1] > knots[span])
            spanPowerFormAnyDegree(span, p, knots.data(), points, &out[span * (p + 1)]);
}

inline std::vector<glm::dvec3> powerForms(int degree, const std::vector<double>& knots,
                                          const glm::dvec3* points, std::size_t count) {
    std::vector<glm::dvec3> out;
    powerFormsInto(out, degree, knots, points, count);
    return out;
}

// spanSamples into out (its storage reused).
void spanSamplesInto(std::vector<double>& out, const std::vector<double>& knots, int degree,
                     std::size_t count, int samplesPerSpan);

// forms: powerForms of the same spline, or null.
inline void evaluateAscending(int degree, const std::vector<double>& knots, const glm::dvec3* points,
                              std::size_t count, std::span<const double> params, glm::dvec3* out,
                              const std::vector<glm::dvec3>* forms = nullptr) {
    const glm::dvec3* given = forms && !forms->empty() ? forms->data() : nullptr;
    withFixedDegree(static_cast<std::size_t>(degree), [&](auto fixed) {
        if constexpr (fixed() > 0) {
            evaluateAscendingFixed<fixed()>(knots, points, count, params, out, given);
        } else {
            SplineSampler sampler(degree, knots, points, count);
            for (std::size_t i = 0; i < params.size(); ++i) out[i] = sampler.value(params[i]);
        }
    });
}

// The distance from target to a polynomial spline found by Newton from parameter u, never more
// than `bound` (the caller's distance to a known point of the spline), stopping early once it is
// at most `enough`. Every distance it takes is to a real point of the spline, so the answer
// bounds the true closest distance from above.
inline double newtonDistance(SplineSampler& spline, const glm::dvec3& target, double u, double bound,
                             double* foot = nullptr, double enough = 0.0) {
    const double lo = spline.start(), hi = spline.end();
    double best = bound;
    for (int it = 0; it < 8; ++it) {
        glm::dvec3 c, d1, d2;
        spline.derivatives(u, c, d1, d2);
        const glm::dvec3 r = c - target;
        if (glm::length(r) < best) {
            best = glm::length(r);
            if (foot) *foot = u;
            if (best <= enough) break;
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

// Solves the symmetric positive definite banded system N X = B in place by Cholesky: N is n x n
// with half bandwidth w, stored by rows as band[i * (w + 1) + k] = N(i, i + k); B has n rows of
// `columns` glm::dvec3 each (b[i * columns + c]). Returns false when N is not positive definite.
inline bool solveBanded(std::vector<double>& band, std::size_t n, std::size_t w, std::vector<glm::dvec3>& b,
                        std::size_t columns = 1) {
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
    for (std::size_t c = 0; c < columns; ++c) {
        for (std::size_t i = 0; i < n; ++i) {  // U^T y = b
            glm::dvec3 s = b[i * columns + c];
            for (std::size_t k = i > w ? i - w : 0; k < i; ++k)
                s -= band[k * wb + (i - k)] * b[k * columns + c];
            b[i * columns + c] = s / band[i * wb];
        }
        for (std::size_t i = n; i-- > 0;) {  // U x = y
            glm::dvec3 s = b[i * columns + c];
            for (std::size_t j = i + 1; j <= std::min(n - 1, i + w); ++j)
                s -= band[i * wb + (j - i)] * b[j * columns + c];
            b[i * columns + c] = s / band[i * wb];
        }
    }
    return true;
}

}  // namespace geom::detail
