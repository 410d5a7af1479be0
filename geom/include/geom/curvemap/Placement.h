#pragma once

#include "geom/Surface.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace geom::curvemap {

/// Where and how a plane curve is put on a surface (the ACSYNT curve-mapping thesis, §7.5): the reference
/// point (u, w), FLIP (reverse the normal), ROTATE (quarter turns counter-clockwise about the normal) and an
/// offset of the curve plane along the normal (the thesis draws it "above").
struct Placement {
    glm::dvec2 reference{0.0};
    bool flipped = false;
    int quarterTurns = 0;
    double offset = 0.0;
};

/// The curve's frame at the reference point: z = unit normal (reversed when flipped), x = the
/// unit u tangent turned by the quarter turns, y = z x x; orthonormal and right-handed even on
/// skewed patches. `transform` takes curve (MCS) coordinates to model coordinates.
struct PlacementFrame {
    glm::dvec3 origin{0.0};        ///< reference point + offset * z
    glm::dvec3 surfacePoint{0.0};  ///< S(reference)
    glm::dvec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    glm::dvec3 tangentU{0.0}, tangentW{0.0};  ///< unit parametric tangents at the reference
    glm::dmat4 transform{1.0};

    glm::dvec3 toModel(const glm::dvec3& curvePoint) const;
    glm::dvec3 toCurve(const glm::dvec3& modelPoint) const;  ///< inverse of toModel
};

/// Computes the frame; throws GeometryError when the reference lies outside the domain or the
/// surface has no tangent plane there.
PlacementFrame placementFrame(const Surface& surface, const Placement& placement);

}  // namespace geom::curvemap
