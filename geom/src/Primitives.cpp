#include "geom/Primitives.h"

#include "geom/GeometryError.h"

#include "NumberText.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
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
        throw GeometryError(std::string(where) + ": " + what + " " + detail::numberText(x) +
                            " must be positive");
}

/// The plane of a circle or arc: two orthonormal axes.
struct PlaneAxes {
    glm::dvec3 x, y;
};

/// xAxis's direction, and yAxis's part perpendicular to it, each of unit length. Axes that are
/// zero, parallel or not finite span no plane (the "circle" would be a segment or a point) and are
/// refused.
PlaneAxes planeAxes(const glm::dvec3& xAxis, const glm::dvec3& yAxis, const char* where) {
    const double span = glm::length(glm::cross(xAxis, yAxis));
    if (!std::isfinite(span) || !(span > 1e-12 * glm::length(xAxis) * glm::length(yAxis)))
        throw GeometryError(std::string(where) + ": the axes must be finite, non-zero and not parallel");
    const glm::dvec3 x = xAxis / glm::length(xAxis);
    return {x, glm::normalize(yAxis - glm::dot(yAxis, x) * x)};
}

}  // namespace

Curve makeCircle(const glm::dvec3& center, const glm::dvec3& xAxis, const glm::dvec3& yAxis, double radius) {
    checkPositive(radius, "radius", "makeCircle");
    const PlaneAxes axes = planeAxes(xAxis, yAxis, "makeCircle");
    std::vector<glm::dvec3> points;
    std::vector<double> weights;
    for (std::size_t j = 0; j < 9; ++j) {
        points.push_back(center + radius * (kCx[j] * axes.x + kCy[j] * axes.y));
        weights.push_back(circleWeight(j));
    }
    return Curve(2, kCircleKnots, points, weights);
}

Curve makeArc(const glm::dvec3& center, const glm::dvec3& xAxis, const glm::dvec3& yAxis, double radius,
              double startAngle, double endAngle) {
    checkPositive(radius, "radius", "makeArc");
    const PlaneAxes axes = planeAxes(xAxis, yAxis, "makeArc");
    const double sweep = endAngle - startAngle;
    if (!std::isfinite(startAngle) || !std::isfinite(sweep) || !(sweep > 0.0) ||
        sweep > 2.0 * std::numbers::pi + 1e-12)
        throw GeometryError("makeArc: sweep " + detail::numberText(sweep) + " must lie in (0, 2 pi]");
    // Each segment spans at most a quarter turn, so its middle weight cos(half angle) stays >= 0.7.
    const int segments = std::max(1, static_cast<int>(std::ceil(sweep / (0.5 * std::numbers::pi) - 1e-12)));
    const double step = sweep / segments;
    auto onCircle = [&](double angle, double r) {
        return center + r * (std::cos(angle) * axes.x + std::sin(angle) * axes.y);
    };
    std::vector<glm::dvec3> points{onCircle(startAngle, radius)};
    std::vector<double> weights{1.0};
    std::vector<double> knots{0.0, 0.0, 0.0};
    for (int i = 1; i <= segments; ++i) {
        const double end = startAngle + step * i;
        // The middle point is where the end tangents meet: on the bisector, r / cos(step / 2) out.
        points.push_back(onCircle(end - 0.5 * step, radius / std::cos(0.5 * step)));
        weights.push_back(std::cos(0.5 * step));
        points.push_back(onCircle(end, radius));
        weights.push_back(1.0);
        const double knot = i == segments ? 1.0 : static_cast<double>(i) / segments;
        knots.insert(knots.end(), {knot, knot});
    }
    knots.push_back(1.0);
    return Curve(2, knots, points, weights);
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
    // x is the distance from the axis: a profile on both sides of it would sweep a surface through
    // itself. The poles bound the curve (its convex hull), so all of them on one side keep it there.
    // Rounding may leave a point on the axis a hair below zero.
    double size = 0.0;
    for (const glm::dvec3& p : profile.points) size = std::max(size, glm::length(p));
    for (std::size_t i = 0; i < profile.points.size(); ++i)
        if (profile.points[i].x < -1e-12 * size)
            throw GeometryError("makeRevolution: profile point " + std::to_string(i) + " has x " +
                                detail::numberText(profile.points[i].x) +
                                "; the profile's x is its distance from the axis and must not be negative");
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
