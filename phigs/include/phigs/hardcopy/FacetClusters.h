#pragma once

#include "phigs/hardcopy/ProjectedScene.h"

#include <cstddef>
#include <vector>

namespace phigs::hardcopy {

/// Facets grouped so that no two groups overlap on the page (facets that only touch, as
/// neighbours in a mesh do, do not count): the painting order matters within a group only, so
/// each can be ordered on its own, and a facet alone needs no ordering at all. Overlap is tested
/// on each facet's convex hull (separating axes), candidates found on a grid of bounding boxes.
/// Indices into `facets`, each group in ascending order, groups by their first facet.
std::vector<std::vector<std::size_t>> overlapClusters(const std::vector<ProjectedFacet>& facets);

}  // namespace phigs::hardcopy
