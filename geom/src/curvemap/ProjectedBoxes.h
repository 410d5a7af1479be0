#pragma once
// The surface's patch boxes as seen along a placement's projection lines.

#include "geom/BezierPatchTree.h"
#include "geom/curvemap/Placement.h"

#include <glm/vec2.hpp>

#include <vector>

namespace geom::curvemap {

/// Per node of a Bézier patch tree, the box of its patches' control points in the placement
/// frame's plane coordinates (x, y): the projection lines through a chord of the plane curve meet
/// the surface only if the chord meets one of these boxes (convex hull property, positive weights).
class ProjectedBoxes {
public:
    ProjectedBoxes(const BezierPatchTree& tree, const PlacementFrame& frame);

    /// Whether the segment p-q, widened by `pad`, meets the box of some patch.
    bool mayMeet(const glm::dvec2& p, const glm::dvec2& q, double pad) const;

private:
    struct Box {
        glm::dvec2 lo{0.0}, hi{0.0};
    };
    Box build(int node, const BezierPatchTree& tree, const PlacementFrame& frame);
    bool meets(int node, const glm::dvec2& p, const glm::dvec2& q, double pad) const;

    std::vector<Box> boxes_;  ///< per tree node
    std::vector<int> first_, second_;
    int root_ = -1;
};

}  // namespace geom::curvemap
