#pragma once

#include "phigs/store/Element.h"

#include "geom/Curve.h"

#include <optional>
#include <string>

namespace phigs {

/// The generalized drawing primitives this implementation registers. ISO 9592 leaves GDP
/// identifiers to the implementation; these are negative, as implementation-defined values are.
/// Both are drawn as exact rational curves with the polyline attributes, like a NURBS curve.
namespace gdp {
/// CIRCLE: the centre, a point on the circle and, for GDP 3, a third point that with the first two
/// fixes the circle's plane (the 2D form lies in z = 0).
inline constexpr int Circle = -1;
/// CIRCULAR ARC: three points on the arc, start, any point between, end.
inline constexpr int ThreePointArc = -2;
}  // namespace gdp

/// Whether traversal draws GDPs with this identifier (the others are stored and ignored).
bool isRegisteredGdp(int identifier);

/// The rules of a registered GDP's points (count, distinct, not collinear): empty when valid,
/// else the reason. Unregistered identifiers have no rules.
std::string checkGdp(const GdpElement& element);

/// The exact curve a registered GDP draws, in modelling coordinates; nullopt for an unregistered
/// identifier or points that break checkGdp.
std::optional<geom::Curve> gdpCurve(const GdpElement& element);

}  // namespace phigs
