#pragma once

#include "phigs/hardcopy/ProjectedScene.h"

#include <glm/common.hpp>
#include <glm/vec2.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace phigs::hardcopy {

/// The occluding facets of a page, triangulated and binned on a grid, for hidden-line removal
/// in object space: a segment is tested against the triangles over it and keeps the parameter
/// intervals no triangle hides. As with the raster's depth bias, a line is hidden only where it
/// lies behind a triangle by more than the depth the triangle's slope spans over 1.5 pixels, so
/// lines on a surface (iso-lines, edges, boundaries) stay visible.
class OcclusionIndex {
public:
    /// `pixel`: points per raster pixel (PageMapping::nominalPixel).
    OcclusionIndex(const std::vector<ProjectedFacet>& facets, double pixel);

    /// The parameter intervals [t0, t1] of the segment a + t (b - a), t in [0, 1], that are visible.
    std::vector<glm::dvec2> visibleParts(const PagePoint& a, const PagePoint& b) const;
    /// Whether a point is visible.
    bool visible(const PagePoint& p) const;
    /// Whether a facet is hidden whole: its centre and every edge of its outline, taken `margin`
    /// points inside (at most a tenth of the way to the centre), are. The margin lets a back face
    /// that meets a silhouette count as hidden although the edge it shares is seen; a sliver of a
    /// facet narrower than the margin, or a hole in what hides it that touches none of the tested
    /// edges, goes unseen.
    bool hidden(const ProjectedFacet& facet, double margin) const;
    /// A line's visible runs (each with its own dash phase).
    std::vector<ProjectedLine> visibleRuns(const ProjectedLine& line) const;
    std::size_t triangleCount() const { return triangles_.size(); }

private:
    struct Triangle {
        glm::dvec2 p[3];
        glm::dvec3 plane{0.0};  ///< depth = plane.x * x + plane.y * y + plane.z
        /// The box on the page, worked out when needed rather than held with every triangle.
        glm::dvec2 lo() const { return glm::min(p[0], glm::min(p[1], p[2])); }
        glm::dvec2 hi() const { return glm::max(p[0], glm::max(p[1], p[2])); }
    };
    void add(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);
    void bin();
    template <class F>
    void forCells(glm::dvec2 lo, glm::dvec2 hi, F&& f) const;
    /// How far behind a triangle a line must lie to be hidden: the depth its slope spans over
    /// the raster's bias (worked out when needed rather than held with every triangle).
    double tolerance(const Triangle& t) const;
    /// The interval of t in [0, 1] where the segment is inside the triangle and behind it.
    bool hides(const Triangle& t, const PagePoint& a, const PagePoint& b, glm::dvec2& interval) const;
    /// The intervals of the segment that triangles hide, in order of their start; the triangles
    /// that hide some of it are added to `hiders` when given.
    void hiddenIntervals(const PagePoint& a, const PagePoint& b, std::vector<glm::dvec2>& hidden,
                         std::vector<std::uint32_t>* hiders = nullptr) const;
    /// Appends the intervals of the segment hidden by the triangles over the cells the box
    /// [lo, hi] meets (each triangle tested once), adding those triangles to `hiders` when given.
    void collectHidden(const PagePoint& a, const PagePoint& b, glm::dvec2 lo, glm::dvec2 hi,
                       std::vector<glm::dvec2>& hidden, std::vector<std::uint32_t>* hiders) const;
    /// Whether no part of the segment is visible (hidden()'s edges: tries its hints first).
    bool hiddenWhole(const PagePoint& a, const PagePoint& b) const;
    /// Adds the triangles that hide a point.
    void hidersOf(const PagePoint& p, std::vector<std::uint32_t>& hiders) const;

    std::vector<Triangle> triangles_;
    double pixel_ = 1.0;  ///< points per raster pixel
    glm::dvec2 lo_{0.0}, cell_{1.0};
    int columns_ = 0, rows_ = 0;
    /// The triangles over each cell: cellItems_[cellStart_[c], cellStart_[c + 1]).
    std::span<const std::uint32_t> items(std::size_t cell) const {
        return {cellItems_.data() + cellStart_[cell], cellItems_.data() + cellStart_[cell + 1]};
    }

    std::vector<std::uint32_t> cellStart_, cellItems_;
    mutable std::vector<std::uint32_t> stamp_;
    mutable std::uint32_t query_ = 0;
    mutable std::vector<glm::dvec2> scratch_;  ///< hiddenWhole's intervals, kept between calls
    mutable std::vector<glm::dvec2> gaps_;     ///< and the parts of its segment the hints leave open
    /// hidden()'s triangles known to hide the facet's centre or edges, tried first on each edge,
    /// and whether each hid some of this facet.
    mutable std::vector<std::uint32_t> hints_, found_;
    mutable std::vector<std::uint8_t> hintUsed_;
    /// The hints that hid some of the last facet tested: a mesh's facets come in order, and
    /// neighbours mostly lie behind the same few triangles.
    mutable std::vector<std::uint32_t> carried_;
};

}  // namespace phigs::hardcopy
