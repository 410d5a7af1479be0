#include "geom/DegreeElevation.h"

#include "DenseLu.h"
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

/// Solves A X = B in place; A is n x n, B is n rows of m doubles, solved one column at a time.
void solveDense(std::vector<double>& A, std::vector<double>& B, std::size_t n, std::size_t m) {
    const detail::DenseLu lu(std::move(A), n, 0.0);
    if (lu.singular()) throw GeometryError("elevateDegree: the collocation system is singular");
    std::vector<double> column(n);
    for (std::size_t j = 0; j < m; ++j) {
        for (std::size_t i = 0; i < n; ++i) column[i] = B[i * m + j];
        column = lu.solve(std::move(column));
        for (std::size_t i = 0; i < n; ++i) B[i * m + j] = column[i];
    }
}

void elevateNet(int degree, std::vector<double>& knots, ControlNet& net, int times) {
    if (times < 0) throw GeometryError("elevateDegree: cannot elevate by " + std::to_string(times));
    if (times == 0) return;
    clampNet(degree, knots, net);
    const std::size_t p = static_cast<std::size_t>(degree);
    const std::size_t count = net.blocks();
    for (std::size_t k = p + 1; k < count; ++k)
        if (std::count(knots.begin(), knots.end(), knots[k]) > degree)
            throw GeometryError("elevateDegree: interior knot " + std::to_string(knots[k]) +
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
    std::vector<double> A(n * n, 0.0), B(n * m, 0.0);
    std::vector<double> oldBasis(p + 1), newBasis(static_cast<std::size_t>(P) + 1);
    for (std::size_t i = 0; i < n; ++i) {
        double tau = 0.0;
        for (std::size_t k = 1; k <= static_cast<std::size_t>(P); ++k) tau += raised[i + k];
        tau /= P;
        const std::size_t ns = findSpan(P, raised, n, tau);
        basisFunctions(ns, tau, P, raised, newBasis);
        for (std::size_t k = 0; k <= static_cast<std::size_t>(P); ++k)
            A[i * n + ns - static_cast<std::size_t>(P) + k] = newBasis[k];
        const std::size_t os = findSpan(degree, knots, count, tau);
        basisFunctions(os, tau, degree, knots, oldBasis);
        for (std::size_t k = 0; k <= p; ++k) {
            const glm::dvec4* block = net.block(os - p + k);
            for (std::size_t c = 0; c < net.stride; ++c)
                for (int d = 0; d < 4; ++d)
                    B[i * m + c * 4 + static_cast<std::size_t>(d)] += oldBasis[k] * block[c][d];
        }
    }
    solveDense(A, B, n, m);
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
