#pragma once

// Private: level curves of NURBS surfaces (parametric surface characteristics 4 and 5), the
// surface cut by parallel planes, drawn like iso-parametric curves.

#include "phigs/store/Element.h"
#include "phigs/traverse/DrawList.h"

#include <vector>

namespace phigs::detail {

/// The planes of level curves (styles 4 and 5; none otherwise) in modelling coordinates, as
/// (n, w) with |n| = 1: the plane is dot(n, x) + w = 0. Plane k passes through origin + t_k *
/// direction perpendicular to direction; world planes (5) are carried back by `modelToWorld`.
std::vector<glm::dvec4> levelPlanes(const SurfaceCharacteristicsAttribute& c, const glm::dmat4& modelToWorld);

/// Adds to `mesh` the polylines where its triangles cut each of `planes`, as iso-lines through
/// positions added for them (normals, colours and uv interpolated). With `surface` and uv, each
/// point is then moved onto the exact surface and plane by Newton steps in (u, v).
void addLevelCurves(MeshData& mesh, const std::vector<glm::dvec4>& planes, const geom::Surface* surface);

}  // namespace phigs::detail
