#include "phigs/view/ViewMatrices.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <string>

namespace phigs {
namespace {

template <class Vector>
void requireFinite(const Vector& value, const char* name, ErrorLog* log, const char* function) {
    for (int i = 0; i < Vector::length(); ++i)
        if (!std::isfinite(value[i]))
            raise(log, errors::NonFiniteValue, function, std::string(name) + " is not finite");
}

}  // namespace

glm::dmat4 evaluateViewOrientationMatrix(const glm::dvec3& viewReferencePoint,
                                         const glm::dvec3& viewPlaneNormal, const glm::dvec3& viewUp,
                                         ErrorLog* log) {
    const char* function = "EVALUATE VIEW ORIENTATION MATRIX 3";
    requireFinite(viewReferencePoint, "the view reference point", log, function);
    requireFinite(viewPlaneNormal, "the view plane normal", log, function);
    requireFinite(viewUp, "the view up vector", log, function);
    if (glm::length(viewPlaneNormal) == 0.0) raise(log, errors::ZeroViewPlaneNormal, function);
    if (glm::length(viewUp) == 0.0) raise(log, errors::ZeroViewUp, function);
    glm::dvec3 n = glm::normalize(viewPlaneNormal);
    glm::dvec3 side = glm::cross(viewUp, n);
    if (glm::length(side) <= 1e-12 * glm::length(viewUp))
        raise(log, errors::ViewUpParallelToNormal, function);
    glm::dvec3 u = glm::normalize(side);
    glm::dvec3 v = glm::cross(n, u);
    glm::dmat4 m(1.0);
    for (int c = 0; c < 3; ++c) {
        m[c][0] = u[c];
        m[c][1] = v[c];
        m[c][2] = n[c];
    }
    m[3][0] = -glm::dot(u, viewReferencePoint);
    m[3][1] = -glm::dot(v, viewReferencePoint);
    m[3][2] = -glm::dot(n, viewReferencePoint);
    return m;
}

glm::dmat4 evaluateViewMappingMatrix(const ViewMapping& p, ErrorLog* log) {
    const char* function = "EVALUATE VIEW MAPPING MATRIX 3";
    requireFinite(glm::dvec4(p.windowMin, p.windowMax), "the window", log, function);
    requireFinite(p.viewportMin, "the projection viewport", log, function);
    requireFinite(p.viewportMax, "the projection viewport", log, function);
    requireFinite(p.projectionReferencePoint, "the projection reference point", log, function);
    requireFinite(glm::dvec3(p.viewPlaneDistance, p.backPlaneDistance, p.frontPlaneDistance),
                  "a plane distance", log, function);
    if (p.windowMin.x >= p.windowMax.x || p.windowMin.y >= p.windowMax.y)
        raise(log, errors::InvalidWindow, function);
    if (p.viewportMin.x >= p.viewportMax.x || p.viewportMin.y >= p.viewportMax.y ||
        p.viewportMin.z > p.viewportMax.z)
        raise(log, errors::InvalidViewport, function);
    for (int i = 0; i < 3; ++i)
        if (p.viewportMin[i] < 0.0 || p.viewportMax[i] > 1.0)
            raise(log, errors::ProjectionViewportOutsideNpc, function);
    const double back = p.backPlaneDistance, front = p.frontPlaneDistance, vpd = p.viewPlaneDistance;
    const glm::dvec3 prp = p.projectionReferencePoint;
    const bool flat = p.viewportMin.z == p.viewportMax.z;
    if (front == back && !flat) raise(log, errors::FrontEqualsBack, function);
    if (back > front) raise(log, errors::BackInFrontOfFront, function);
    if (prp.z == vpd) raise(log, errors::PrpOnViewPlane, function);
    if (p.projection == ProjectionType::Perspective && prp.z >= back && prp.z <= front)
        raise(log, errors::PrpBetweenPlanes, function);

    const double sx = (p.viewportMax.x - p.viewportMin.x) / (p.windowMax.x - p.windowMin.x);
    const double sy = (p.viewportMax.y - p.viewportMin.y) / (p.windowMax.y - p.windowMin.y);
    const double zRange = p.viewportMax.z - p.viewportMin.z;
    glm::dmat4 m(0.0);  // m[column][row]
    if (p.projection == ProjectionType::Parallel) {
        // Shear along the direction of projection (PRP to the window centre) so that the
        // projectors become parallel to n, keeping the view plane fixed.
        glm::dvec3 centre{(p.windowMin.x + p.windowMax.x) / 2, (p.windowMin.y + p.windowMax.y) / 2, vpd};
        glm::dvec3 dop = centre - prp;
        double shu = -dop.x / dop.z, shv = -dop.y / dop.z;
        double sz = front == back ? 0.0 : zRange / (front - back);
        m[0][0] = sx;
        m[2][0] = sx * shu;
        m[3][0] = p.viewportMin.x + sx * (-shu * vpd - p.windowMin.x);
        m[1][1] = sy;
        m[2][1] = sy * shv;
        m[3][1] = p.viewportMin.y + sy * (-shv * vpd - p.windowMin.y);
        m[2][2] = sz;
        m[3][2] = p.viewportMin.z - sz * back;
        m[3][3] = 1.0;
        return m;
    }
    // Perspective: with PRP at the origin (u1 = u - prp), a point projects to u1 * d / n1 on the
    // view plane n1 = d; w = n1 / d keeps everything linear.
    const double d = vpd - prp.z;
    const double ax = p.viewportMin.x + (prp.x - p.windowMin.x) * sx;
    const double ay = p.viewportMin.y + (prp.y - p.windowMin.y) * sy;
    const double nFront = front - prp.z, nBack = back - prp.z;
    double a = 0.0, b = 0.0;
    if (flat || front == back) {
        a = p.viewportMax.z / d;
    } else {
        b = zRange / (d * (1.0 / nFront - 1.0 / nBack));
        a = (p.viewportMax.z - b * d / nFront) / d;
    }
    glm::dmat4 rows(0.0);
    rows[0][0] = sx;
    rows[2][0] = ax / d;
    rows[1][1] = sy;
    rows[2][1] = ay / d;
    rows[2][2] = a;
    rows[3][2] = b;
    rows[2][3] = 1.0 / d;
    glm::dmat4 toPrp(1.0);
    toPrp[3] = glm::dvec4(-prp, 1.0);
    // w = n1 / d is negative throughout the view volume where the view plane lies beyond the
    // PRP (an inverted image, which the standard allows); the same matrix negated keeps x/w, y/w
    // and z/w and gives w > 0 there, which clipping requires.
    return nBack / d > 0.0 ? rows * toPrp : -(rows * toPrp);
}

}  // namespace phigs
