#pragma once

#include "geom/BezierPatchTree.h"
#include "geom/Intersect.h"
#include "geom/Surface.h"

#include <glm/vec3.hpp>

#include <optional>
#include <vector>

namespace geom {

/// Line/surface intersection against one surface, many times: the Bézier patches and their
/// box tree are built once. Each query projects candidate patches onto the plane across the
/// line, subdivides while the projected box holds the origin (Krawczyk's test parts the cells
/// beside a root from it), and polishes each root by Newton. A patch edge lying on the line (a
/// pole, or a straight edge along it) is one hit at its middle, its factor divided out of the search.
class SurfaceIntersector {
public:
    explicit SurfaceIntersector(const Surface& surface);

    /// All hits on the infinite line origin + t * direction, sorted by t (see intersectLine).
    std::vector<LineSurfaceHit> intersect(const glm::dvec3& origin, const glm::dvec3& direction) const;

    /// The surface's own patch tree (in its own coordinates).
    const BezierPatchTree& tree() const { return tree_; }

private:
    /// A line in the search tree's coordinates: a point of it, its direction, two unit vectors
    /// across it, and how far off it a point may lie by the rounding that placed it.
    struct SearchLine {
        glm::dvec3 origin, direction, n1, n2;
        double placing = 0.0;
    };
    void intersectPatch(std::size_t patch, const SearchLine& line, std::vector<LineSurfaceHit>& hits) const;
    /// The tree the search runs on: tree_, or for a surface with coordinates past 2^400 or all
    /// below 2^-400 (where squared distances overflow or underflow) a copy scaled by a power of
    /// two, unitScale_, to unit size.
    const BezierPatchTree& searchTree() const { return unitTree_ ? *unitTree_ : tree_; }

    BezierPatchTree tree_;
    std::optional<BezierPatchTree> unitTree_;
    double unitScale_ = 1.0;
};

}  // namespace geom
