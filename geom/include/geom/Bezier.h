#pragma once

#include "geom/Curve.h"
#include "geom/Surface.h"

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

namespace geom {

/// de Casteljau evaluation of a Bézier polygon at t in [0, 1] (any vector type: dvec2, dvec3,
/// dvec4 for homogeneous points, double). Stable for any degree; Molt (1994) uses degree 99.
template <class V>
V deCasteljau(std::span<const V> points, double t) {
    std::vector<V> work(points.begin(), points.end());
    const std::size_t n = work.size();
    for (std::size_t r = 1; r < n; ++r)
        for (std::size_t i = 0; i + r < n; ++i) work[i] = (1.0 - t) * work[i] + t * work[i + 1];
    return work[0];
}

/// Splits a Bézier polygon at t: left covers [0, t], right covers [t, 1], both re-parameterised
/// to [0, 1] (Lane-Riesenfeld when t = 1/2). left and right may not alias points.
template <class V>
void subdivideBezier(std::span<const V> points, double t, std::span<V> left, std::span<V> right) {
    const std::size_t n = points.size();
    std::vector<V> work(points.begin(), points.end());
    left[0] = work[0];
    right[n - 1] = work[n - 1];
    for (std::size_t r = 1; r < n; ++r) {
        for (std::size_t i = 0; i + r < n; ++i) work[i] = (1.0 - t) * work[i] + t * work[i + 1];
        left[r] = work[0];
        right[n - 1 - r] = work[n - 1 - r];
    }
}

/// Splits a tensor-product Bézier net (rows of countV, u the slow index) at u = t, in place
/// into two nets of the same size; withV splits in v instead.
template <class V>
void subdivideBezierNet(std::span<const V> net, std::size_t countU, std::size_t countV, double t, bool alongV,
                        std::vector<V>& first, std::vector<V>& second) {
    first.resize(net.size());
    second.resize(net.size());
    const std::size_t lines = alongV ? countU : countV;
    const std::size_t length = alongV ? countV : countU;
    std::vector<V> line(length), a(length), b(length);
    for (std::size_t l = 0; l < lines; ++l) {
        for (std::size_t k = 0; k < length; ++k) line[k] = alongV ? net[l * countV + k] : net[k * countV + l];
        subdivideBezier<V>(line, t, a, b);
        for (std::size_t k = 0; k < length; ++k) {
            const std::size_t at = alongV ? l * countV + k : k * countV + l;
            first[at] = a[k];
            second[at] = b[k];
        }
    }
}

/// Bernstein polynomials B_{i,degree}(t), i = 0..degree, and optionally their first and second
/// derivatives (pass empty spans to skip them); each span holds degree+1 values (GeometryError for
/// a negative degree or a shorter span).
void bernsteinBasis(int degree, double t, std::span<double> values, std::span<double> first = {},
                    std::span<double> second = {});

/// True when the curve is one Bézier segment: degree+1 points and knots a^(p+1) b^(p+1).
bool isBezier(const Curve& curve);
/// True when the surface is one Bézier patch in both directions.
bool isBezier(const Surface& surface);

/// Point of a Bézier curve (rational ones in homogeneous form) by de Casteljau at the curve's
/// own parameter u in [start, end]. Throws GeometryError when the curve is not one segment.
glm::dvec3 evaluateBezier(const Curve& bezier, double u);
/// Point of a Bézier patch by de Casteljau, first along v then along u.
glm::dvec3 evaluateBezier(const Surface& bezier, double u, double v);

/// Splits a Bézier curve at u (start < u < end) into the pieces over [start, u] and [u, end].
std::pair<Curve, Curve> subdivide(const Curve& bezier, double u);
/// Splits a Bézier patch at u (or at v when alongV) into its two halves.
std::pair<Surface, Surface> subdivide(const Surface& bezier, double t, bool alongV);

}  // namespace geom
