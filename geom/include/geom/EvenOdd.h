#pragma once

// The even-odd (crossing-number) rule: PHIGS fills a FILL AREA SET by it, and trim loops and
// mapped curves' outlines keep the part of the plane it calls inside.

#include <glm/vec2.hpp>

#include <cstddef>

namespace geom {

/// Whether a ray from p toward +x crosses the closed polygon's edges an odd number of times;
/// `xy(point)` gives a polygon point's (x, y). A repeated first point adds no crossing.
template <class Polygon, class XY>
bool oddCrossings(glm::dvec2 p, const Polygon& polygon, XY xy) {
    bool odd = false;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const glm::dvec2 a = xy(polygon[i]), b = xy(polygon[j]);
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) odd = !odd;
    }
    return odd;
}

/// Whether p is inside the contours together by the even-odd rule.
template <class Contours, class XY>
bool insideEvenOdd(glm::dvec2 p, const Contours& contours, XY xy) {
    bool inside = false;
    for (const auto& contour : contours) inside = inside != oddCrossings(p, contour, xy);
    return inside;
}

}  // namespace geom
