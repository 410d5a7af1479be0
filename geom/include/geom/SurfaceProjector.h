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
    /// Newton from a guess, confined to [u0,u1] x [v0,v1] (the domain by default).
    SurfacePoint closestPointFrom(const glm::dvec3& p, const glm::dvec2& guess) const;

    const BezierPatchTree& tree() const { return tree_; }

private:
    SurfacePoint polish(std::size_t patch, const glm::dvec3& p, glm::dvec2 uv) const;

    BezierPatchTree tree_;
};

}  // namespace geom
