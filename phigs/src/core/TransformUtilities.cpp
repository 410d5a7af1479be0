#include "phigs/core/TransformUtilities.h"

#include <cmath>

namespace phigs {

namespace {

bool finite(double x) {
    return std::isfinite(x);
}

}  // namespace

glm::dmat4 translate3(const glm::dvec3& shift) {
    glm::dmat4 m(1.0);
    m[3] = glm::dvec4(shift, 1.0);
    return m;
}

glm::dmat3 translate2(const glm::dvec2& shift) {
    glm::dmat3 m(1.0);
    m[2] = glm::dvec3(shift, 1.0);
    return m;
}

glm::dmat4 scale3(const glm::dvec3& factors) {
    glm::dmat4 m(1.0);
    for (int i = 0; i < 3; ++i) m[i][i] = factors[i];
    return m;
}

glm::dmat3 scale2(const glm::dvec2& factors) {
    glm::dmat3 m(1.0);
    m[0][0] = factors.x;
    m[1][1] = factors.y;
    return m;
}

// glm is column-major: m[column][row].
glm::dmat4 rotateX(double angle) {
    glm::dmat4 m(1.0);
    const double c = std::cos(angle), s = std::sin(angle);
    m[1][1] = c, m[2][1] = -s, m[1][2] = s, m[2][2] = c;
    return m;
}

glm::dmat4 rotateY(double angle) {
    glm::dmat4 m(1.0);
    const double c = std::cos(angle), s = std::sin(angle);
    m[0][0] = c, m[2][0] = s, m[0][2] = -s, m[2][2] = c;
    return m;
}

glm::dmat4 rotateZ(double angle) {
    glm::dmat4 m(1.0);
    const double c = std::cos(angle), s = std::sin(angle);
    m[0][0] = c, m[1][0] = -s, m[0][1] = s, m[1][1] = c;
    return m;
}

glm::dmat3 rotate2(double angle) {
    glm::dmat3 m(1.0);
    const double c = std::cos(angle), s = std::sin(angle);
    m[0][0] = c, m[1][0] = -s, m[0][1] = s, m[1][1] = c;
    return m;
}

glm::dmat4 buildTransformationMatrix3(const glm::dvec3& fixedPoint, const glm::dvec3& shift,
                                      const glm::dvec3& angles, const glm::dvec3& scale) {
    return translate3(shift) * translate3(fixedPoint) * rotateZ(angles.z) * rotateY(angles.y) *
           rotateX(angles.x) * scale3(scale) * translate3(-fixedPoint);
}

glm::dmat3 buildTransformationMatrix2(const glm::dvec2& fixedPoint, const glm::dvec2& shift, double angle,
                                      const glm::dvec2& scale) {
    return translate2(shift) * translate2(fixedPoint) * rotate2(angle) * scale2(scale) *
           translate2(-fixedPoint);
}

glm::dmat4 composeTransformationMatrix3(const glm::dmat4& m, const glm::dvec3& fixedPoint,
                                        const glm::dvec3& shift, const glm::dvec3& angles,
                                        const glm::dvec3& scale) {
    return buildTransformationMatrix3(fixedPoint, shift, angles, scale) * m;
}

glm::dmat3 composeTransformationMatrix2(const glm::dmat3& m, const glm::dvec2& fixedPoint,
                                        const glm::dvec2& shift, double angle, const glm::dvec2& scale) {
    return buildTransformationMatrix2(fixedPoint, shift, angle, scale) * m;
}

std::optional<glm::dvec3> transformPoint3(const glm::dmat4& m, const glm::dvec3& p) {
    const glm::dvec4 h = m * glm::dvec4(p, 1.0);
    if (h.w == 0.0) return std::nullopt;
    const glm::dvec3 r = glm::dvec3(h) / h.w;
    if (!finite(r.x) || !finite(r.y) || !finite(r.z)) return std::nullopt;
    return r;
}

std::optional<glm::dvec2> transformPoint2(const glm::dmat3& m, const glm::dvec2& p) {
    const glm::dvec3 h = m * glm::dvec3(p, 1.0);
    if (h.z == 0.0) return std::nullopt;
    const glm::dvec2 r = glm::dvec2(h) / h.z;
    if (!finite(r.x) || !finite(r.y)) return std::nullopt;
    return r;
}

}  // namespace phigs
