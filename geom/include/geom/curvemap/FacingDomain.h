#pragma once

#include "geom/Surface.h"
#include "geom/curvemap/SurfaceDomain.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>

namespace geom::curvemap {

/// The sheet of a surface that a curve placed at `reference` is projected onto along `direction`:
/// the largest parameter rectangle (grown side by side from the reference, never across a seam)
/// on which the unit normal n keeps dot(n, direction) the sign it has at the reference and at
/// least `minimumCosine` in size. Its edges are where a part hanging over a leading or trailing
/// edge, or over a fold of a closed surface, is clipped. Both directions of the result are open.
/// Empty when the reference itself is not facing that way.
std::optional<SurfaceDomain> facingDomain(const Surface& surface, const SurfaceDomain& domain,
                                          const glm::dvec2& reference, const glm::dvec3& direction,
                                          double minimumCosine = 0.15);

/// The piece of `surface` over `part` (a rectangle inside its domain), with the same parameters.
Surface subSurface(const Surface& surface, const SurfaceDomain& domain, const SurfaceDomain& part);

}  // namespace geom::curvemap
