#pragma once

#include "geom/Curve.h"
#include "geom/Surface.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace geom {

// Counts above kMaxSamplePoints (GlobalInterpolation.h) are refused, the paraboloid's above 1024
// a side.

/// The thesis's "I-beam" test curve (Marcaly 1991, chapter 7): y = 5 + (x^3 - x) sin(pi x / 180) / 7500
/// sampled at controlPoints evenly spaced x from -180 to 180 and interpolated by a clamped cubic
/// with uniform parameters (controlPoints control points, 401 in the thesis), in the z = 0 plane.
Curve iBeamCurve(std::size_t controlPoints = 401);

/// Points of a NACA 4-digit symmetric section (closed trailing edge) of the given chord and
/// thickness ratio: count points from the trailing edge over the upper surface to the leading
/// edge and back along the lower surface (cosine spacing), in the z = 0 plane, x along the chord.
std::vector<glm::dvec3> nacaSymmetricPoints(std::size_t count, double chord, double thickness);

/// A NACA 0012 airfoil of chord 192 (16 ft in inches) as a clamped cubic through
/// nacaSymmetricPoints with chord-length parameters: 100 control points as in the thesis.
Curve nacaAirfoilCurve(double chord = 192.0, std::size_t controlPoints = 100, double thickness = 0.12);

/// A paraboloid z = (x^2 + y^2) / 50 over [-50, 50]^2 as a bicubic surface interpolating a
/// count x count grid (75 x 75 control points in the thesis). The thesis does not give its
/// equation; this one has no inflection and no large curvature variation, as it describes.
Surface paraboloidSurface(std::size_t count = 75);

/// A swept, tapered, twisted wing of NACA 0012 sections: `sections` spanwise cross sections
/// (u) times pointsPerSection points around each airfoil (v), interpolated by a bicubic surface
/// with sections x pointsPerSection control points (25 x 100 in the thesis). Root chord 192,
/// semi-span 480, 30 degree leading-edge sweep, 3 degree dihedral, 3 degree washout at the tip.
Surface wingSurface(std::size_t sections = 25, std::size_t pointsPerSection = 100);

}  // namespace geom
