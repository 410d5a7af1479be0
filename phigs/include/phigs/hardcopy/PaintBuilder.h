#pragma once

#include "phigs/hardcopy/PageMapping.h"
#include "phigs/hardcopy/ProjectedScene.h"
#include "phigs/hardcopy/VectorPicture.h"

#include <glm/geometric.hpp>

namespace phigs::hardcopy {

/// Turns projected parts into a VectorPicture's paint operations, sizing in nominal pixels what
/// the raster sizes in pixels: line widths (at least one), dash arrays from render::linePattern
/// scaled by the width, hatch spacing (8) and the marker shapes of render::markerShape. What no
/// file can hold goes: a part with a coordinate that is not finite, a marker whose scale is not a
/// positive number; line widths stop at kMaxLineScale and markers at twice the page's diagonal.
class PaintBuilder {
public:
    /// The widest line, in nominal pixels (the raster stops at its device's widest).
    static constexpr double kMaxLineScale = 1024.0;

    PaintBuilder(const PageMapping& mapping, VectorPicture& picture)
        : pixel_(mapping.nominalPixel), largest_(2.0 * glm::length(mapping.pageSize)), picture_(picture) {}

    void operator()(const ProjectedFacet& facet);
    void operator()(const ProjectedLine& line);
    void operator()(const ProjectedMarker& marker);
    /// Makes room for this many operations in the picture.
    void reserve(std::size_t operations) { picture_.ops.reserve(picture_.ops.size() + operations); }

private:
    double pixel_;
    double largest_;  ///< points: no marker is drawn larger
    VectorPicture& picture_;
};

}  // namespace phigs::hardcopy
