#include "phigs/store/Gdp.h"

#include "geom/Primitives.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace phigs {
namespace {

// Relative to the figure's size, below which points count as coincident or collinear.
constexpr double kDegenerate = 1e-12;

// A 2D circle lies in z = 0; an arc turns the way its three points do.
glm::dvec3 planeNormal(const GdpElement& e) {
    if (e.twoD && e.identifier == gdp::Circle) return {0, 0, 1};
    return glm::cross(e.points[1] - e.points[0], e.points[2] - e.points[0]);
}

std::size_t pointsNeeded(const GdpElement& e) {
    return e.identifier == gdp::Circle && e.twoD ? 2 : 3;
}

// The circle through three points: its centre, or nullopt when they are (nearly) collinear.
std::optional<glm::dvec3> circumcentre(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 ab = b - a, ac = c - a, n = glm::cross(ab, ac);
    const double nn = glm::dot(n, n);
    const double scale = std::max(glm::dot(ab, ab), glm::dot(ac, ac));
    if (!(nn > kDegenerate * scale * scale)) return std::nullopt;
    return a + (glm::dot(ab, ab) * glm::cross(ac, n) + glm::dot(ac, ac) * glm::cross(n, ab)) / (2.0 * nn);
}

}  // namespace

bool isRegisteredGdp(int identifier) {
    return identifier == gdp::Circle || identifier == gdp::ThreePointArc;
}

std::string checkGdp(const GdpElement& e) {
    if (!isRegisteredGdp(e.identifier)) return {};
    const char* name = e.identifier == gdp::Circle ? "GDP CIRCLE" : "GDP CIRCULAR ARC";
    if (e.points.size() != pointsNeeded(e))
        return std::string(name) + " needs " + std::to_string(pointsNeeded(e)) + " points, has " +
               std::to_string(e.points.size());
    const double radius = glm::length(e.points[1] - e.points[0]);
    if (!(radius > 0.0)) return std::string(name) + ": its first two points coincide";
    if (e.identifier == gdp::Circle) {
        const glm::dvec3 n = planeNormal(e);
        if (!(glm::dot(n, n) > kDegenerate * std::pow(radius, 4)))
            return std::string(name) + ": its three points do not fix a plane";
        return {};
    }
    if (!circumcentre(e.points[0], e.points[1], e.points[2]))
        return std::string(name) + ": its three points are collinear";
    return {};
}

std::optional<geom::Curve> gdpCurve(const GdpElement& e) {
    if (!isRegisteredGdp(e.identifier) || !checkGdp(e).empty()) return std::nullopt;
    const glm::dvec3 normal = glm::normalize(planeNormal(e));
    if (e.identifier == gdp::Circle) {
        const glm::dvec3 x = e.points[1] - e.points[0];
        const double radius = glm::length(x);
        return geom::makeCircle(e.points[0], x / radius, glm::cross(normal, x / radius), radius);
    }
    // The arc turns counterclockwise about (b - a) x (c - a), which meets a, b, c in that order.
    const glm::dvec3 centre = *circumcentre(e.points[0], e.points[1], e.points[2]);
    const glm::dvec3 x = e.points[0] - centre;
    const double radius = glm::length(x);
    const glm::dvec3 xAxis = x / radius, yAxis = glm::cross(normal, xAxis);
    const glm::dvec3 toEnd = e.points[2] - centre;
    double sweep = std::atan2(glm::dot(toEnd, yAxis), glm::dot(toEnd, xAxis));
    if (sweep <= 0.0) sweep += 2.0 * std::numbers::pi;
    return geom::makeArc(centre, xAxis, yAxis, radius, 0.0, sweep);
}

}  // namespace phigs
