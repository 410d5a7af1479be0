#pragma once

#include "geom/BezierPatchTree.h"
#include "geom/Inversion.h"
#include "geom/Surface.h"

namespace geom {

/// Point inversion against one surface, many times: patches and box tree built once; a query
/// visits patches nearest first and stops when no box can hold a nearer point.
class SurfaceProjector {
public:
    explicit SurfaceProjector(const Surface& surface);

    /// Global closest point.
    SurfacePoint closestPoint(const glm::dvec3& p) const;
    /// Newton from a guess, kept in the domain (edges held as constraints).
    SurfacePoint closestPointFrom(const glm::dvec3& p, const glm::dvec2& guess) const;

    const BezierPatchTree& tree() const { return tree_; }

private:
    /// Newton from uv on the whole domain (a local minimum of the distance).
    SurfacePoint polish(const glm::dvec3& p, glm::dvec2 uv) const;

    BezierPatchTree tree_;
};

}  // namespace geom
