#pragma once

#include "acsynt/Component.h"

#include "geom/Curve.h"
#include "geom/curvemap/CurveMapper.h"

#include <cstddef>
#include <string>
#include <vector>

namespace acsynt {

/// How one part of a curve model came out of MAP CURVE.
enum class PartOutcome {
    Mapped,   ///< inside the surface
    Clipped,  ///< cut at the surface boundary or at the edge of the sheet facing the curve
    Lost      ///< nothing mapped (reason says why)
};

/// One part's line of the mapping report.
struct PartReport {
    std::string name;
    PartOutcome outcome = PartOutcome::Lost;
    std::size_t loops = 0, boundaryWalks = 0;
    std::string reason;  ///< why clipped or lost (empty when mapped)
};

/// MAP CURVE on one component: the mapper's result with every part accounted for.
struct ComponentMapping {
    geom::curvemap::MapResult result;
    std::vector<PartReport> parts;
};

/// Maps `curves` (named by `names`, one per curve) onto `component`. A part that the whole
/// surface cannot close (it hangs over a leading or trailing edge, over the root or over a fold
/// of a closed component, where the projection leaves the sheet at a silhouette) is mapped
/// again on the sheet facing the curve (geom::curvemap::facingDomain) and clipped at its edges
/// with boundary walks; a part that still maps nothing is reported Lost with the reason.
/// Throws geom::GeometryError as CurveMapper::map does, before any part is mapped.
ComponentMapping mapOnComponent(const Component& component, const std::vector<geom::Curve>& curves,
                                const std::vector<std::string>& names,
                                const geom::curvemap::Placement& placement,
                                const geom::curvemap::MapOptions& options);

/// "MAPPED", "CLIPPED" or "LOST".
const char* outcomeName(PartOutcome outcome);

/// The message line's account of parts not simply mapped: empty when every part mapped, else
/// e.g. ", CLIPPED: O_RING, SQUARE; LOST: SWOOSH (MISSES THE SURFACE)".
std::string partsNotice(const std::vector<PartReport>& parts);

}  // namespace acsynt
