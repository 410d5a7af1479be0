#pragma once

#include <stdexcept>
#include <string>

namespace geom {

/// Thrown when geometric input breaks a rule (decreasing knots, sizes that disagree, a
/// non-positive weight, a non-finite number, ...); the message names the rule and the place.
class GeometryError : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

}  // namespace geom
