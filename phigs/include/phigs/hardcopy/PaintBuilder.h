#pragma once

#include "phigs/hardcopy/PageMapping.h"
#include "phigs/hardcopy/ProjectedScene.h"
#include "phigs/hardcopy/VectorPicture.h"

namespace phigs::hardcopy {

/// Turns projected parts into a VectorPicture's paint operations, sizing in nominal pixels what
/// the raster sizes in pixels: line widths (at least one), dash arrays from render::linePattern
/// scaled by the width, hatch spacing (8) and the marker shapes of render::markerShape.
class PaintBuilder {
public:
    PaintBuilder(const PageMapping& mapping, VectorPicture& picture)
        : pixel_(mapping.nominalPixel), picture_(picture) {}

    void operator()(const ProjectedFacet& facet);
    void operator()(const ProjectedLine& line);
    void operator()(const ProjectedMarker& marker);
    /// Makes room for this many operations in the picture.
    void reserve(std::size_t operations) { picture_.ops.reserve(picture_.ops.size() + operations); }

private:
    double pixel_;
    VectorPicture& picture_;
};

}  // namespace phigs::hardcopy
