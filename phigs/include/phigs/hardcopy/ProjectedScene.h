#pragma once

// The describe step's middle form: a draw list's primitives lit, clipped to their views and mapped
// onto the page, each point with its NPC depth, before hidden parts are removed and the paint
// operations are made. A small closed family, so it shares a file.

#include "phigs/traverse/DrawList.h"

#include <glm/vec3.hpp>

#include <memory>
#include <variant>
#include <vector>

namespace phigs::hardcopy {

/// A point on the page (x right, y down, points) with its NPC depth as z (1 is the front).
using PagePoint = glm::dvec3;

/// A PATTERN interior on the page: its cells, and the affine map from page points (x, y) to cell
/// coordinates, column = dot(u, (x, y, 1)) and row = dot(v, (x, y, 1)).
struct PagePattern {
    DrawPattern cells;
    glm::dvec3 u{0.0}, v{0.0};
};

/// A planar region of one colour (even-odd over its contours): a clipped mesh facet or fill area.
struct ProjectedFacet {
    // The flags after the numbers: a page holds tens of thousands of facets, each 8 bytes smaller so.
    std::vector<std::vector<PagePoint>> contours;
    glm::vec3 colour{1.0f};
    float opacity = 1.0f;
    std::shared_ptr<const PagePattern> pattern;  ///< PATTERN interiors: the cells instead of `colour`
    int hatchIndex = 1;
    int clip = 0;          ///< the view whose clip rectangle applies
    bool hatch = false;    ///< hatch lines in `colour` instead of a fill
    bool occludes = true;  ///< hides what lies behind (not when transparent or hatched)
    /// A hidden-line surface: it hides, and is painted in the background colour only where
    /// other facets could show through it.
    bool coverOnly = false;
    bool seam = false;  ///< one of many pieces: its outline is stroked thinly so no seam shows
};

/// A run of a line (polyline, curve, edge, iso-line, text stroke) on the page.
struct ProjectedLine {
    std::vector<PagePoint> points;
    std::vector<double> distances;  ///< nominal pixels along the original line (the dash phase)
    glm::vec3 colour{1.0f};
    LineType type = LineType::Solid;
    float width = 1.0f;  ///< linewidth scale factor
    int clip = 0;
};

/// A marker at a page point, its colour final.
struct ProjectedMarker {
    PagePoint position{0.0};
    MarkerStyle style;
    int clip = 0;
};

using ProjectedPart = std::variant<ProjectedFacet, ProjectedLine, ProjectedMarker>;

/// Everything a draw list puts on one page, in traversal order.
struct ProjectedScene {
    std::vector<ProjectedPart> parts;
};

}  // namespace phigs::hardcopy
