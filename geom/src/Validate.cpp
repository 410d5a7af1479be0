#include "Checked.h"
#include "NumberText.h"
#include "geom/Curve.h"
#include "geom/GeometryError.h"
#include "geom/Surface.h"

#include <cmath>
#include <limits>
#include <string>
#include <string_view>

namespace geom {
namespace {

void checkKnots(const std::vector<double>& knots, int degree, std::size_t count, const std::string& where) {
    if (degree < 1) throw GeometryError(where + ": degree " + std::to_string(degree) + " must be at least 1");
    if (count < static_cast<std::size_t>(degree) + 1)
        throw GeometryError(where + ": " + std::to_string(count) + " control points are too few for degree " +
                            std::to_string(degree) + " (need at least degree + 1)");
    // A count near SIZE_MAX would wrap the sum below to a small number that an empty knot list
    // then matches: no curve has that many points.
    if (count > std::numeric_limits<std::size_t>::max() / 2)
        throw GeometryError(where + ": " + std::to_string(count) + " control points are too many");
    const std::size_t expected = count + static_cast<std::size_t>(degree) + 1;
    if (knots.size() != expected)
        throw GeometryError(where + ": " + std::to_string(knots.size()) + " knots given, but " +
                            std::to_string(count) + " control points of degree " + std::to_string(degree) +
                            " need " + std::to_string(expected));
    for (std::size_t i = 0; i < knots.size(); ++i) {
        if (!std::isfinite(knots[i]))
            throw GeometryError(where + ": knot " + std::to_string(i) + " is not a finite number");
        if (i > 0 && knots[i] < knots[i - 1])
            throw GeometryError(where + ": knots decrease at index " + std::to_string(i) + " (" +
                                detail::numberText(knots[i - 1]) + " then " + detail::numberText(knots[i]) +
                                ")");
        // The basis functions divide by knot differences: a subnormal one overflows them.
        if (i > 0 && knots[i] > knots[i - 1] && knots[i] - knots[i - 1] < std::numeric_limits<double>::min())
            throw GeometryError(where + ": knots " + std::to_string(i - 1) + " and " + std::to_string(i) +
                                " differ by less than the smallest normal double (2.2e-308)");
    }
    // Basis functions take differences of knots across the vector: they must not overflow.
    if (!std::isfinite(knots.back() - knots.front()))
        throw GeometryError(where + ": the knot span " + detail::numberText(knots.front()) + " to " +
                            detail::numberText(knots.back()) + " is wider than the largest double");
    std::size_t run = 1;
    for (std::size_t i = 1; i < knots.size(); ++i) {
        run = knots[i] == knots[i - 1] ? run + 1 : 1;
        if (run > static_cast<std::size_t>(degree) + 1)
            throw GeometryError(where + ": knot value " + detail::numberText(knots[i]) + " at index " +
                                std::to_string(i) + " has multiplicity above degree + 1");
    }
    if (!(knots[static_cast<std::size_t>(degree)] < knots[count]))
        throw GeometryError(where + ": the parameter domain [knots[degree], knots[n]] is empty");
}

void checkPointsAndWeights(const std::vector<glm::dvec3>& points, const std::vector<double>& weights,
                           const std::string& where) {
    for (std::size_t i = 0; i < points.size(); ++i)
        if (!detail::finite(points[i]))
            throw GeometryError(where + ": control point " + std::to_string(i) +
                                " has a non-finite coordinate");
    if (weights.empty()) return;
    if (weights.size() != points.size())
        throw GeometryError(where + ": " + std::to_string(weights.size()) + " weights for " +
                            std::to_string(points.size()) + " control points");
    for (std::size_t i = 0; i < weights.size(); ++i) {
        if (!detail::usableWeight(weights[i]))
            throw GeometryError(
                where + ": weight " + std::to_string(i) + " is " + detail::numberText(weights[i]) +
                ", weights must be finite and at least the smallest normal double (2.2e-308)");
        // Rational algorithms work on the homogeneous point (w x, w y, w z, w): it must be finite.
        if (!detail::finite(weights[i] * points[i]))
            throw GeometryError(where + ": control point " + std::to_string(i) + " times its weight " +
                                detail::numberText(weights[i]) + " overflows a double");
    }
}

std::string prefixed(std::string_view where, const char* what) {
    return where.empty() ? std::string(what) : std::string(where) + ": " + what;
}

}  // namespace

void validate(const Curve& curve, std::string_view where) {
    checkKnots(curve.knots, curve.degree, curve.points.size(), prefixed(where, "curve"));
    checkPointsAndWeights(curve.points, curve.weights, prefixed(where, "curve"));
}

void validate(const Surface& surface, std::string_view where) {
    checkKnots(surface.knotsU, surface.degreeU, surface.countU, prefixed(where, "surface u direction"));
    checkKnots(surface.knotsV, surface.degreeV, surface.countV, prefixed(where, "surface v direction"));
    if (surface.countV == 0 || surface.points.size() / surface.countV != surface.countU ||
        surface.points.size() % surface.countV != 0)
        throw GeometryError(prefixed(where, "surface") + ": " + std::to_string(surface.points.size()) +
                            " control points given for a " + std::to_string(surface.countU) + " x " +
                            std::to_string(surface.countV) + " net");
    checkPointsAndWeights(surface.points, surface.weights, prefixed(where, "surface"));
}

Curve::Curve(int degree_, std::vector<double> knots_, std::vector<glm::dvec3> points_,
             std::vector<double> weights_)
    : degree(degree_), knots(std::move(knots_)), points(std::move(points_)), weights(std::move(weights_)) {
    validate(*this);
}

Surface::Surface(int degreeU_, int degreeV_, std::vector<double> knotsU_, std::vector<double> knotsV_,
                 std::size_t countU_, std::size_t countV_, std::vector<glm::dvec3> points_,
                 std::vector<double> weights_)
    : degreeU(degreeU_),
      degreeV(degreeV_),
      knotsU(std::move(knotsU_)),
      knotsV(std::move(knotsV_)),
      countU(countU_),
      countV(countV_),
      points(std::move(points_)),
      weights(std::move(weights_)) {
    validate(*this);
}

}  // namespace geom
