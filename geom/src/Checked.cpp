#include "Checked.h"

#include "geom/GeometryError.h"

#include <cmath>
#include <string>
#include <vector>

namespace geom::detail {
namespace {

// Strings are built only on the way to a throw: these checks run once per evaluated point.
[[noreturn]] void fail(const char* where, const char* what, const std::string& message) {
    throw GeometryError(std::string(where) + ": " + what + ": " + message);
}

void checkDirection(const std::vector<double>& knots, int degree, std::size_t count, const char* where,
                    const char* what) {
    if (degree < 1) fail(where, what, "degree " + std::to_string(degree) + " must be at least 1");
    const std::size_t p = static_cast<std::size_t>(degree);
    if (count < p + 1)
        fail(where, what,
             std::to_string(count) + " control points are too few for degree " + std::to_string(degree));
    if (knots.size() != count + p + 1)
        fail(where, what,
             std::to_string(knots.size()) + " knots for " + std::to_string(count) +
                 " control points of degree " + std::to_string(degree));
    if (!std::isfinite(knots[p]) || !std::isfinite(knots[count]) || !(knots[p] < knots[count]))
        fail(where, what, "the parameter domain [knots[degree], knots[n]] is empty or not finite");
}

void checkWeightCount(std::size_t weights, std::size_t points, const char* where, const char* what) {
    if (weights != 0 && weights != points)
        fail(where, what,
             std::to_string(weights) + " weights for " + std::to_string(points) + " control points");
}

}  // namespace

void explainShape(const Curve& curve, const char* where) {
    checkDirection(curve.knots, curve.degree, curve.points.size(), where, "curve");
    checkWeightCount(curve.weights.size(), curve.points.size(), where, "curve");
    fail(where, "curve", "its shape is invalid");  // unreachable while the rules match checkShape's
}

void explainShape(const Surface& surface, const char* where) {
    std::size_t total = 0;  // countU * countV, refused when it overflows (no division per point)
    if (__builtin_mul_overflow(surface.countU, surface.countV, &total) || total != surface.points.size() ||
        total == 0)
        fail(where, "surface",
             std::to_string(surface.points.size()) + " control points for a " +
                 std::to_string(surface.countU) + " x " + std::to_string(surface.countV) + " net");
    checkDirection(surface.knotsU, surface.degreeU, surface.countU, where, "surface u direction");
    checkDirection(surface.knotsV, surface.degreeV, surface.countV, where, "surface v direction");
    checkWeightCount(surface.weights.size(), surface.points.size(), where, "surface");
    fail(where, "surface", "its shape is invalid");  // unreachable while the rules match checkShape's
}

void parameterOutside(double value, double start, double end, const char* where, const char* name) {
    throw GeometryError(std::string(where) + ": parameter " + name + " = " + std::to_string(value) +
                        " is outside the domain [" + std::to_string(start) + ", " + std::to_string(end) +
                        "]");
}

void spanNotOrdered(std::size_t span, const char* where) {
    throw GeometryError(std::string(where) + ": the knots around span " + std::to_string(span) +
                        " are not finite and non-decreasing");
}

void resultNotFinite(const char* where) {
    throw GeometryError(std::string(where) +
                        ": the result is not finite (a control point that is not finite, or a weight "
                        "that is not positive, near the parameter)");
}

}  // namespace geom::detail
