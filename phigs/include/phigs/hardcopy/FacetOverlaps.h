#pragma once

#include "phigs/hardcopy/ProjectedScene.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <utility>
#include <vector>

namespace phigs::hardcopy {

/// The pairs of facets that overlap on the page, which alone constrain the painting order: facets
/// that only touch, as neighbours in a mesh do, do not count. Overlap is tested on each facet's
/// convex hull (separating axes), candidates found on a grid of bounding boxes.
struct FacetOverlaps {
    /// Each facet's convex hull on the page, counter-clockwise (fewer than 3 points: no area).
    std::vector<std::vector<glm::dvec2>> hulls;
    /// Indices into the facets, the smaller first, each pair once.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    bool complete = true;  ///< false: more than `maxPairs` pairs, and the search stopped there
};

/// The facets' hulls and overlapping pairs; the search stops past `maxPairs` pairs (bounded room
/// where facets overlap by the hundred).
FacetOverlaps facetOverlaps(const std::vector<ProjectedFacet>& facets, std::size_t maxPairs);

/// The part of the page two convex counter-clockwise polygons share (empty when they only touch).
std::vector<glm::dvec2> convexIntersection(const std::vector<glm::dvec2>& a,
                                           const std::vector<glm::dvec2>& b);

}  // namespace phigs::hardcopy
