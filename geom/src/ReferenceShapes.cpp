#include "geom/ReferenceShapes.h"

#include "geom/GeometryError.h"
#include "geom/GlobalInterpolation.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace geom {

Curve iBeamCurve(std::size_t controlPoints) {
    if (controlPoints < 4 || controlPoints > kMaxSamplePoints)
        throw GeometryError("iBeamCurve: need 4 to " + std::to_string(kMaxSamplePoints) + " control points");
    std::vector<glm::dvec3> points(controlPoints);
    for (std::size_t i = 0; i < controlPoints; ++i) {
        const double x = -180.0 + 360.0 * static_cast<double>(i) / static_cast<double>(controlPoints - 1);
        const double y = 5.0 + (x * x * x - x) * std::sin(std::numbers::pi * x / 180.0) / 7500.0;
        points[i] = {x, y, 0.0};
    }
    return interpolateCurve(points, uniformParameters(controlPoints), 3, Closure::Open);
}

std::vector<glm::dvec3> nacaSymmetricPoints(std::size_t count, double chord, double thickness) {
    if (count < 5 || count > kMaxSamplePoints)
        throw GeometryError("nacaSymmetricPoints: need 5 to " + std::to_string(kMaxSamplePoints) + " points");
    if (!(chord > 0.0) || !(thickness > 0.0))
        throw GeometryError("nacaSymmetricPoints: chord and thickness must be positive");
    std::vector<glm::dvec3> points(count);
    for (std::size_t i = 0; i < count; ++i) {
        // theta runs once around: x = (1 + cos theta) / 2 clusters points at both edges.
        const double theta = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(count - 1);
        const double x = 0.5 * (1.0 + std::cos(theta));
        const double half = 5.0 * thickness *
                            (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x -
                             0.1036 * x * x * x * x);  // -0.1036: closed trailing edge
        const double y = theta <= std::numbers::pi ? half : -half;
        points[i] = {chord * x, chord * y, 0.0};
    }
    points.back() = points.front();
    return points;
}

Curve nacaAirfoilCurve(double chord, std::size_t controlPoints, double thickness) {
    const std::vector<glm::dvec3> points = nacaSymmetricPoints(controlPoints, chord, thickness);
    return interpolateCurve(points, chordLengthParameters(points, Closure::Open), 3, Closure::Open);
}

Surface paraboloidSurface(std::size_t count) {
    if (count < 4 || count > 1024)
        throw GeometryError("paraboloidSurface: need 4 to 1024 control points each way");
    std::vector<glm::dvec3> grid(count * count);
    const std::vector<double> params = uniformParameters(count);
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t j = 0; j < count; ++j) {
            const double x = -50.0 + 100.0 * params[i];
            const double y = -50.0 + 100.0 * params[j];
            grid[i * count + j] = {x, y, (x * x + y * y) / 50.0};
        }
    return interpolateSurface(grid, count, count, GridParameters{params, params}, 3, 3, Closure::Open,
                              Closure::Open);
}

Surface wingSurface(std::size_t sections, std::size_t pointsPerSection) {
    if (sections < 4) throw GeometryError("wingSurface: need at least 4 sections");
    if (sections > kMaxSamplePoints / std::max<std::size_t>(pointsPerSection, 1))
        throw GeometryError("wingSurface: " + std::to_string(sections) + " x " +
                            std::to_string(pointsPerSection) + " points are more than " +
                            std::to_string(kMaxSamplePoints));
    const double rootChord = 192.0, semiSpan = 480.0;
    const double sweep = std::tan(30.0 * std::numbers::pi / 180.0);
    const double dihedral = std::tan(3.0 * std::numbers::pi / 180.0);
    const std::vector<glm::dvec3> airfoil = nacaSymmetricPoints(pointsPerSection, 1.0, 0.12);
    const std::vector<double> paramsV = chordLengthParameters(airfoil, Closure::Open);
    const std::vector<double> paramsU = uniformParameters(sections);
    std::vector<glm::dvec3> grid(sections * pointsPerSection);
    for (std::size_t i = 0; i < sections; ++i) {
        const double s = paramsU[i];
        const double chord = rootChord * (1.0 - 0.65 * std::pow(s, 1.5));
        const double twist = -3.0 * std::numbers::pi / 180.0 * s * s;
        const double leadingEdge = s * semiSpan * sweep;
        for (std::size_t j = 0; j < pointsPerSection; ++j) {
            // Section in (chordwise, thickness), twisted about its quarter chord.
            const double cx = (airfoil[j].x - 0.25) * chord, cz = airfoil[j].y * chord;
            const double x = leadingEdge + 0.25 * chord + cx * std::cos(twist) + cz * std::sin(twist);
            const double z = s * semiSpan * dihedral - cx * std::sin(twist) + cz * std::cos(twist);
            grid[i * pointsPerSection + j] = {x, s * semiSpan, z};
        }
    }
    return interpolateSurface(grid, sections, pointsPerSection, GridParameters{paramsU, paramsV}, 3, 3,
                              Closure::Open, Closure::Open);
}

}  // namespace geom
