#pragma once

#include "phigs/store/StructureStore.h"
#include "phigs/traverse/NameSetFilter.h"

#include <glm/vec3.hpp>

#include <vector>

namespace phigs {

/// What INCREMENTAL SPATIAL SEARCH (3) looks for and where.
struct SpatialSearchQuery {
    glm::dvec3 point{0.0};   ///< search reference point, world coordinates
    double distance = 0.0;   ///< search distance; <= 0: the locus must contain the point
    StructurePath start;     ///< root first; the last element number may be 0 (before the first)
    int ceiling = 1;         ///< 1-based index into `start`: the structure whose end stops the search
    bool modelClip = false;  ///< the model clipping volume cuts the loci first
    std::vector<NameSetFilter> normal;    ///< every one must accept the name set
    std::vector<NameSetFilter> inverted;  ///< every one must reject it
};

/// INCREMENTAL SPATIAL SEARCH 3 (ISO 9592-1, 4.4.6): a conceptual traversal of the network below
/// start[0] with the PHIGS description table's initial traversal state (identity transforms,
/// empty name set, model clipping off). The setup goes up to and including the element the
/// start path names (a structure it executes is traversed there, not searched); the search goes
/// on from the next element and ends after the last element of the structure at the ceiling's
/// level. The first output primitive whose locus (see LocusDistance.h) lies within `distance` of
/// `point` and whose name set passes the filters is found: its path from the root, else an empty
/// path. Errors: 203 the start path is not in the CSS (each level but the last must name an
/// EXECUTE STRUCTURE of the next level's structure), 204 the ceiling outside 1..start.size().
StructurePath incrementalSpatialSearch(const StructureStore& store, const SpatialSearchQuery& query,
                                       const char* function);

}  // namespace phigs
