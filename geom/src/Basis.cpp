#include "geom/Basis.h"

#include "geom/GeometryError.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace geom {
namespace {

// These run once per evaluated point: the checks inline are comparisons only; the messages are
// made in cold functions out of line.
[[noreturn, gnu::cold, gnu::noinline]] void badBasisArguments(const char* where, std::size_t span, int degree,
                                                              std::size_t knotCount, std::size_t needed,
                                                              std::size_t given) {
    std::string why;
    if (degree < 0)
        why = "degree " + std::to_string(degree) + " is negative";
    else if (given < needed)
        why = "an output of " + std::to_string(given) + " values is too small for " + std::to_string(needed);
    else
        why = "span " + std::to_string(span) + " of degree " + std::to_string(degree) + " reads past the " +
              std::to_string(knotCount) + " knots";
    throw GeometryError(std::string(where) + ": " + why);
}

/// The knot window [span + 1 - degree, span + degree] that one span's basis reads, and `needed`
/// values in the smallest output, `given`.
inline void checkBasisArguments(const char* where, std::size_t span, int degree, std::size_t knotCount,
                                std::size_t needed, std::size_t given) {
    const std::size_t p = static_cast<std::size_t>(degree);
    if (degree < 0 || span + 1 < p || span + p >= knotCount || given < needed) [[unlikely]]
        badBasisArguments(where, span, degree, knotCount, needed, given);
}

[[noreturn, gnu::cold, gnu::noinline]] void badSpanArguments(int degree, std::size_t knotCount,
                                                             std::size_t controlCount) {
    throw GeometryError(
        "findSpan: degree " + std::to_string(degree) + ", " + std::to_string(controlCount) +
        " control points and " + std::to_string(knotCount) +
        " knots do not fit (degree >= 0, more points than the degree, more knots than points)");
}

/// Basis values at a NaN or infinite parameter would be NaN, and a NaN passes findSpan's
/// comparisons as false.
[[noreturn, gnu::cold, gnu::noinline]] void badParameter(const char* where, double u) {
    throw GeometryError(std::string(where) + ": the parameter u = " + std::to_string(u) + " is not finite");
}

inline void checkParameter(const char* where, double u) {
    if (!std::isfinite(u)) [[unlikely]]
        badParameter(where, u);
}

[[noreturn, gnu::cold, gnu::noinline]] void badOrder(const char* where, int order) {
    throw GeometryError(std::string(where) + ": derivative order " + std::to_string(order) + " is negative");
}

}  // namespace

std::size_t findSpan(int degree, std::span<const double> knots, std::size_t controlCount, double u) {
    if (degree < 0 || controlCount <= static_cast<std::size_t>(degree) || knots.size() <= controlCount)
        [[unlikely]]
        badSpanArguments(degree, knots.size(), controlCount);
    checkParameter("findSpan", u);
    const std::size_t low = static_cast<std::size_t>(degree);
    const std::size_t high = controlCount - 1;
    if (u >= knots[high + 1]) {
        // The domain end belongs to the last span of non-zero length.
        std::size_t s = high;
        while (s > low && knots[s] == knots[high + 1]) --s;
        return s;
    }
    if (u <= knots[low]) {
        std::size_t s = low;
        while (s < high && knots[s + 1] == knots[low]) ++s;
        return s;
    }
    // upper_bound gives the first knot > u; the span starts one before it.
    const auto first = knots.begin() + static_cast<std::ptrdiff_t>(low);
    const auto last = knots.begin() + static_cast<std::ptrdiff_t>(high + 1);
    const auto it = std::upper_bound(first, last, u);
    return static_cast<std::size_t>(it - knots.begin()) - 1;
}

void basisFunctions(std::size_t span, double u, int degree, std::span<const double> knots,
                    std::span<double> out) {
    checkBasisArguments("basisFunctions", span, degree, knots.size(), static_cast<std::size_t>(degree) + 1,
                        out.size());
    checkParameter("basisFunctions", u);
    // Cox-de Boor in the triangular form of The NURBS Book, A2.2; left/right hold the knot
    // differences so each value is computed once.
    const std::size_t p = static_cast<std::size_t>(degree);
    double leftBuf[64], rightBuf[64];
    std::vector<double> heap;
    double* left = leftBuf;
    double* right = rightBuf;
    if (p + 1 > 64) {
        heap.resize(2 * (p + 1));
        left = heap.data();
        right = heap.data() + p + 1;
    }
    out[0] = 1.0;
    for (std::size_t j = 1; j <= p; ++j) {
        left[j] = u - knots[span + 1 - j];
        right[j] = knots[span + j] - u;
        double saved = 0.0;
        for (std::size_t r = 0; r < j; ++r) {
            const double temp = out[r] / (right[r + 1] + left[j - r]);
            out[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        out[j] = saved;
    }
}

void basisDerivatives(std::size_t span, double u, int degree, std::span<const double> knots, int order,
                      std::span<double> out) {
    if (order < 0) [[unlikely]]
        badOrder("basisDerivatives", order);
    checkBasisArguments("basisDerivatives", span, degree, knots.size(),
                        (static_cast<std::size_t>(order) + 1) * (static_cast<std::size_t>(degree) + 1),
                        out.size());
    checkParameter("basisDerivatives", u);
    // The NURBS Book, A2.3: build the triangular table of basis values and knot differences,
    // then combine its columns for each derivative order.
    const std::size_t p = static_cast<std::size_t>(degree);
    const std::size_t n = static_cast<std::size_t>(order);
    const std::size_t w = p + 1;
    // Per-point callers evaluate millions of times: the tables live on the stack up to degree 15.
    constexpr std::size_t kStack = 16;
    double nduStack[kStack * kStack], leftStack[kStack], rightStack[kStack], aStack[2 * kStack];
    std::vector<double> heap;
    double *ndu = nduStack, *left = leftStack, *right = rightStack, *a = aStack;
    if (w > kStack) {
        heap.resize(w * w + 4 * w);
        ndu = heap.data();
        left = ndu + w * w;
        right = left + w;
        a = right + w;
    }
    ndu[0] = 1.0;
    for (std::size_t j = 1; j <= p; ++j) {
        left[j] = u - knots[span + 1 - j];
        right[j] = knots[span + j] - u;
        double saved = 0.0;
        for (std::size_t r = 0; r < j; ++r) {
            ndu[j * w + r] = right[r + 1] + left[j - r];  // lower triangle: knot differences
            const double temp = ndu[r * w + (j - 1)] / ndu[j * w + r];
            ndu[r * w + j] = saved + right[r + 1] * temp;  // upper triangle: basis values
            saved = left[j - r] * temp;
        }
        ndu[j * w + j] = saved;
    }
    for (std::size_t j = 0; j <= p; ++j) out[j] = ndu[j * w + p];
    for (std::size_t k = 1; k <= n; ++k)
        for (std::size_t j = 0; j <= p; ++j) out[k * w + j] = 0.0;

    const std::size_t top = std::min(n, p);
    for (std::size_t r = 0; r <= p; ++r) {
        double* a0 = a;
        double* a1 = a + w;
        a0[0] = 1.0;
        for (std::size_t k = 1; k <= top; ++k) {
            double d = 0.0;
            const long rk = static_cast<long>(r) - static_cast<long>(k);
            const long pk = static_cast<long>(p) - static_cast<long>(k);
            if (rk >= 0) {
                a1[0] = a0[0] / ndu[(pk + 1) * w + static_cast<std::size_t>(rk)];
                d = a1[0] * ndu[static_cast<std::size_t>(rk) * w + static_cast<std::size_t>(pk)];
            }
            const long j1 = rk >= -1 ? 1 : -rk;
            const long j2 = (static_cast<long>(r) - 1 <= pk) ? static_cast<long>(k) - 1
                                                             : static_cast<long>(p) - static_cast<long>(r);
            for (long j = j1; j <= j2; ++j) {
                a1[j] = (a0[j] - a0[j - 1]) /
                        ndu[static_cast<std::size_t>(pk + 1) * w + static_cast<std::size_t>(rk + j)];
                d += a1[j] * ndu[static_cast<std::size_t>(rk + j) * w + static_cast<std::size_t>(pk)];
            }
            if (static_cast<long>(r) <= pk) {
                a1[k] = -a0[k - 1] / ndu[static_cast<std::size_t>(pk + 1) * w + r];
                d += a1[k] * ndu[r * w + static_cast<std::size_t>(pk)];
            }
            out[k * w + r] = d;
            std::swap(a0, a1);
        }
    }
    double factor = static_cast<double>(p);
    for (std::size_t k = 1; k <= top; ++k) {
        for (std::size_t j = 0; j <= p; ++j) out[k * w + j] *= factor;
        factor *= static_cast<double>(p - k);
    }
}

void basisWithFirstDerivatives(std::size_t span, double u, int degree, std::span<const double> knots,
                               std::span<double> values, std::span<double> firsts) {
    checkBasisArguments("basisWithFirstDerivatives", span, degree, knots.size(),
                        static_cast<std::size_t>(degree) + 1, std::min(values.size(), firsts.size()));
    checkParameter("basisWithFirstDerivatives", u);
    if (degree < 1) [[unlikely]]
        throw GeometryError("basisWithFirstDerivatives: degree 0 has no first derivatives");
    const std::size_t p = static_cast<std::size_t>(degree);
    if (p == 1) {  // hat functions: no recursion needed
        const double lo = knots[span], hi = knots[span + 1], scale = 1.0 / (hi - lo);
        values[0] = (hi - u) * scale;
        values[1] = (u - lo) * scale;
        firsts[0] = -scale;
        firsts[1] = scale;
        return;
    }
    // The degree p-1 values first, then N'_{i,p} = p (N_{i,p-1} / (t_{i+p} - t_i) -
    // N_{i+1,p-1} / (t_{i+p+1} - t_{i+1})) and one more Cox-de Boor step for the values, from the
    // same quotients.
    basisFunctions(span, u, degree - 1, knots, values);
    double previous = 0.0;  // N_{i,p-1} / (t_{i+p} - t_i) for the function before
    double carried = 0.0;
    for (std::size_t r = 0; r < p; ++r) {
        const double lo = knots[span + r + 1 - p], hi = knots[span + r + 1];
        const double scaled = hi > lo ? values[r] / (hi - lo) : 0.0;
        firsts[r] = static_cast<double>(p) * (previous - scaled);
        previous = scaled;
        // N_{i,p} = (u - t_i) N_{i,p-1} / (t_{i+p} - t_i) + (t_{i+p+1} - u) N_{i+1,p-1} / (t_{i+p+1} -
        // t_{i+1}).
        values[r] = carried + (hi - u) * scaled;
        carried = (u - lo) * scaled;
    }
    firsts[p] = static_cast<double>(p) * previous;
    values[p] = carried;
}

int knotMultiplicity(std::span<const double> knots, double u) {
    return static_cast<int>(std::count(knots.begin(), knots.end(), u));
}

}  // namespace geom
