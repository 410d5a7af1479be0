#include "Checked.h"
#include "NumberText.h"

#include "geom/GeometryError.h"

#include <cmath>
#include <string>

namespace geom::detail {

// The failure path only: validate() names the broken rule in its own words; it is stricter than
// checkShape, so the plain throws after it are not reached.
void explainShape(const Curve& curve, const char* where) {
    validate(curve, where);
    throw GeometryError(std::string(where) + ": curve: its shape is invalid");
}

void explainShape(const Surface& surface, const char* where) {
    validate(surface, where);
    throw GeometryError(std::string(where) + ": surface: its shape is invalid");
}

void parameterOutside(double value, double start, double end, const char* where, const char* name) {
    throw GeometryError(std::string(where) + ": parameter " + name + " = " + detail::numberText(value) +
                        " is outside the domain [" + detail::numberText(start) + ", " +
                        detail::numberText(end) + "]");
}

void spanNotOrdered(std::size_t span, const char* where) {
    throw GeometryError(std::string(where) + ": the knots around span " + std::to_string(span) +
                        " are not finite and non-decreasing");
}

void resultNotFinite(const char* where) {
    throw GeometryError(std::string(where) +
                        ": the result is not finite (a control point that is not finite, or a weight "
                        "that is not a positive normal number, near the parameter)");
}

}  // namespace geom::detail
