#pragma once

// Private tessellation of NURBS curves and surfaces for traversal: grids per knot span for the
// parametric criteria, geom's adaptive tessellation for the chordal-deviation criteria.

#include "phigs/store/Element.h"
#include "phigs/traverse/DrawList.h"
#include "phigs/traverse/TessellationCache.h"

#include <vector>

namespace phigs::detail {

/// Segments per knot span for an approximation criteria attribute: 1 (workstation dependent)
/// 8; 2 (constant parametric subdivision between knots) the given counts; 3-8 (chordal
/// size / deviation) from the control polygon's second differences against `value` as tolerance.
int segmentsPerSpan(const std::vector<glm::dvec3>& controlPolygon, int criteria, double value);

/// Distinct knot values inside the domain [start, end], both ends included.
std::vector<double> spanBreaks(const std::vector<double>& knots, double start, double end);

std::vector<glm::dvec3> tessellateCurve(const geom::Curve& curve, double start, double end, int criteria,
                                        double value);

/// A curve element's runs over [start, end] (equal: the whole curve): the curve alone, or its
/// pieces between breaks (geom::splitAtBreaks) each over its part of the range, each tessellated.
std::vector<TessellationCache::CurveRun> curveRuns(geom::Curve curve, double start, double end, int criteria,
                                                   double value);

/// A grid over the surface (positions, unit normals, triangles counter-clockwise seen along the
/// normal, uv where read: knot lines inside the domain or level curves, styles 4 and 5), with triangles
/// outside the trimming loops (even-odd in (u, v)) removed and iso-parametric curves (style 3) added.
/// Criteria 3-8 with a positive tolerance (and no iso-curves asked for) use geom::tessellateAdaptive instead
/// of the grid. With `grids`, an untrimmed grid's triangles are shared with every mesh on a grid of its size.
MeshData tessellateSurface(const NurbsSurfaceElement& element, const ApproximationAttribute& criteria,
                           const SurfaceCharacteristicsAttribute& characteristics,
                           TessellationCache* grids = nullptr);

}  // namespace phigs::detail
