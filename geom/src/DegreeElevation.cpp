#include "geom/DegreeElevation.h"
#include "NumberText.h"

#include "geom/Basis.h"
#include "geom/ControlNet.h"
#include "geom/GeometryError.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace geom {
namespace {

/// Clamps a net at both domain ends (knot insertion to multiplicity degree, then the parts
/// outside the domain dropped); a clamped net comes back unchanged.
void clampNet(int degree, std::vector<double>& knots, ControlNet& net) {
    const std::size_t p = static_cast<std::size_t>(degree);
    const double a = knots[p], b = knots[net.blocks()];
    if (knots.front() != a) {
        const int s = static_cast<int>(std::count(knots.begin(), knots.end(), a));
        if (s < degree) insertKnotInNet(degree, knots, net, a, degree - s, "elevateDegree");
        const auto r =
            static_cast<std::size_t>(std::lower_bound(knots.begin(), knots.end(), a) - knots.begin());
        const std::size_t firstPoint = s > degree ? r : r - 1;
        std::vector<double> k{a};
        if (s > degree) k.clear();
        k.insert(k.end(), knots.begin() + static_cast<std::ptrdiff_t>(r), knots.end());
        knots = std::move(k);
        net.data.erase(net.data.begin(),
                       net.data.begin() + static_cast<std::ptrdiff_t>(firstPoint * net.stride));
    }
    if (knots.back() != b) {
        const int s = static_cast<int>(std::count(knots.begin(), knots.end(), b));
        if (s < degree) insertKnotInNet(degree, knots, net, b, degree - s, "elevateDegree");
        const auto e =
            static_cast<std::size_t>(std::upper_bound(knots.begin(), knots.end(), b) - knots.begin());
        knots.resize(e);
        if (s <= degree) knots.push_back(b);
        net.data.resize((knots.size() - p - 1) * net.stride);
    }
}

/// The highest degree elevateDegree makes: beyond it the Bernstein and B-spline arithmetic loses
/// the digits a shape needs (and a count near INT_MAX overflows).
constexpr int kMaxElevatedDegree = 64;

/// Solves A X = B in place for A of band w (a(i, j) = 0 for |i - j| > w), held as n rows of
/// 2w + 1 (column j of row i at j - i + w); B is n rows of m doubles. Gaussian elimination without
/// pivoting: a B-spline collocation matrix at points meeting the Schoenberg-Whitney condition is
/// totally positive, for which that is stable (de Boor and Pinkus, 1977); fill-in stays in the
/// band. O(n w^2) where a dense solve was O(n^3).
void solveBanded(std::vector<double>& A, std::vector<double>& B, std::size_t n, std::size_t w,
                 std::size_t m) {
    const std::size_t width = 2 * w + 1;
    auto a = [&](std::size_t i, std::size_t j) -> double& { return A[i * width + j + w - i]; };
    for (std::size_t k = 0; k < n; ++k) {
        const double pivot = a(k, k);
        double scale = 0.0;
        for (std::size_t j = k; j < std::min(n, k + w + 1); ++j) scale = std::max(scale, std::abs(a(k, j)));
        if (!(std::abs(pivot) > 1e-14 * scale))
            throw GeometryError("elevateDegree: the collocation system is singular");
        for (std::size_t i = k + 1; i < std::min(n, k + w + 1); ++i) {
            const double l = a(i, k) / pivot;
            if (l == 0.0) continue;
            for (std::size_t j = k; j < std::min(n, k + w + 1); ++j) a(i, j) -= l * a(k, j);
            for (std::size_t c = 0; c < m; ++c) B[i * m + c] -= l * B[k * m + c];
        }
    }
    for (std::size_t i = n; i-- > 0;) {
        for (std::size_t j = i + 1; j < std::min(n, i + w + 1); ++j)
            for (std::size_t c = 0; c < m; ++c) B[i * m + c] -= a(i, j) * B[j * m + c];
        for (std::size_t c = 0; c < m; ++c) B[i * m + c] /= a(i, i);
    }
}

void elevateNet(int degree, std::vector<double>& knots, ControlNet& net, int times) {
    if (times < 0) throw GeometryError("elevateDegree: cannot elevate by " + std::to_string(times));
    if (times > kMaxElevatedDegree - degree)
        throw GeometryError("elevateDegree: degree " + std::to_string(degree) + " raised by " +
                            std::to_string(times) + " is above " + std::to_string(kMaxElevatedDegree) +
                            ", the highest made");
    if (times == 0) return;
    clampNet(degree, knots, net);
    const std::size_t p = static_cast<std::size_t>(degree);
    const std::size_t count = net.blocks();
    for (std::size_t k = p + 1; k < count; ++k)
        if (std::count(knots.begin(), knots.end(), knots[k]) > degree)
            throw GeometryError("elevateDegree: interior knot " + detail::numberText(knots[k]) +
                                " has multiplicity degree + 1 (a break); split the curve there first");
    const int P = degree + times;
    std::vector<double> raised;
    for (std::size_t i = 0; i < knots.size();) {
        std::size_t j = i;
        while (j < knots.size() && knots[j] == knots[i]) ++j;
        raised.insert(raised.end(), j - i + static_cast<std::size_t>(times), knots[i]);
        i = j;
    }
    const std::size_t n = raised.size() - static_cast<std::size_t>(P) - 1;
    const std::size_t m = 4 * net.stride;
    const std::size_t w = static_cast<std::size_t>(P);  // row i's entries lie in columns i - P .. i + P
    std::vector<double> A(n * (2 * w + 1), 0.0), B(n * m, 0.0);
    std::vector<double> oldBasis(p + 1), newBasis(static_cast<std::size_t>(P) + 1);
    for (std::size_t i = 0; i < n; ++i) {
        double tau = 0.0;
        for (std::size_t k = 1; k <= static_cast<std::size_t>(P); ++k) tau += raised[i + k];
        tau /= P;
        const std::size_t ns = findSpan(P, raised, n, tau);
        basisFunctions(ns, tau, P, raised, newBasis);
        for (std::size_t k = 0; k <= static_cast<std::size_t>(P); ++k) {
            const std::size_t j = ns - static_cast<std::size_t>(P) + k;
            if (j + w < i || j > i + w)
                throw GeometryError("elevateDegree: a collocation row leaves the band");
            A[i * (2 * w + 1) + j + w - i] = newBasis[k];
        }
        const std::size_t os = findSpan(degree, knots, count, tau);
        basisFunctions(os, tau, degree, knots, oldBasis);
        for (std::size_t k = 0; k <= p; ++k) {
            const glm::dvec4* block = net.block(os - p + k);
            for (std::size_t c = 0; c < net.stride; ++c)
                for (int d = 0; d < 4; ++d)
                    B[i * m + c * 4 + static_cast<std::size_t>(d)] += oldBasis[k] * block[c][d];
        }
    }
    solveBanded(A, B, n, w, m);
    net.data.resize(n * net.stride);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t c = 0; c < net.stride; ++c)
            for (int d = 0; d < 4; ++d)
                net.data[i * net.stride + c][d] = B[i * m + c * 4 + static_cast<std::size_t>(d)];
    knots = std::move(raised);
}

}  // namespace

Curve elevateDegree(const Curve& curve, int times) {
    validate(curve, "elevateDegree");
    Curve out = curve;
    ControlNet net = homogeneousNet(curve);
    elevateNet(curve.degree, out.knots, net, times);
    out.degree = curve.degree + times;
    setFromNet(out, net, curve.rational());
    validate(out);
    return out;
}

Surface elevateDegree(const Surface& surface, int times, bool alongV) {
    validate(surface, "elevateDegree");
    Surface out = surface;
    ControlNet net = homogeneousNet(surface, alongV);
    elevateNet(alongV ? surface.degreeV : surface.degreeU, alongV ? out.knotsV : out.knotsU, net, times);
    (alongV ? out.degreeV : out.degreeU) += times;
    setFromNet(out, net, alongV, surface.rational());
    validate(out);
    return out;
}

}  // namespace geom
