#pragma once

#include "phigs/core/ErrorLog.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace phigs {

enum class ProjectionType { Parallel, Perspective };

/// The view mapping parameters of EVALUATE VIEW MAPPING MATRIX 3, in view reference coordinates
/// (u, v, n): the window on the view plane, the projection viewport in NPC, the projection
/// reference point and the view plane, back and front plane distances along n.
struct ViewMapping {
    glm::dvec2 windowMin{-1.0}, windowMax{1.0};
    glm::dvec3 viewportMin{0.0}, viewportMax{1.0};
    ProjectionType projection = ProjectionType::Parallel;
    glm::dvec3 projectionReferencePoint{0.0, 0.0, 1.0};
    double viewPlaneDistance = 0.0;
    double backPlaneDistance = 0.0;
    double frontPlaneDistance = 1.0;
};

/// EVALUATE VIEW ORIENTATION MATRIX 3: world -> VRC, the view reference point to the origin, n
/// along the view plane normal, v the projection of the view up vector. Errors 159, 160, 161, and
/// -208 for an input that is not finite.
glm::dmat4 evaluateViewOrientationMatrix(const glm::dvec3& viewReferencePoint,
                                         const glm::dvec3& viewPlaneNormal, const glm::dvec3& viewUp,
                                         ErrorLog* log = nullptr);

/// EVALUATE VIEW MAPPING MATRIX 3: VRC -> NPC (homogeneous for perspective), the window onto the
/// projection viewport, the back plane to viewportMin.z and the front plane to viewportMax.z.
/// A perspective matrix gives w > 0 in the view volume, also where the view plane lies beyond the
/// PRP. Errors 151, 152, 155, 158, 162, 163, 164, and -208 for an input that is not finite.
glm::dmat4 evaluateViewMappingMatrix(const ViewMapping& mapping, ErrorLog* log = nullptr);

}  // namespace phigs
