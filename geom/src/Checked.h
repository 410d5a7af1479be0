#pragma once

#include "NumberText.h"
#include "UnitScale.h"
#include "geom/Curve.h"
#include "geom/GeometryError.h"
#include "geom/Surface.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

// Private to geom: the checks a per-point entry (evaluate, derivatives, normal, curvature) makes
// instead of a full validate(), which would cost O(control points) per point: the sizes agree
// and the domain is finite and not empty (constant time), the knots of the span it reads are in
// order (O(degree)), the parameter is finite and in the domain, and the result is finite (which
// catches a non-finite point or a non-positive weight among those it read).
namespace geom::detail {

/// The shape checks' failure path: validate(), which names the broken rule, then a plain throw.
[[noreturn]] void explainShape(const Curve& curve, const char* where);
[[noreturn]] void explainShape(const Surface& surface, const char* where);

/// One direction's sizes agree, its domain is finite and not empty, and its knot span is finite.
inline bool directionShapeOk(const std::vector<double>& knots, int degree, std::size_t count) {
    const std::size_t p = static_cast<std::size_t>(degree);
    return degree >= 1 && count >= p + 1 && knots.size() == count + p + 1 && std::isfinite(knots[p]) &&
           std::isfinite(knots[count]) && knots[p] < knots[count] &&
           std::isfinite(knots.back() - knots.front());
}

/// Whether `size` equals countU * countV, the product taken without wrapping: two user counts whose
/// wrapped product matched would let a caller allocate for the huge counts.
inline bool gridSizeIs(std::size_t size, std::size_t countU, std::size_t countV) {
    std::size_t total = 0;
    return !__builtin_mul_overflow(countU, countV, &total) && total == size;
}

inline void checkShape(const Curve& curve, const char* where) {
    if (!directionShapeOk(curve.knots, curve.degree, curve.points.size()) ||
        (!curve.weights.empty() && curve.weights.size() != curve.points.size()))
        explainShape(curve, where);
}

inline void checkShape(const Surface& surface, const char* where) {
    std::size_t total = 0;  // countU * countV, refused when it overflows (no division per point)
    if (__builtin_mul_overflow(surface.countU, surface.countV, &total) || total != surface.points.size() ||
        total == 0 || !directionShapeOk(surface.knotsU, surface.degreeU, surface.countU) ||
        !directionShapeOk(surface.knotsV, surface.degreeV, surface.countV) ||
        (!surface.weights.empty() && surface.weights.size() != surface.points.size()))
        explainShape(surface, where);
}

/// The throws behind the inline checks below, out of line: the checks run once per point.
[[noreturn]] void parameterOutside(double value, double start, double end, const char* where,
                                   const char* name);
[[noreturn]] void spanNotOrdered(std::size_t span, const char* where);
[[noreturn]] void resultNotFinite(const char* where);

/// The parameter `name`, finite and inside [start, end] up to rounding (1e-9 of the width, and
/// clamped there); else GeometryError naming where and name.
inline double checkedParameter(double value, double start, double end, const char* where, const char* name) {
    const double slack = 1e-9 * (end - start);
    // NaN fails both comparisons, infinities the range.
    if (!(value >= start - slack && value <= end + slack)) parameterOutside(value, start, end, where, name);
    return value < start ? start : (value > end ? end : value);
}

/// knots[span - degree + 1 .. span + degree] non-decreasing (no NaN), knots[span] < knots[span + 1],
/// span in [degree, n - 1]: the window the basis functions of one span read.
inline void checkSpan(std::span<const double> knots, std::size_t span, int degree, const char* where) {
    const std::size_t p = static_cast<std::size_t>(degree);
    // NaN fails every comparison; an infinite knot in the window makes the result non-finite,
    // which checkResult catches.
    bool ordered = span >= p && span + p + 1 < knots.size() && knots[span] < knots[span + 1];
    for (std::size_t i = span + 1 - p; ordered && i < span + p; ++i) ordered = knots[i] <= knots[i + 1];
    if (!ordered) spanNotOrdered(span, where);
}

/// A weight geom computes with: finite and at least the smallest normal double (a subnormal one
/// beside ordinary weights makes their ratio overflow). validate() and the per-point checks share it.
inline bool usableWeight(double w) {
    return std::isfinite(w) && w >= std::numeric_limits<double>::min();
}

/// All three coordinates finite.
inline bool finite(const glm::dvec3& value) {
    return std::isfinite(value.x) && std::isfinite(value.y) && std::isfinite(value.z);
}

/// A closest-point query must be finite, and no farther out than 1e150: beyond it squared
/// distances overflow, and the answer would be wrong without a sign.
inline void checkQueryPoint(const glm::dvec3& p, const char* where) {
    if (!finite(p)) throw GeometryError(std::string(where) + ": the query point has a non-finite coordinate");
    if (detail::largestCoordinate(p) > 1e150)
        throw GeometryError(std::string(where) +
                            ": the query point lies beyond 1e150, where squared distances overflow");
}

/// A closest-point object's extent (the longest side of its control points' box) must be 0 or
/// at least 1e-140: below it squared distances underflow to 0 and every point would seem nearest.
inline void checkProjectedExtent(const glm::dvec3& boxSides, const char* where) {
    const double extent = std::max({boxSides.x, boxSides.y, boxSides.z});
    if (extent > 0.0 && extent < 1e-140)
        throw GeometryError(std::string(where) + ": its control points span " + numberText(extent) +
                            ", below 1e-140, where squared distances underflow (scale it up)");
}

/// A closest point's distance must be finite: it overflows only where the object's own control
/// points lie near 1e300, beyond what squared distances can hold.
inline void checkDistance(double distance, const char* where) {
    if (!std::isfinite(distance))
        throw GeometryError(std::string(where) +
                            ": the distance overflows: control points lie too far out (near 1e300) for "
                            "squared distances");
}

/// Throws when a computed point or vector is not finite: the data it came from is not (a point
/// that is not finite, or a weight that is not positive).
inline void checkResult(const glm::dvec3& value, const char* where) {
    if (!finite(value)) resultNotFinite(where);
}

/// The sum of the absolute values (of a span's basis derivatives).
inline double absoluteSum(std::span<const double> values) {
    double sum = 0.0;
    for (double x : values) sum += std::abs(x);
    return sum;
}

/// Whether first derivatives su, sv at `point`, summed from the control points with basis
/// derivatives whose absolute values sum to scaleU and scaleV, are so small against those points'
/// coordinates that rounding may rule them (next to a collapsed edge or pole, more so far from the
/// origin): then they are taken again about a control point of the span (Evaluate.cpp), whose
/// digits they keep. The terms are about as large as the point's own size plus the net's reach
/// from it; a derivative ten thousand times smaller than such terms times the basis derivatives
/// has lost four of its digits or more. Compared squared, with (|a| + |b|)^2 <= 2 (|a|^2 + |b|^2).
inline bool derivativesMayBeRounding(const Surface& surface, const glm::dvec3& point, const glm::dvec3& su,
                                     const glm::dvec3& sv, double scaleU, double scaleV) {
    const glm::dvec3 span = surface.points.front() - point;
    const double reach2 = 2.0 * (point.x * point.x + point.y * point.y + point.z * point.z + span.x * span.x +
                                 span.y * span.y + span.z * span.z);
    const double u2 = su.x * su.x + su.y * su.y + su.z * su.z, v2 = sv.x * sv.x + sv.y * sv.y + sv.z * sv.z;
    return u2 < 1e-8 * reach2 * scaleU * scaleU || v2 < 1e-8 * reach2 * scaleV * scaleV;
}

}  // namespace geom::detail
