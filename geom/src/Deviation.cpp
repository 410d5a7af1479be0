#include "geom/Deviation.h"

#include "LocalProjection.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <string>

namespace geom {
namespace {

// Distance of every point to `curve`, globally: Newton from the point's own parameter gives an
// upper bound; then every knot span whose control points' bounding box (which holds the span,
// by the convex hull property) comes nearer than the bound is searched from its nearest sample.
std::vector<double> distancesTo(const Curve& curve, const std::vector<glm::dvec3>& points,
                                const std::vector<double>& seeds, int samplesPerSpan) {
    struct Span {
        double from, to;
        glm::dvec3 lo, hi;
    };
    const std::size_t p = static_cast<std::size_t>(curve.degree);
    std::vector<Span> spans;
    for (std::size_t s = p; s < curve.points.size(); ++s) {
        if (!(curve.knots[s + 1] > curve.knots[s])) continue;
        Span sp{curve.knots[s], curve.knots[s + 1], curve.points[s - p], curve.points[s - p]};
        for (std::size_t i = s - p; i <= s; ++i) {
            sp.lo = glm::min(sp.lo, curve.points[i]);
            sp.hi = glm::max(sp.hi, curve.points[i]);
        }
        spans.push_back(sp);
    }
    std::vector<double> out(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::dvec3& q = points[i];
        double best = detail::projectFrom(curve, q, seeds[i]).distance;
        for (const Span& sp : spans) {
            const glm::dvec3 gap = glm::max(glm::max(sp.lo - q, q - sp.hi), glm::dvec3(0.0));
            if (glm::length(gap) >= best) continue;
            double seed = sp.from, nearest = std::numeric_limits<double>::infinity();
            for (int k = 0; k <= samplesPerSpan; ++k) {
                const double u = sp.from + (sp.to - sp.from) * k / samplesPerSpan;
                const double d = glm::length(detail::pointOf(curve, u) - q);
                if (d < nearest) nearest = d, seed = u;
            }
            best = std::min(best, detail::projectFrom(curve, q, seed).distance);
        }
        out[i] = best;
    }
    return out;
}

}  // namespace

std::vector<double> spanSamples(const std::vector<double>& knots, int degree, std::size_t count,
                                int samplesPerSpan) {
    if (samplesPerSpan < 1) throw GeometryError("spanSamples: samplesPerSpan must be at least 1");
    std::vector<double> out;
    for (std::size_t i = static_cast<std::size_t>(degree); i < count; ++i) {
        const double a = knots[i], b = knots[i + 1];
        if (!(b > a)) continue;
        for (int k = 0; k < samplesPerSpan; ++k) out.push_back(a + (b - a) * k / samplesPerSpan);
    }
    out.push_back(knots[count]);
    return out;
}

CurveDeviation measureDeviation(const Curve& original, const Curve& reduced, int samplesPerSpan) {
    const std::vector<double> pa =
        spanSamples(original.knots, original.degree, original.points.size(), samplesPerSpan);
    const std::vector<double> pb =
        spanSamples(reduced.knots, reduced.degree, reduced.points.size(), samplesPerSpan);
    std::vector<glm::dvec3> a(pa.size()), b(pb.size());
    for (std::size_t i = 0; i < pa.size(); ++i) a[i] = detail::pointOf(original, pa[i]);
    for (std::size_t i = 0; i < pb.size(); ++i) b[i] = detail::pointOf(reduced, pb[i]);
    const std::vector<double> da = distancesTo(reduced, a, pa, 4);
    const std::vector<double> db = distancesTo(original, b, pb, 4);
    CurveDeviation out;
    double sum = 0.0;
    for (double d : da) out.maxOriginalToReduced = std::max(out.maxOriginalToReduced, d), sum += d;
    for (double d : db) out.maxReducedToOriginal = std::max(out.maxReducedToOriginal, d), sum += d;
    out.maxError = std::max(out.maxOriginalToReduced, out.maxReducedToOriginal);
    out.samples = da.size() + db.size();
    out.meanError = sum / static_cast<double>(out.samples);
    return out;
}

SurfaceDeviation measureDeviation(const Surface& original, const Surface& reduced, int samplesPerSpan) {
    if (original.domainStartU() != reduced.domainStartU() || original.domainEndU() != reduced.domainEndU() ||
        original.domainStartV() != reduced.domainStartV() || original.domainEndV() != reduced.domainEndV())
        throw GeometryError("measureDeviation: the two surfaces have different parameter domains");
    SurfaceDeviation out;
    out.u = spanSamples(reduced.knotsU, reduced.degreeU, reduced.countU, samplesPerSpan);
    out.v = spanSamples(reduced.knotsV, reduced.degreeV, reduced.countV, samplesPerSpan);
    out.error.resize(out.u.size() * out.v.size());
    double sum = 0.0;
    for (std::size_t i = 0; i < out.u.size(); ++i)
        for (std::size_t j = 0; j < out.v.size(); ++j) {
            const glm::dvec3 p = evaluate(reduced, out.u[i], out.v[j]);
            const double d = detail::projectFrom(original, p, out.u[i], out.v[j]).distance;
            out.error[i * out.v.size() + j] = d;
            out.maxReducedToOriginal = std::max(out.maxReducedToOriginal, d);
            sum += d;
        }
    out.meanError = sum / static_cast<double>(out.error.size());
    const std::vector<double> ou =
        spanSamples(original.knotsU, original.degreeU, original.countU, samplesPerSpan);
    const std::vector<double> ov =
        spanSamples(original.knotsV, original.degreeV, original.countV, samplesPerSpan);
    for (double u : ou)
        for (double v : ov) {
            const glm::dvec3 p = evaluate(original, u, v);
            out.maxOriginalToReduced =
                std::max(out.maxOriginalToReduced, detail::projectFrom(reduced, p, u, v).distance);
        }
    out.maxError = std::max(out.maxOriginalToReduced, out.maxReducedToOriginal);
    return out;
}

}  // namespace geom
