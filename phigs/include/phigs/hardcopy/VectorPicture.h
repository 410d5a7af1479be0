#pragma once

// The describe step's result: paint operations on one page in points (y down), in painting order,
// with nothing left to decide but how a file format writes them. A small closed family.

#include "phigs/hardcopy/PageMapping.h"
#include "phigs/hardcopy/ProjectedScene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <memory>
#include <variant>
#include <vector>

namespace phigs::hardcopy {

/// A filled region (even-odd over its contours); `seamWidth` > 0 also strokes its outline in the
/// same colour, so neighbouring facets meet without a hairline gap.
struct VectorFill {
    std::vector<std::vector<glm::dvec2>> contours;
    glm::vec3 colour{1.0f};
    float opacity = 1.0f;
    std::shared_ptr<const PagePattern> pattern;  ///< tiles the region with its cells instead of `colour`
    double seamWidth = 0.0;
    int clip = -1;  ///< index into VectorPicture::clips, -1: none
};

/// Parallel lines across a region (even-odd over its contours), at `angles` degrees from the page's
/// x axis counter-clockwise, `spacing` apart, anchored to the page so neighbouring areas line up.
struct VectorHatch {
    std::vector<std::vector<glm::dvec2>> contours;
    glm::vec3 colour{1.0f};
    float opacity = 1.0f;
    std::vector<double> angles;
    double spacing = 4.0, width = 0.5;
    int clip = -1;
};

/// A stroked polyline; `dashes` (on, off, ...) empty for solid, `dashOffset` its phase at the start.
struct VectorStroke {
    std::vector<glm::dvec2> points;
    glm::vec3 colour{1.0f};
    double width = 0.5;
    std::vector<double> dashes;
    double dashOffset = 0.0;
    int clip = -1;
};

/// A stroked circle (the circle marker).
struct VectorCircle {
    glm::dvec2 centre{0.0};
    double radius = 1.0;
    glm::vec3 colour{1.0f};
    double width = 0.5;
    int clip = -1;
};

using VectorOp = std::variant<VectorFill, VectorHatch, VectorStroke, VectorCircle>;

/// One page of a vector hardcopy.
struct VectorPicture {
    glm::dvec2 pageSize{0.0};
    bool paintBackground = true;
    PageRect backgroundRect;  ///< the display surface
    glm::vec3 background{0.0f};
    std::vector<PageRect> clips;  ///< one per view of the draw list
    std::vector<VectorOp> ops;
};

}  // namespace phigs::hardcopy
