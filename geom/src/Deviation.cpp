#include "geom/Deviation.h"

#include "LocalProjection.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <string>

namespace geom {
namespace {

// Distance of every point to `curve`: the nearest of the curve's samples (a plain search, so no
// local minimum is missed), then Newton from there and from the point's own parameter.
std::vector<double> distancesTo(const Curve& curve, const std::vector<double>& params,
                                const std::vector<glm::dvec3>& points, const std::vector<double>& seeds) {
    std::vector<glm::dvec3> samples(params.size());
    for (std::size_t i = 0; i < params.size(); ++i) samples[i] = evaluate(curve, params[i]);
    std::vector<double> out(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        std::size_t nearest = 0;
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < samples.size(); ++k) {
            const glm::dvec3 d = samples[k] - points[i];
            const double dd = glm::dot(d, d);
            if (dd < best) best = dd, nearest = k;
        }
        double dist = detail::projectFrom(curve, points[i], params[nearest]).distance;
        dist = std::min(dist, detail::projectFrom(curve, points[i], seeds[i]).distance);
        out[i] = dist;
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
    const std::vector<double> pa = spanSamples(original.knots, original.degree, original.points.size(), samplesPerSpan);
    const std::vector<double> pb = spanSamples(reduced.knots, reduced.degree, reduced.points.size(), samplesPerSpan);
    std::vector<glm::dvec3> a(pa.size()), b(pb.size());
    for (std::size_t i = 0; i < pa.size(); ++i) a[i] = evaluate(original, pa[i]);
    for (std::size_t i = 0; i < pb.size(); ++i) b[i] = evaluate(reduced, pb[i]);
    // The other curve's samples are four times denser, so the nearest one seeds Newton well.
    const std::vector<double> qa = spanSamples(reduced.knots, reduced.degree, reduced.points.size(), 4 * samplesPerSpan);
    const std::vector<double> qb = spanSamples(original.knots, original.degree, original.points.size(), 4 * samplesPerSpan);
    const std::vector<double> da = distancesTo(reduced, qa, a, pa);
    const std::vector<double> db = distancesTo(original, qb, b, pb);
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
    const std::vector<double> ou = spanSamples(original.knotsU, original.degreeU, original.countU, samplesPerSpan);
    const std::vector<double> ov = spanSamples(original.knotsV, original.degreeV, original.countV, samplesPerSpan);
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
