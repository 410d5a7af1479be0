#pragma once

#include <glm/vec2.hpp>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace acsynt {

/// Whether a NACA section ends in the standard finite-thickness trailing edge (coefficient
/// -0.1015) or in a sharp one (-0.1036), which the lofted wings use so the upper and lower
/// surfaces meet in one edge.
enum class TrailingEdge { Open, Closed };

/// A NACA 4-digit airfoil "MPTT": maximum camber M/100 at P/10 of the chord, thickness TT/100.
struct Naca4Airfoil {
    std::string code;           ///< the four digits as written, e.g. "2412"
    double maxCamber = 0.0;     ///< m, fraction of the chord
    double camberPosition = 0;  ///< p, fraction of the chord (0 for a symmetric section)
    double thickness = 0.0;     ///< t, fraction of the chord
};

/// Reads a 4-digit code; throws std::invalid_argument naming the reason for anything else
/// (not four digits, zero thickness, camber without a camber position or the reverse).
Naca4Airfoil parseNaca4(std::string_view code);

/// Half thickness y_t(x) = 5t (0.2969 sqrt(x) - 0.1260 x - 0.3516 x^2 + 0.2843 x^3 - a4 x^4),
/// x in [0, 1] of the chord.
double naca4HalfThickness(double thickness, double x, TrailingEdge edge = TrailingEdge::Open);

/// Mean camber line y_c(x) and its slope dy_c/dx.
double naca4Camber(const Naca4Airfoil& airfoil, double x);
double naca4CamberSlope(const Naca4Airfoil& airfoil, double x);

/// Points (x, z) of the upper and lower surface at chord station x, the thickness laid off
/// normal to the camber line.
glm::dvec2 naca4Upper(const Naca4Airfoil& airfoil, double x, TrailingEdge edge = TrailingEdge::Open);
glm::dvec2 naca4Lower(const Naca4Airfoil& airfoil, double x, TrailingEdge edge = TrailingEdge::Open);

/// The closed section contour in chord units, sharp trailing edge: from the trailing edge along
/// the upper surface to the leading edge and back along the lower surface, pointCount points
/// (odd, >= 5), cosine-spaced in x so the leading edge is dense. The first and last points are
/// the same trailing-edge point.
std::vector<glm::dvec2> naca4Contour(const Naca4Airfoil& airfoil, std::size_t pointCount);

}  // namespace acsynt
