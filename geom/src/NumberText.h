#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace geom::detail {

/// A number as error messages quote it: the fewest significant digits (6 to 17) that read back
/// as the same double, so 1e-9 is not "0.000000" and two knots that differ in their last digit
/// print differently.
inline std::string numberText(double value) {
    char text[32];
    for (int digits = 6; digits <= 17; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, value);
        if (!std::isfinite(value) || std::strtod(text, nullptr) == value) break;
    }
    return text;
}

}  // namespace geom::detail
