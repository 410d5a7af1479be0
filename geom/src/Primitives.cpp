#include "geom/Primitives.h"

#include "geom/GeometryError.h"

#include <cmath>
#include <string>

namespace geom {
namespace {

const std::vector<double> kCircleKnots{0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
// The nine control points of the unit circle on its circumscribed square, and their weights.
const double kCx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1};
const double kCy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};

double circleWeight(std::size_t j) {
    return j % 2 == 1 ? std::sqrt(0.5) : 1.0;
}

void checkPositive(double x, const char* what, const char* where) {
    if (!std::isfinite(x) || !(x > 0.0))
        throw GeometryError(std::string(where) + ": " + what + " " + std::to_string(x) + " must be positive");
}

}  // namespace

Curve makeCircle(const glm::dvec3& center, const glm::dvec3& xAxis, const glm::dvec3& yAxis, double radius) {
    checkPositive(radius, "radius", "makeCircle");
    std::vector<glm::dvec3> points;
    std::vector<double> weights;
    for (std::size_t j = 0; j < 9; ++j) {
        points.push_back(center + radius * (kCx[j] * xAxis + kCy[j] * yAxis));
        weights.push_back(circleWeight(j));
    }
    return Curve(2, kCircleKnots, points, weights);
}

Curve makePeriodicCurve(int degree, const std::vector<glm::dvec3>& points,
                        const std::vector<double>& weights) {
    if (degree < 1)
        throw GeometryError("makePeriodicCurve: degree " + std::to_string(degree) + " must be at least 1");
    if (points.size() < static_cast<std::size_t>(degree) + 1)
        throw GeometryError("makePeriodicCurve: " + std::to_string(points.size()) +
                            " points are too few for a closed curve of degree " + std::to_string(degree));
    if (!weights.empty() && weights.size() != points.size())
        throw GeometryError("makePeriodicCurve: " + std::to_string(weights.size()) + " weights for " +
                            std::to_string(points.size()) + " points");
    const std::size_t p = static_cast<std::size_t>(degree), n = points.size();
    std::vector<glm::dvec3> wrapped(points);
    std::vector<double> wrappedWeights(weights);
    for (std::size_t i = 0; i < p; ++i) {
        wrapped.push_back(points[i]);
        if (!weights.empty()) wrappedWeights.push_back(weights[i]);
    }
    // n spans over [0, 1]: knot i at (i - p) / n.
    std::vector<double> knots(n + 2 * p + 1);
    for (std::size_t i = 0; i < knots.size(); ++i)
        knots[i] = (static_cast<double>(i) - static_cast<double>(p)) / static_cast<double>(n);
    return Curve(degree, knots, wrapped, wrappedWeights);
}

Surface makeRevolution(const Curve& profile) {
    validate(profile, "makeRevolution");
    const std::size_t nu = profile.points.size();
    std::vector<glm::dvec3> points;
    std::vector<double> weights;
    for (std::size_t i = 0; i < nu; ++i) {
        const glm::dvec3& q = profile.points[i];
        for (std::size_t j = 0; j < 9; ++j) {
            points.emplace_back(q.x * kCx[j], q.x * kCy[j], q.z);
            weights.push_back(profile.weight(i) * circleWeight(j));
        }
    }
    return Surface(profile.degree, 2, profile.knots, kCircleKnots, nu, 9, points, weights);
}

Surface makeSphere(double radius) {
    checkPositive(radius, "radius", "makeSphere");
    const double r = radius, s = std::sqrt(0.5);
    const Curve half(2, {0, 0, 0, 0.5, 0.5, 1, 1, 1},
                     {{0, 0, -r}, {r, 0, -r}, {r, 0, 0}, {r, 0, r}, {0, 0, r}}, {1, s, 1, s, 1});
    return makeRevolution(half);
}

Surface makeCylinder(double radius, double height) {
    checkPositive(radius, "radius", "makeCylinder");
    checkPositive(height, "height", "makeCylinder");
    return makeRevolution(Curve(1, {0, 0, 1, 1}, {{radius, 0, 0}, {radius, 0, height}}));
}

Surface makeCone(double radius, double height) {
    checkPositive(radius, "radius", "makeCone");
    checkPositive(height, "height", "makeCone");
    return makeRevolution(Curve(1, {0, 0, 1, 1}, {{radius, 0, 0}, {0, 0, height}}));
}

Surface makeTorus(double major, double minor) {
    checkPositive(major, "major radius", "makeTorus");
    checkPositive(minor, "minor radius", "makeTorus");
    if (!(minor < major)) throw GeometryError("makeTorus: the minor radius must be below the major radius");
    return makeRevolution(makeCircle({major, 0, 0}, {1, 0, 0}, {0, 0, 1}, minor));
}

}  // namespace geom
