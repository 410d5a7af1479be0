#pragma once

#include "phigs/traverse/DrawList.h"

#include <glm/vec2.hpp>

#include <vector>

namespace phigs::render {

/// Nominal marker size in pixels (PHIGS marker size scale factor 1).
inline constexpr float kNominalMarkerPixels = 7.0f;

/// The shape of a PHIGS marker type as line segments (pairs of points) in pixels around the marker
/// position (y up); a dot is a filled square given as two triangles in `triangles` instead.
struct MarkerShape {
    std::vector<glm::vec2> segments;
    std::vector<glm::vec2> triangles;
};

/// The shape of `type` at `scale` times the nominal size.
MarkerShape markerShape(MarkerType type, float scale);

}  // namespace phigs::render
