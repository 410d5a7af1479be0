#pragma once

#include "phigs/traverse/DrawList.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace phigs {

/// The workstation transformation of a draw list: the workstation window (NPC) onto the
/// viewport (device coordinates) with one scale for x and y, window corner on viewport corner,
/// as PHIGS maps it; z has its own scale.
struct WorkstationMapping {
    glm::dvec3 windowMin{0.0}, viewportMin{0.0};
    double scaleXY = 1.0, scaleZ = 1.0;

    explicit WorkstationMapping(const DrawList& list);
    glm::dvec3 toDevice(const glm::dvec3& npc) const;
    glm::dvec3 toNpc(const glm::dvec3& device) const;
    /// NPC distance covered by `pixels` device units.
    double npcLength(double pixels) const { return pixels / scaleXY; }
};

}  // namespace phigs
