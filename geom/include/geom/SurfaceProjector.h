#pragma once

#include "geom/BezierPatchTree.h"
#include "geom/Inversion.h"
#include "geom/Surface.h"

#include <cstddef>

namespace geom {

/// Point inversion against one surface, many times: patches and box tree built once; a query
/// searches each Bézier patch on its own (creases and seams lie on patch edges), nearest first,
/// and subdivides a patch wherever its net's bound could still hold a nearer point.
class SurfaceProjector {
public:
    explicit SurfaceProjector(const Surface& surface);

    /// Global closest point.
    SurfacePoint closestPoint(const glm::dvec3& p) const;
    /// Local closest point from a guess: Newton inside the guess's patch, edges held as
    /// constraints, going on into a neighbouring patch while that lowers the distance.
    SurfacePoint closestPointFrom(const glm::dvec3& p, const glm::dvec2& guess) const;

    const BezierPatchTree& tree() const { return tree_; }

private:
    class Search;

    /// Newton from uv on patch `index`, held inside [ua, ub] x [va, vb] (a part of the patch).
    SurfacePoint polishIn(std::size_t index, const glm::dvec3& p, glm::dvec2 uv, double ua, double ub,
                          double va, double vb) const;
    /// Newton from uv held inside patch `index` (a local minimum of the distance on that patch).
    SurfacePoint polishOnPatch(std::size_t index, const glm::dvec3& p, glm::dvec2 uv) const;
    /// polishOnPatch, then on into neighbouring patches while the distance falls.
    SurfacePoint polish(const glm::dvec3& p, glm::dvec2 uv) const;
    /// best's (u, v) moved just below a knot line of multiplicity degree + 1 where the point lies
    /// on the patch before the jump: evaluate() there gives the patch after it.
    SurfacePoint beforeJump(SurfacePoint best) const;
    /// Whether the distance from p has no slope at `at` within the domain (a local minimum's
    /// first-order condition, to rounding).
    bool stationary(const glm::dvec3& p, const SurfacePoint& at) const;
    /// The start of a patch's search: `start` (its nearest control point's abscissa) or the point
    /// of a 3 x 3 grid on the patch nearer to p.
    glm::dvec2 patchStart(std::size_t index, const glm::dvec3& p, glm::dvec2 start) const;

    BezierPatchTree tree_;
    bool rational_ = false;
};

}  // namespace geom
