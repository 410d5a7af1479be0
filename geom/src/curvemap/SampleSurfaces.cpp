#include "geom/curvemap/SampleSurfaces.h"

#include "geom/GeometryError.h"

#include <cmath>
#include <numbers>
#include <vector>

namespace geom::curvemap {

namespace {

/// Clamped uniform cubic knots 0,0,0,0,1,2,...,n,n,n,n for n patches.
std::vector<double> clampedUniform(std::size_t patches) {
    std::vector<double> k(4, 0.0);
    for (std::size_t i = 1; i < patches; ++i) k.push_back(static_cast<double>(i));
    k.insert(k.end(), 4, static_cast<double>(patches));
    return k;
}

/// Greville abscissa of control point i of clamped uniform cubic knots: placing control points
/// there makes the parameterisation linear (linear precision).
double greville(const std::vector<double>& knots, std::size_t i) {
    return (knots[i + 1] + knots[i + 2] + knots[i + 3]) / 3.0;
}

}  // namespace

Surface makeWaveSurface(std::size_t patchesU, std::size_t patchesV, double size, double amplitude,
                        double wavelength) {
    if (patchesU == 0 || patchesV == 0 || !(size > 0.0) || !(wavelength > 0.0))
        throw GeometryError(
            "makeWaveSurface: needs at least one patch each way, a positive size and wavelength");
    const std::vector<double> ku = clampedUniform(patchesU), kv = clampedUniform(patchesV);
    const std::size_t nu = patchesU + 3, nv = patchesV + 3;
    std::vector<glm::dvec3> points;
    points.reserve(nu * nv);
    const double k = 2.0 * std::numbers::pi / wavelength;
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j) {
            const double x = size * (greville(ku, i) / static_cast<double>(patchesU) - 0.5);
            const double y = size * (greville(kv, j) / static_cast<double>(patchesV) - 0.5);
            points.push_back({x, y, amplitude * std::sin(k * x) * std::cos(k * y)});
        }
    return Surface(3, 3, ku, kv, nu, nv, std::move(points));
}

Surface makeFuselageSurface(std::size_t patchesU, std::size_t patchesV, double length, double radius) {
    if (patchesU < 3 || patchesV == 0 || !(length > 0.0) || !(radius > 0.0))
        throw GeometryError("makeFuselageSurface: needs at least 3 patches around, 1 along, positive sizes");
    // u: periodic uniform knots -3..patchesU+3, control points wrap (j + patchesU == j).
    std::vector<double> ku;
    for (std::size_t i = 0; i < patchesU + 7; ++i) ku.push_back(static_cast<double>(i) - 3.0);
    const std::vector<double> kv = clampedUniform(patchesV);
    const std::size_t nu = patchesU + 3, nv = patchesV + 3;
    const double step = 2.0 * std::numbers::pi / static_cast<double>(patchesU);
    // A uniform cubic through a regular polygon of radius rho passes at rho (4 + 2 cos step) / 6.
    const double polygonScale = 6.0 / (4.0 + 2.0 * std::cos(step));
    auto profile = [](double s) {
        if (s < 0.4) return 0.45 + 0.55 * std::sin(0.5 * std::numbers::pi * s / 0.4);
        const double q = (s - 0.4) / 0.6;
        return 1.0 - 0.7 * q * q;
    };
    std::vector<glm::dvec3> points;
    points.reserve(nu * nv);
    for (std::size_t i = 0; i < nu; ++i) {
        // Control point i sits at Greville abscissa i - 1; u = 0 is on top (angle pi/2).
        const double angle = 0.5 * std::numbers::pi + step * (static_cast<double>(i) - 1.0);
        for (std::size_t j = 0; j < nv; ++j) {
            const double s = greville(kv, j) / static_cast<double>(patchesV);
            const double r = radius * profile(s) * polygonScale;
            points.push_back({length * s, r * std::cos(angle), 0.9 * r * std::sin(angle)});
        }
    }
    return Surface(3, 3, ku, kv, nu, nv, std::move(points));
}

Surface makeWingSurface(std::size_t patchesU, std::size_t patchesV, double span, double rootChord,
                        double thickness) {
    if (patchesU < 4 || patchesV == 0 || !(span > 0.0) || !(rootChord > 0.0) || !(thickness > 0.0))
        throw GeometryError("makeWingSurface: needs at least 4 patches around, 1 along, positive sizes");
    std::vector<double> ku;
    for (std::size_t i = 0; i < patchesU + 7; ++i) ku.push_back(static_cast<double>(i) - 3.0);
    const std::vector<double> kv = clampedUniform(patchesV);
    const std::size_t nu = patchesU + 3, nv = patchesV + 3;
    // NACA 00xx half thickness with the closed trailing edge coefficient.
    auto halfThickness = [thickness](double x) {
        return 5.0 * thickness *
               (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x -
                0.1036 * x * x * x * x);
    };
    std::vector<glm::dvec3> points;
    points.reserve(nu * nv);
    for (std::size_t i = 0; i < nu; ++i) {
        // Control point i at Greville abscissa i - 1; cosine spacing crowds the leading edge.
        const double phi =
            2.0 * std::numbers::pi * (static_cast<double>(i) - 1.0) / static_cast<double>(patchesU);
        const double x = 0.5 * (1.0 + std::cos(phi));
        const double z = (std::sin(phi) <= 0.0 ? 1.0 : -1.0) * halfThickness(x);
        for (std::size_t j = 0; j < nv; ++j) {
            const double s = greville(kv, j) / static_cast<double>(patchesV);
            const double chord = rootChord * (1.0 - 0.5 * s);
            points.push_back({0.2 * span * s + chord * x, span * s, chord * z});
        }
    }
    return Surface(3, 3, ku, kv, nu, nv, std::move(points));
}

}  // namespace geom::curvemap
