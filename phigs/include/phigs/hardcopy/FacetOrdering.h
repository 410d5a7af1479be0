#pragma once

#include "phigs/hardcopy/ProjectedScene.h"

#include <cstddef>
#include <vector>

namespace phigs::hardcopy {

/// What orderBackToFront did.
struct FacetOrderStats {
    std::size_t input = 0, output = 0;
    std::size_t clusters = 0;  ///< groups no order of whole facets fits, ordered by a BSP tree
    std::size_t splits = 0;    ///< facets cut in two by another's plane in those groups
    bool fellBack = false;     ///< a group's split budget ran out: its rest was sorted by mean depth
};

/// Facets in an order that paints what lies behind first (hidden-surface removal by the painter's
/// algorithm). Only facets that overlap on the page (FacetOverlaps) constrain it: of each such
/// pair, the one behind where they overlap comes first, found by comparing planes in the page's
/// x and y with depth scaled by `pointsPerDepth`. Where no order of whole facets fits (facets
/// that pierce each other, or overlap in a cycle) the group is ordered by a BSP tree that splits
/// facets at each other's planes, capped at eight splits a facet (plus 10,000), past which the
/// rest is sorted by mean depth. Facets that overlap in more than 64 pairs a facet (plus 2^20) are
/// all ordered by one such tree. Among the facets free to come next, one with the last one's view
/// and colour at 8 bits a channel is taken first, so that runs of one colour can be painted as
/// one path.
std::vector<ProjectedFacet> orderBackToFront(std::vector<ProjectedFacet> facets, double pointsPerDepth,
                                             FacetOrderStats* stats = nullptr);

}  // namespace phigs::hardcopy
