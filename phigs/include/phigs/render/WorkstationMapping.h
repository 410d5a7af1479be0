#pragma once

#include "phigs/traverse/DrawList.h"

#include <glm/mat4x4.hpp>

#include <cstdint>

namespace phigs::render {

/// A rectangle of framebuffer pixels (origin top left), as a Vulkan scissor wants it.
struct PixelRect {
    std::int32_t x = 0, y = 0;
    std::uint32_t width = 0, height = 0;
};

/// The workstation transformation for one framebuffer: NPC (the workstation window) to device
/// coordinates (the workstation viewport) to pixels. Device coordinates put the unit square on the
/// target's shorter side, origin bottom left; the window maps isotropically (PHIGS keeps the aspect
/// ratio, aligned at the lower left corner of the viewport).
struct WorkstationMapping {
    WorkstationMapping(const DrawList& list, std::uint32_t width, std::uint32_t height);

    glm::dmat4 npcToClip{1.0};  ///< NPC (x, y, z in [0,1], z = 1 front) to Vulkan clip space, depth = 1 - z
    double pixelsPerNpc = 1.0;
    glm::dvec3 windowMin{0.0}, windowMax{1.0};

    /// The pixels covered by an NPC box, clipped to the workstation window and the framebuffer.
    PixelRect scissor(glm::dvec2 npcMin, glm::dvec2 npcMax) const;
    /// Pixel position (x right, y down) of an NPC point.
    glm::dvec2 toPixels(glm::dvec3 npc) const;

private:
    std::uint32_t width_, height_;
};

}  // namespace phigs::render
