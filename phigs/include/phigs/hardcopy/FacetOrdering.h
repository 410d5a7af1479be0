#pragma once

#include "phigs/hardcopy/ProjectedScene.h"

#include <cstddef>
#include <vector>

namespace phigs::hardcopy {

/// What orderBackToFront did.
struct FacetOrderStats {
    std::size_t input = 0, output = 0;
    std::size_t clusters = 0;  ///< groups of mutually overlapping facets ordered by a BSP tree
    std::size_t splits = 0;    ///< facets cut in two by another's plane
    bool fellBack = false;     ///< the split budget ran out: the rest was sorted by mean depth
};

/// Facets in an order that paints what lies behind first (hidden-surface removal by the painter's
/// algorithm): facets that overlap on the page (FacetClusters) are ordered by a BSP tree of their
/// planes, the page's x and y with depth scaled by `pointsPerDepth`; a facet straddling the plane
/// of another is split there, so facets that overlap in depth come out right. Splits are capped
/// at eight times a cluster's size (plus 10,000); beyond that the rest of the cluster is sorted
/// by mean depth, which stats report. Facets that overlap no other come first, by view and by
/// colour at 8 bits per channel, so that runs of one colour can be painted as one path.
std::vector<ProjectedFacet> orderBackToFront(std::vector<ProjectedFacet> facets, double pointsPerDepth,
                                             FacetOrderStats* stats = nullptr);

}  // namespace phigs::hardcopy
