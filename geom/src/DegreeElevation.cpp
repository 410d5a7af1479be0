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

/// The highest degree elevateDegree makes (a count near INT_MAX would overflow).
constexpr int kMaxElevatedDegree = 64;

/// weights[i][k] = C(p, k) C(t, i - k) / C(p + t, i): the Bezier points of a degree-p segment
/// raised by t are these convex combinations of its own (The NURBS Book eq. 5.36).
std::vector<std::vector<double>> elevationWeights(int p, int t) {
    const int P = p + t;
    std::vector<std::vector<double>> binomial(static_cast<std::size_t>(P) + 1);
    for (int n = 0; n <= P; ++n) {
        binomial[static_cast<std::size_t>(n)].assign(static_cast<std::size_t>(n) + 1, 1.0);
        for (int k = 1; k < n; ++k)
            binomial[static_cast<std::size_t>(n)][static_cast<std::size_t>(k)] =
                binomial[static_cast<std::size_t>(n) - 1][static_cast<std::size_t>(k) - 1] +
                binomial[static_cast<std::size_t>(n) - 1][static_cast<std::size_t>(k)];
    }
    auto C = [&](int n, int k) { return binomial[static_cast<std::size_t>(n)][static_cast<std::size_t>(k)]; };
    std::vector<std::vector<double>> w(static_cast<std::size_t>(P) + 1,
                                       std::vector<double>(static_cast<std::size_t>(p) + 1, 0.0));
    for (int i = 0; i <= P; ++i)
        for (int k = std::max(0, i - t); k <= std::min(p, i); ++k)
            w[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] = C(p, k) * C(t, i - k) / C(P, i);
    return w;
}

/// The old net's Bezier segments (every interior break to multiplicity p), each raised by
/// `times`: segment g's P + 1 points start at block g (P + 1) of the result.
std::vector<glm::dvec4> raisedSegments(int degree, const std::vector<double>& knots, const ControlNet& net,
                                       const std::vector<double>& breaks, int times) {
    const std::size_t p = static_cast<std::size_t>(degree), Pn = p + static_cast<std::size_t>(times);
    const std::size_t stride = net.stride, segments = breaks.size() - 1;
    std::vector<double> bezierKnots = knots;
    ControlNet bezier = net;  // segment g then holds blocks g p .. g p + p
    for (std::size_t b = 1; b + 1 < breaks.size(); ++b) {
        const int s = static_cast<int>(std::count(bezierKnots.begin(), bezierKnots.end(), breaks[b]));
        if (s < degree) insertKnotInNet(degree, bezierKnots, bezier, breaks[b], degree - s, "elevateDegree");
    }
    const std::vector<std::vector<double>> w = elevationWeights(degree, times);
    std::vector<glm::dvec4> high(segments * (Pn + 1) * stride, glm::dvec4(0.0));
    for (std::size_t g = 0; g < segments; ++g)
        for (std::size_t i = 0; i <= Pn; ++i) {
            glm::dvec4* out = high.data() + (g * (Pn + 1) + i) * stride;
            for (std::size_t k = 0; k <= p; ++k) {
                if (w[i][k] == 0.0) continue;
                const glm::dvec4* in = bezier.block(g * p + k);
                for (std::size_t c = 0; c < stride; ++c) out[c] += w[i][k] * in[c];
            }
        }
    return high;
}

/// The segment to read new control point i off: segment g spans [breaks[g], breaks[g + 1]], and
/// any inside the point's support [raised[i], raised[i + P + 1]] gives it in exact arithmetic. A
/// step at an argument outside the segment extrapolates and scales rounding by |1 - lambda| +
/// |lambda|: the segment whose steps multiply to the least (the longer of two neighbours, so that
/// each factor stays below 3).
std::size_t blossomSegment(const std::vector<double>& breaks, const std::vector<double>& raised,
                           std::size_t i, std::size_t Pn) {
    const std::size_t segments = breaks.size() - 1;
    std::size_t best = segments;
    double bestGrowth = 0.0;
    const auto start = std::lower_bound(breaks.begin(), breaks.end(), raised[i]) - breaks.begin();
    for (std::size_t g = static_cast<std::size_t>(start); g < segments && breaks[g] < raised[i + Pn + 1];
         ++g) {
        if (breaks[g + 1] > raised[i + Pn + 1]) break;
        double growth = 0.0;  // log of the product of the factors
        for (std::size_t r = 1; r <= Pn; ++r) {
            const double lambda = (raised[i + r] - breaks[g]) / (breaks[g + 1] - breaks[g]);
            if (lambda < 0.0 || lambda > 1.0) growth += std::log(std::abs(1.0 - lambda) + std::abs(lambda));
        }
        if (best == segments || growth < bestGrowth) best = g, bestGrowth = growth;
    }
    if (best == segments) throw GeometryError("elevateDegree: no segment lies in a support (internal)");
    return best;
}

/// The blossom of a degree-P Bezier segment over [a, b] (its P + 1 points in `work`, each
/// `stride` wide) at the arguments `at`, by de Casteljau with one argument a step; the result is
/// left at the block returned. Arguments at an end of the segment select instead of blending (no
/// rounding): a shifts nothing off, b shifts by one.
std::size_t blossom(std::vector<glm::dvec4>& work, std::size_t stride, double a, double b, const double* at,
                    std::size_t Pn) {
    std::size_t lo = 0, len = Pn + 1;
    for (std::size_t r = 0; r < Pn; ++r) {
        const double u = at[r];
        --len;
        if (u == a) continue;
        if (u == b) {
            ++lo;
            continue;
        }
        const double lambda = (u - a) / (b - a);
        for (std::size_t k = lo; k < lo + len; ++k) {
            glm::dvec4* x = work.data() + k * stride;
            const glm::dvec4* y = work.data() + (k + 1) * stride;
            for (std::size_t c = 0; c < stride; ++c) x[c] = (1.0 - lambda) * x[c] + lambda * y[c];
        }
    }
    return lo;
}

/// Degree elevation without a linear solve, so that no digits are lost at any degree: the old
/// net is cut into Bezier segments (knot insertion, convex combinations), each segment raised
/// (convex combinations again), and each new control point read off as the blossom of a segment
/// at its knots (Ramshaw: c_i = F(s[i+1], ..., s[i+P]) for the piece on any non-empty span of
/// its support). A collocation system would lose digits as its condition grows with the degree.
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
    const std::size_t stride = net.stride, Pn = p + static_cast<std::size_t>(times);
    std::vector<double> raised, breaks;
    for (std::size_t i = 0; i < knots.size();) {
        std::size_t j = i;
        while (j < knots.size() && knots[j] == knots[i]) ++j;
        raised.insert(raised.end(), j - i + static_cast<std::size_t>(times), knots[i]);
        breaks.push_back(knots[i]);
        i = j;
    }
    const std::vector<glm::dvec4> high = raisedSegments(degree, knots, net, breaks, times);
    const std::size_t n = raised.size() - Pn - 1;
    ControlNet result;
    result.stride = stride;
    result.data.resize(n * stride);
    std::vector<glm::dvec4> work((Pn + 1) * stride);
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t g = blossomSegment(breaks, raised, i, Pn);
        std::copy_n(high.data() + g * (Pn + 1) * stride, (Pn + 1) * stride, work.data());
        const std::size_t at = blossom(work, stride, breaks[g], breaks[g + 1], raised.data() + i + 1, Pn);
        std::copy_n(work.data() + at * stride, stride, result.block(i));
    }
    net = std::move(result);
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
