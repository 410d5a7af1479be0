#pragma once

// Interior style PATTERN (ISO 9592): the pattern box given by the pattern reference point,
// reference vectors and size in modelling coordinates, projected onto the primitive's plane,
// tiles the interior with the cells of a pattern representation. Shared by the renderer and
// the hardcopy, which both colour a point of an interior by the cell these maps give.

#include "phigs/traverse/DrawList.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <optional>

namespace phigs::render {

/// World coordinates to pattern cell coordinates: column dot(u.xyz, x) + u.w, row likewise with v
/// (cell (0, 0) starts at the reference point; the pattern repeats every columns x rows cells).
struct PatternMap {
    glm::dvec4 u{0.0}, v{0.0};
    glm::dvec2 at(const glm::dvec3& world) const;
};

/// The pattern an interior's index names: its entry, else entry 1 (an undefined pattern index
/// reads as 1, ISO 9592), else null (no pattern defined: the interior draws solid).
const DrawPattern* findPattern(const DrawList& list, int index);

/// The map of `placement` under the modelling transform `model`, projected orthogonally onto the
/// plane through `planePoint` with normal `planeNormal` (world). Null when the projected pattern
/// box has no area (its plane stands perpendicular to the primitive's).
std::optional<PatternMap> patternMap(const PatternPlacement& placement, const glm::dmat4& model,
                                     const DrawPattern& pattern, const glm::dvec3& planePoint,
                                     const glm::dvec3& planeNormal);

/// The map for a fill area or mesh item with a PATTERN side (the front style, or the back style
/// with face distinguishing on; both share the placement): projected onto the plane of a planar
/// primitive, onto the pattern's own plane for a curved mesh. Null for other items and
/// degenerate boxes or primitives.
std::optional<PatternMap> itemPatternMap(const DrawItem& item, const DrawPattern& pattern);

/// The colour of the cell holding pattern coordinates `cell`.
glm::vec3 patternColour(const DrawPattern& pattern, const glm::dvec2& cell);

}  // namespace phigs::render
