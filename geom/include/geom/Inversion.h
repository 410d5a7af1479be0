#pragma once

#include "geom/Curve.h"
#include "geom/Surface.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace geom {

/// The point of a curve nearest to a query point: parameter, point and distance.
struct CurvePoint {
    double u = 0.0;
    glm::dvec3 point{0.0};
    double distance = 0.0;
};

/// Global closest point on a curve: Bézier pieces ordered by box distance, Newton in each piece
/// that could hold a nearer point. For many queries build a CurveProjector once. Every
/// closest-point query throws GeometryError for a point that is not finite or lies beyond 1e150
/// (where squared distances overflow), and every projector (CurveProjector, SurfaceProjector)
/// for an object whose control points span less than 1e-140 but not 0 (where they underflow).
CurvePoint closestPoint(const Curve& curve, const glm::dvec3& p);
/// Local closest point: Newton on (C(u) - p) . C'(u) = 0 from the guess u, kept in the domain.
CurvePoint closestPoint(const Curve& curve, const glm::dvec3& p, double guess);

/// The point of a surface nearest to a query point.
struct SurfacePoint {
    glm::dvec2 uv{0.0};
    glm::dvec3 point{0.0};
    double distance = 0.0;
};

/// Global closest point on a surface (see SurfaceProjector, which this builds per call).
SurfacePoint closestPoint(const Surface& surface, const glm::dvec3& p);
/// Local closest point by Newton from the guess (u, v), kept in the domain (edges included).
SurfacePoint closestPoint(const Surface& surface, const glm::dvec3& p, const glm::dvec2& guess);

}  // namespace geom
