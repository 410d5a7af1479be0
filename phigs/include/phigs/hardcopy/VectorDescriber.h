#pragma once

#include "phigs/hardcopy/FacetOrdering.h"
#include "phigs/hardcopy/PageSetup.h"
#include "phigs/hardcopy/VectorOptions.h"
#include "phigs/hardcopy/VectorPicture.h"
#include "phigs/traverse/DrawList.h"

namespace phigs::hardcopy {

/// What describing a picture found, for tests and the README's figures.
struct DescribeStats {
    FacetOrderStats facets;
    std::size_t occluders = 0;     ///< triangles lines were tested against
    std::size_t hiddenFacets = 0;  ///< facets hidden whole, left out before ordering
    bool hidden = false;           ///< hidden parts were removed
};

/// The describe step of the vector hardcopy: a draw list as paint operations on one page. Without
/// hidden-surface removal everything is painted in traversal order, as the raster path draws it;
/// with it (DrawList::hiddenSurfaceRemoval, or hidden-line surfaces) facets are painted back to
/// front (FacetOrdering) and then every line and marker with its hidden parts removed
/// (OcclusionIndex).
VectorPicture describePicture(const DrawList& list, const PageSetup& page, const VectorOptions& options = {},
                              DescribeStats* stats = nullptr);

}  // namespace phigs::hardcopy
