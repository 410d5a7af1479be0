#pragma once

#include "geom/Surface.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace acsynt {

/// One knot-span piece of a bicubic component surface, with what ACSYNT's PATCH_DATA keeps:
/// its 8 + 8 local knots and 16 B-spline control points, the same piece as a Bezier hull, and
/// the points and tangents the DEFINE POINT and mapping steps start from. The surface's v is w.
struct Patch {
    int number = 0;          ///< 1-based, u-major: number = row * countW + column + 1
    std::size_t row = 0;     ///< patch index along u (0-based)
    std::size_t column = 0;  ///< patch index along w (0-based)
    std::size_t spanU = 0;   ///< knot span in the surface: knotsU[spanU] = u0
    std::size_t spanW = 0;   ///< knotsV[spanW] = w0
    double u0 = 0, u1 = 0, w0 = 0, w1 = 0;
    std::array<double, 8> knotsU{};  ///< knots spanU-3 .. spanU+4; knotsU[3] = u0, knotsU[4] = u1
    std::array<double, 8> knotsW{};
    std::array<glm::dvec3, 16> hull{};    ///< control points (spanU-3+i, spanW-3+j) at [i * 4 + j]
    std::array<glm::dvec3, 16> bezier{};  ///< Bezier points of the piece on [u0,u1] x [w0,w1], [i * 4 + j]
    glm::dvec3 corner{0.0};               ///< S(u0, w0)
    glm::dvec3 u1w0{0.0};                 ///< S(u1, w0)
    glm::dvec3 u0w1{0.0};                 ///< S(u0, w1)
    glm::dvec3 middle{0.0};               ///< S at the middle of both intervals
    glm::dvec3 tangentU{0.0};             ///< dS/du at the corner
    glm::dvec3 tangentW{0.0};             ///< dS/dw at the corner
    glm::dvec3 normal{0.0};               ///< unit normal at the corner (geom::normal's rule at poles)

    bool contains(double u, double w) const { return u >= u0 && u <= u1 && w >= w0 && w <= w1; }
};

/// All patches of a surface, u-major, one per non-empty knot span pair.
struct PatchList {
    std::size_t countU = 0;
    std::size_t countW = 0;
    std::vector<Patch> patches;

    std::size_t size() const { return patches.size(); }
    /// The patch whose intervals hold (u, w); on a shared edge the later patch (the one that
    /// starts there) wins, except at the domain end. Null outside the domain.
    const Patch* find(double u, double w) const;
};

/// The patch list of a polynomial bicubic surface; throws geom::GeometryError for any other.
PatchList buildPatches(const geom::Surface& surface);

/// The patch's piece evaluated from its local knots and hull alone (a 4 x 4 surface on 8 + 8 knots).
glm::dvec3 evaluatePatchHull(const Patch& patch, double u, double w);

/// The patch's piece evaluated from its Bezier points (de Casteljau), (u, w) in surface parameters.
glm::dvec3 evaluateBezierPatch(const Patch& patch, double u, double w);

/// Power-basis coefficients of the piece (ACSYNT's bicubic_coef): S = sum c[i * 4 + j] s^i t^j
/// with s = (u - u0) / (u1 - u0) and t = (w - w0) / (w1 - w0) in [0, 1].
std::array<glm::dvec3, 16> powerBasisCoefficients(const Patch& patch);

}  // namespace acsynt
