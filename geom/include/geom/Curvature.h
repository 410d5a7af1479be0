#pragma once

#include "geom/Surface.h"

namespace geom {

/// Gaussian and mean curvature of a surface at a point, with the unit normal they refer to
/// (the mean curvature is positive where the surface bends towards that normal).
struct SurfaceCurvature {
    double gaussian = 0.0;
    double mean = 0.0;
    double principalMin = 0.0;
    double principalMax = 0.0;
};

/// Curvatures from the first and second fundamental forms (derivatives, which keep their digits
/// next to a collapsed edge or pole too). Throws GeometryError at a point where the first fundamental form
/// is singular (on a collapsed edge or pole), where they are undefined.
SurfaceCurvature curvature(const Surface& surface, double u, double v);

}  // namespace geom
