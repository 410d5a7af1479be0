#pragma once
// Closed polygons in a surface's (u, v), as the writer and the reader of trimmed faces see loops.

#include <glm/vec2.hpp>

#include <vector>

namespace geom::exchange {

/// Twice the signed area of a closed polygon in (u, v) (its last point repeats its first):
/// positive counter-clockwise.
inline double twiceSignedArea(const std::vector<glm::dvec2>& uv) {
    double twice = 0.0;
    for (std::size_t i = 0; i + 1 < uv.size(); ++i) twice += uv[i].x * uv[i + 1].y - uv[i + 1].x * uv[i].y;
    return twice;
}

}  // namespace geom::exchange
