#pragma once
// Exact conversion between geom's B-splines (flat knot vectors with repeats; a closed curve is an
// unclamped one whose end points wrap) and OpenCASCADE's (distinct knots with multiplicities; a
// periodic curve stores each pole once).

#include "geom/Curve.h"
#include "geom/Surface.h"

#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>

#include <glm/vec2.hpp>

#include <vector>

namespace geom::exchange {

/// Whether a direction goes to OpenCASCADE as periodic where it is periodic by construction.
enum class Periodicity { Detect, Never };

/// True when the curve is periodic by construction: its knots are OpenCASCADE's periodic knot
/// sequence of the knots in its domain (the gaps beyond each end repeat those inside the other)
/// and its last points and weights repeat its first, so it is C^(degree - multiplicity) across
/// the seam. Knots compare within 1e-12 of the domain width, points within 1e-12 of the net's size.
bool periodicByConstruction(const Curve& curve);
/// The same test for the u (alongV false) or v direction of a surface (every row or column).
bool periodicByConstruction(const Surface& surface, bool alongV);

/// The same curve as an OpenCASCADE B-spline: same poles, weights and knots; periodic (each pole
/// once) where `periodicity` is Detect and the curve is periodic by construction.
opencascade::handle<Geom_BSplineCurve> toOcct(const Curve& curve,
                                              Periodicity periodicity = Periodicity::Detect);
/// The same surface, periodic in each direction that is periodic by construction (Detect).
opencascade::handle<Geom_BSplineSurface> toOcct(const Surface& surface,
                                                Periodicity periodicity = Periodicity::Detect);
/// A degree-1 B-spline through `points` with knots 0, 1, ..., n - 1 (a polyline; a pcurve).
opencascade::handle<Geom2d_BSplineCurve> polylineToOcct(const std::vector<glm::dvec2>& points);

/// The same curve in geom's form: a periodic one unrolled (poles wrapped, periodic knots), so
/// it evaluates alike on its domain. Throws GeometryError where geom's rules are broken.
Curve fromOcct(const Geom_BSplineCurve& curve);
Surface fromOcct(const Geom_BSplineSurface& surface);

}  // namespace geom::exchange
