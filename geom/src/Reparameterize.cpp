#include "geom/Reparameterize.h"
#include "NumberText.h"

#include "geom/GeometryError.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace geom {
namespace {

std::vector<double> reversedKnots(const std::vector<double>& knots, double a, double b) {
    std::vector<double> out(knots.rbegin(), knots.rend());
    for (double& k : out) k = a + b - k;
    // a + b - k can round differently for equal k; keep equal knots equal and the ends exact.
    for (std::size_t i = 0; i < out.size(); ++i) {
        const double original = knots[knots.size() - 1 - i];
        if (original == a) out[i] = b;
        if (original == b) out[i] = a;
        if (i > 0 && original == knots[knots.size() - i]) out[i] = out[i - 1];
    }
    return out;
}

std::vector<double> mappedKnots(const std::vector<double>& knots, double a, double b, double c, double d,
                                const char* where) {
    if (!std::isfinite(c) || !std::isfinite(d) || !(c < d))
        throw GeometryError(std::string(where) + ": the new domain [" + detail::numberText(c) + ", " +
                            detail::numberText(d) + "] must be finite and non-empty");
    std::vector<double> out(knots.size());
    for (std::size_t i = 0; i < knots.size(); ++i) {
        out[i] = knots[i] == a ? c : knots[i] == b ? d : c + (knots[i] - a) * ((d - c) / (b - a));
        if (i > 0 && knots[i] == knots[i - 1]) out[i] = out[i - 1];
    }
    return out;
}

}  // namespace

Curve reverse(const Curve& curve) {
    validate(curve, "reverse");
    Curve out = curve;
    out.knots = reversedKnots(curve.knots, curve.domainStart(), curve.domainEnd());
    std::reverse(out.points.begin(), out.points.end());
    std::reverse(out.weights.begin(), out.weights.end());
    return out;
}

Surface reverse(const Surface& surface, bool alongV) {
    validate(surface, "reverse");
    Surface out = surface;
    if (alongV)
        out.knotsV = reversedKnots(surface.knotsV, surface.domainStartV(), surface.domainEndV());
    else
        out.knotsU = reversedKnots(surface.knotsU, surface.domainStartU(), surface.domainEndU());
    for (std::size_t i = 0; i < surface.countU; ++i)
        for (std::size_t j = 0; j < surface.countV; ++j) {
            const std::size_t from = alongV ? i * surface.countV + (surface.countV - 1 - j)
                                            : (surface.countU - 1 - i) * surface.countV + j;
            out.points[i * surface.countV + j] = surface.points[from];
            if (surface.rational()) out.weights[i * surface.countV + j] = surface.weights[from];
        }
    return out;
}

Curve reparameterize(const Curve& curve, double start, double end) {
    validate(curve, "reparameterize");
    Curve out = curve;
    out.knots =
        mappedKnots(curve.knots, curve.domainStart(), curve.domainEnd(), start, end, "reparameterize");
    validate(out, "reparameterize (the mapped knots)");  // a span beyond the doubles overflows them
    return out;
}

Surface reparameterize(const Surface& surface, double u0, double u1, double v0, double v1) {
    validate(surface, "reparameterize");
    Surface out = surface;
    out.knotsU =
        mappedKnots(surface.knotsU, surface.domainStartU(), surface.domainEndU(), u0, u1, "reparameterize");
    out.knotsV =
        mappedKnots(surface.knotsV, surface.domainStartV(), surface.domainEndV(), v0, v1, "reparameterize");
    validate(out, "reparameterize (the mapped knots)");
    return out;
}

}  // namespace geom
