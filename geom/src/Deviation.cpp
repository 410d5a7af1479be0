#include "geom/Deviation.h"

#include "LocalProjection.h"
#include "geom/CurveProjector.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "geom/SurfaceProjector.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <string>

namespace geom {
namespace {

// Distance of every point to `curve`: the global closest point (geom's CurveProjector), and
// Newton from the point's own parameter; both are distances to points of the curve, so the
// smaller is the better measurement.
std::vector<double> distancesTo(const Curve& curve, const std::vector<glm::dvec3>& points,
                                const std::vector<double>& seeds) {
    const CurveProjector projector(curve);
    std::vector<double> out(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        out[i] = std::min(projector.closestPoint(points[i]).distance,
                          detail::projectFrom(curve, points[i], seeds[i]).distance);
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
    const std::vector<double> da = distancesTo(reduced, a, pa);
    const std::vector<double> db = distancesTo(original, b, pb);
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
    const SurfaceProjector toOriginal(original), toReduced(reduced);
    for (std::size_t i = 0; i < out.u.size(); ++i)
        for (std::size_t j = 0; j < out.v.size(); ++j) {
            const glm::dvec3 p = evaluate(reduced, out.u[i], out.v[j]);
            const double d = std::min(toOriginal.closestPoint(p).distance,
                                      detail::projectFrom(original, p, out.u[i], out.v[j]).distance);
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
            const double d =
                std::min(toReduced.closestPoint(p).distance, detail::projectFrom(reduced, p, u, v).distance);
            out.maxOriginalToReduced = std::max(out.maxOriginalToReduced, d);
        }
    out.maxError = std::max(out.maxOriginalToReduced, out.maxReducedToOriginal);
    return out;
}

}  // namespace geom
