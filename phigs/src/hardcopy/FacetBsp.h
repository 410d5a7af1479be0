#pragma once

// Private to phigs_hardcopy: the last resort of facet ordering.

#include "phigs/hardcopy/FacetOrdering.h"

#include <vector>

namespace phigs::hardcopy {

/// Facets far to near by a BSP tree of their planes in depth-scaled page space: a facet that
/// straddles the plane of another is split there. For facets whose order no comparison of whole
/// facets settles (they pierce each other, or overlap in a cycle). Splits are capped at eight
/// times the facets' count (plus 10,000); the rest is then sorted by mean depth, which `stats`
/// reports.
std::vector<ProjectedFacet> bspBackToFront(std::vector<ProjectedFacet> facets, double pointsPerDepth,
                                           FacetOrderStats& stats);

}  // namespace phigs::hardcopy
