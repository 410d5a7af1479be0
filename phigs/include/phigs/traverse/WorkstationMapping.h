#pragma once

#include "phigs/traverse/DrawList.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>

namespace phigs {

/// A rectangle of surface pixels (origin top left), as a Vulkan scissor wants it.
struct PixelRect {
    std::int32_t x = 0, y = 0;
    std::uint32_t width = 0, height = 0;
};

/// The workstation transformation of a draw list shown on a surface of pixels, the one
/// convention the renderer and the input devices share. NPC (the workstation window) maps onto
/// the workstation viewport in device coordinates with one scale for x and y, window corner on
/// viewport corner (PHIGS keeps the aspect ratio); device coordinates (origin bottom left, y up)
/// put the display surface (`DrawList::displaySize`) on the pixels isotropically, lower-left
/// aligned; pixels count from the top left, y down, pixel (i, j) covering [i, i+1) x [j, j+1).
struct WorkstationMapping {
    /// On a surface whose pixels are the device coordinates (pixelsPerDevice = 1).
    explicit WorkstationMapping(const DrawList& list);
    WorkstationMapping(const DrawList& list, std::uint32_t width, std::uint32_t height);

    glm::dvec3 windowMin{0.0}, windowMax{1.0}, viewportMin{0.0};
    double scaleXY = 1.0, scaleZ = 1.0;  ///< device units per NPC unit
    double pixelsPerDevice = 1.0;
    double pixelsPerNpc = 1.0;
    std::uint32_t width = 1, height = 1;  ///< the surface in pixels
    glm::dmat4 npcToClip{1.0};            ///< NPC (z = 1 front) to Vulkan clip space, depth = 1 - z

    glm::dvec3 toDevice(const glm::dvec3& npc) const;
    glm::dvec3 toNpc(const glm::dvec3& device) const;
    /// Pixel position (x right, y down) of an NPC point.
    glm::dvec2 toPixels(const glm::dvec3& npc) const;
    /// The NPC point under a pixel position (x right, y down), with the given NPC z.
    glm::dvec3 pixelsToNpc(glm::dvec2 pixels, double npcZ) const;
    /// NPC distance covered by `pixels` pixels.
    double npcLength(double pixels) const { return pixels / pixelsPerNpc; }
    /// The pixels covered by an NPC box, clipped to the workstation window and the surface.
    PixelRect scissor(glm::dvec2 npcMin, glm::dvec2 npcMax) const;
};

}  // namespace phigs
