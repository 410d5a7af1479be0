#pragma once
// Shared by the session's source files (not installed): the pad's alternatives, the slider
// ranges and small element helpers.

#include "phigs/store/Element.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace acsynt::session_detail {

using namespace phigs;

inline const char* const title = "ACSYNT B-SPLINE MODULE V1.2.2";
inline const std::vector<std::string> padItems{"NORTH_WEST", "NORTH", "NORTH_EAST", "WEST", "CENTRE", "EAST",
                                               "SOUTH_WEST", "SOUTH", "SOUTH_EAST", "DONE"};
inline const char* const sliderNames[] = {"U", "W", "ROTATE", "ZOOM"};
inline const double sliderLow[] = {0, 0, -180, 0.25};
inline const double sliderHigh[] = {1, 1, 180, 8};

/// Half the shorter side of an oblique (3D) view's window at zoom 1, for a model whose bounding
/// sphere has `radius`: the whole sphere, whichever way the view turns.
inline double obliqueHalfSize(double radius) {
    return radius;
}

/// How a menu alternative is shown: underscores as blanks (SURF_REDN keeps its name).
inline std::string shown(const std::string& item) {
    if (item == "SURF_REDN") return item;
    std::string s = item;
    std::replace(s.begin(), s.end(), '_', ' ');
    return s;
}

inline std::string number(double v, int digits = 6) {
    std::ostringstream out;
    out.precision(digits);
    out << v;
    return out.str();
}

/// A whole prompt answer as one finite number (surrounding blanks allowed), else nothing:
/// "0.01" and " 3 " are numbers; "0.01abc", "1e999", "nan", "" and "3 4" are not.
inline std::optional<double> parseNumber(const std::string& text) {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string::npos) return std::nullopt;
    const auto last = text.find_last_not_of(" \t");
    const char* begin = text.data() + first;
    const char* end = text.data() + last + 1;
    if (*begin == '+') ++begin;  // from_chars takes no plus sign
    double value = 0;
    const auto [stop, ec] = std::from_chars(begin, end, value);
    if (ec != std::errc() || stop != end || !std::isfinite(value)) return std::nullopt;
    return value;
}

/// A length in model units read as metres, with an SI prefix and 3 significant digits
/// ("4.21 mm", "200 nm", "0").
inline std::string lengthText(double metres) {
    if (metres == 0) return "0";
    const double a = std::abs(metres);
    if (a >= 1) return number(metres, 3) + " m";
    if (a >= 1e-3) return number(metres * 1e3, 3) + " mm";
    if (a >= 1e-6) return number(metres * 1e6, 3) + " um";
    return number(metres * 1e9, 3) + " nm";
}

/// The error map's colour at fraction t of its scale: blue (0) through green to red (1 and above).
inline glm::dvec3 errorColour(double t) {
    t = std::clamp(t, 0.0, 1.0);
    return t < 0.5 ? glm::mix(glm::dvec3(0.1, 0.2, 1.0), glm::dvec3(0.1, 0.9, 0.2), t * 2)
                   : glm::mix(glm::dvec3(0.1, 0.9, 0.2), glm::dvec3(1.0, 0.1, 0.1), t * 2 - 1);
}

inline Element colourAttr(ElementType type, const glm::dvec3& rgb) {
    return ColourAttribute{type, Colour::fromRgb(rgb)};
}

inline Element textAt(const glm::dvec3& at, const std::string& s) {
    return TextElement{at, {1, 0, 0}, {0, 1, 0}, s, false};
}

}  // namespace acsynt::session_detail
