#include "acsynt/Naca4.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace acsynt {

Naca4Airfoil parseNaca4(std::string_view code) {
    if (code.size() != 4)
        throw std::invalid_argument("NACA code '" + std::string(code) + "' must have exactly 4 digits");
    for (char c : code)
        if (c < '0' || c > '9')
            throw std::invalid_argument("NACA code '" + std::string(code) + "' must have exactly 4 digits");
    Naca4Airfoil a;
    a.code = std::string(code);
    a.maxCamber = (code[0] - '0') / 100.0;
    a.camberPosition = (code[1] - '0') / 10.0;
    a.thickness = ((code[2] - '0') * 10 + (code[3] - '0')) / 100.0;
    if (a.thickness <= 0.0) throw std::invalid_argument("NACA code '" + a.code + "' has zero thickness");
    if ((a.maxCamber > 0.0) != (a.camberPosition > 0.0))
        throw std::invalid_argument("NACA code '" + a.code +
                                    "' needs both a camber and a camber position, or neither");
    return a;
}

double naca4HalfThickness(double thickness, double x, TrailingEdge edge) {
    const double a4 = edge == TrailingEdge::Closed ? 0.1036 : 0.1015;
    return 5.0 * thickness *
           (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x - a4 * x * x * x * x);
}

double naca4Camber(const Naca4Airfoil& a, double x) {
    const double m = a.maxCamber, p = a.camberPosition;
    if (m == 0.0) return 0.0;
    if (x < p) return m / (p * p) * (2.0 * p * x - x * x);
    return m / ((1.0 - p) * (1.0 - p)) * ((1.0 - 2.0 * p) + 2.0 * p * x - x * x);
}

double naca4CamberSlope(const Naca4Airfoil& a, double x) {
    const double m = a.maxCamber, p = a.camberPosition;
    if (m == 0.0) return 0.0;
    if (x < p) return 2.0 * m / (p * p) * (p - x);
    return 2.0 * m / ((1.0 - p) * (1.0 - p)) * (p - x);
}

glm::dvec2 naca4Upper(const Naca4Airfoil& a, double x, TrailingEdge edge) {
    const double yt = naca4HalfThickness(a.thickness, x, edge);
    const double theta = std::atan(naca4CamberSlope(a, x));
    return {x - yt * std::sin(theta), naca4Camber(a, x) + yt * std::cos(theta)};
}

glm::dvec2 naca4Lower(const Naca4Airfoil& a, double x, TrailingEdge edge) {
    const double yt = naca4HalfThickness(a.thickness, x, edge);
    const double theta = std::atan(naca4CamberSlope(a, x));
    return {x + yt * std::sin(theta), naca4Camber(a, x) - yt * std::cos(theta)};
}

std::vector<glm::dvec2> naca4Contour(const Naca4Airfoil& a, std::size_t pointCount) {
    if (pointCount < 5 || pointCount % 2 == 0)
        throw std::invalid_argument("an airfoil contour needs an odd number of points, at least 5; got " +
                                    std::to_string(pointCount));
    const std::size_t k = (pointCount - 1) / 2;
    auto station = [k](std::size_t i) {
        return 0.5 * (1.0 - std::cos(std::numbers::pi * static_cast<double>(i) / static_cast<double>(k)));
    };
    std::vector<glm::dvec2> contour;
    contour.reserve(pointCount);
    // The sharp trailing edge is the point (1, 0) exactly, shared by both surfaces.
    contour.push_back({1.0, 0.0});
    for (std::size_t i = k - 1; i >= 1; --i)
        contour.push_back(naca4Upper(a, station(i), TrailingEdge::Closed));
    contour.push_back({0.0, 0.0});
    for (std::size_t i = 1; i < k; ++i) contour.push_back(naca4Lower(a, station(i), TrailingEdge::Closed));
    contour.push_back({1.0, 0.0});
    return contour;
}

}  // namespace acsynt
