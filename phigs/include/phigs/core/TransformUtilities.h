#pragma once

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <optional>

namespace phigs {

// The PHIGS transformation utilities (ISO 9592 clause 4.7): matrices act on column vectors
// (x' = M x), so the translation sits in the last column; angles are in radians, positive
// counter-clockwise looking down the axis towards the origin. 3D matrices are 4 x 4, 2D 3 x 3.

/// TRANSLATE 3 / TRANSLATE.
glm::dmat4 translate3(const glm::dvec3& shift);
glm::dmat3 translate2(const glm::dvec2& shift);
/// SCALE 3 / SCALE.
glm::dmat4 scale3(const glm::dvec3& factors);
glm::dmat3 scale2(const glm::dvec2& factors);
/// ROTATE X, ROTATE Y, ROTATE Z / ROTATE (about the origin in the plane).
glm::dmat4 rotateX(double angle);
glm::dmat4 rotateY(double angle);
glm::dmat4 rotateZ(double angle);
glm::dmat3 rotate2(double angle);
/// BUILD TRANSFORMATION MATRIX 3: scale, rotate about x, then y, then z, all relative to the
/// fixed point, then shift.
glm::dmat4 buildTransformationMatrix3(const glm::dvec3& fixedPoint, const glm::dvec3& shift,
                                      const glm::dvec3& angles, const glm::dvec3& scale);
/// BUILD TRANSFORMATION MATRIX: scale, rotate, relative to the fixed point, then shift.
glm::dmat3 buildTransformationMatrix2(const glm::dvec2& fixedPoint, const glm::dvec2& shift, double angle,
                                      const glm::dvec2& scale);
/// COMPOSE TRANSFORMATION MATRIX 3 / COMPOSE TRANSFORMATION MATRIX: built x m, so m applies
/// first and the built transformation after it (the order the PHIGS C binding's manual pages
/// give: result = a x b with b the input matrix, Sun Microsystems 1991).
glm::dmat4 composeTransformationMatrix3(const glm::dmat4& m, const glm::dvec3& fixedPoint,
                                        const glm::dvec3& shift, const glm::dvec3& angles,
                                        const glm::dvec3& scale);
glm::dmat3 composeTransformationMatrix2(const glm::dmat3& m, const glm::dvec2& fixedPoint,
                                        const glm::dvec2& shift, double angle, const glm::dvec2& scale);
/// TRANSFORM POINT 3 / TRANSFORM POINT: the homogeneous product divided by w; nothing when w
/// is 0 or the result is not finite (the C binding answers error 908 then).
std::optional<glm::dvec3> transformPoint3(const glm::dmat4& m, const glm::dvec3& p);
std::optional<glm::dvec2> transformPoint2(const glm::dmat3& m, const glm::dvec2& p);
/// The homogeneous product divided by w, or by 1 where w is 0: the drawing and picking paths'
/// point transform, which never refuses a point.
inline glm::dvec3 projectPoint3(const glm::dmat4& m, const glm::dvec3& p) {
    const glm::dvec4 q = m * glm::dvec4(p, 1.0);
    return glm::dvec3(q) / (q.w != 0.0 ? q.w : 1.0);
}

/// Whether every coordinate is finite (no NaN, no infinity).
inline bool allFinite(const glm::dvec3& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

}  // namespace phigs
