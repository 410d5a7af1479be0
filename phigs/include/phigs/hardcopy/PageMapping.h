#pragma once

#include "phigs/hardcopy/PageSetup.h"
#include "phigs/traverse/DrawList.h"
#include "phigs/traverse/WorkstationMapping.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace phigs::hardcopy {

/// An axis-aligned rectangle on the page (points, y down).
struct PageRect {
    glm::dvec2 min{0.0}, max{0.0};
    bool empty() const { return !(max.x > min.x && max.y > min.y); }
};

/// The workstation transformation of a draw list on a page: NPC to device coordinates by
/// WorkstationMapping's rule, then the display surface fitted into the page (isotropic, centred
/// in the margins), page y down as cairo wants it.
struct PageMapping {
    PageMapping(const DrawList& list, const PageSetup& page);

    WorkstationMapping workstation;
    glm::dvec2 pageSize{0.0};
    PageRect display;  ///< the display surface on the page
    double pointsPerDevice = 1.0;
    double pointsPerNpc = 1.0;
    double nominalPixel = 1.0;  ///< points per raster pixel (PageSetup::nominalPixel)
    glm::dmat4 npcToPage{1.0};  ///< NPC (x, y, z) to page (x, y) keeping z; affine

    /// The page point (x, y) of an NPC point, with its NPC z kept as the third coordinate.
    glm::dvec3 toPage(const glm::dvec3& npc) const;
    /// What a view shows on the page: its x/y clip limits (when it clips) within the
    /// workstation window and the display surface.
    PageRect clipRect(const DrawView& view) const;
};

}  // namespace phigs::hardcopy
